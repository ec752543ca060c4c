"""What the documentation's tests share: their report."""


def report(failures):
    """prints each failure on a line of its own, FAIL first; the exit status: 1 if any, else 0"""
    for f in failures:
        print("FAIL " + f)
    return 1 if failures else 0
