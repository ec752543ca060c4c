"""threads= on a mesh with copies, as a repaired scan has them: lion_head with 1,500 fins glued on
its edges (test/DGG_VTP_3_cli/glue_fins.py), whose ends the solver splits into copies that land in
other patches of faces than the vertices they copy. One propagation on 2 and 4 threads, repeated,
gives the bits of one thread; so do two Python threads querying one solver at once. The build of
scripts/run_thread_sanitizer.sh runs this file under ThreadSanitizer, with fewer runs
(DGG_VTP_3_TEST_RUNS)."""
import os
import sys
import threading
import warnings

import numpy as np
import pytest

import dggvtp
from conftest import CLI_DATA, mesh, same_bits

sys.path.insert(0, str(CLI_DATA.parent))
from glue_fins import glue_fins, read_ply  # noqa: E402

RUNS = int(os.environ.get("DGG_VTP_3_TEST_RUNS", "10"))


@pytest.fixture(scope="module")
def finned():
    V, F = glue_fins(*read_ply(mesh("lion_head.ply")), 1500)
    with pytest.warns(RuntimeWarning, match=r"split \d+ non-manifold vertices"):
        return dggvtp.GeodesicSolver(V, F)


@pytest.mark.parametrize("epsilon", [0.0, 1e-3, 1e-1])
def test_threads_give_the_bits_of_one_thread(finned, epsilon):
    one = finned.distances(1234, epsilon=epsilon)
    targets = [17, 5000, 9000]
    one_targets = finned.target_distances(1234, targets, epsilon=epsilon)
    for threads in (2, 4):
        for run in range(RUNS):
            assert same_bits(finned.distances(1234, epsilon=epsilon, threads=threads), one), (threads, run)
        assert same_bits(finned.target_distances(1234, targets, epsilon=epsilon, threads=threads), one_targets), threads


def test_python_threads_share_a_solver(finned):
    sources = [3, 2000, 4000, 6000, 8000, 9800]
    expected = [finned.distances(s, epsilon=1e-3) for s in sources]
    wrong, errors, done = [], [], []

    def work(k):
        # an exception here would only reach threading.excepthook (a pytest warning, the test
        # passing): it is kept and raised by the test, and each worker says it finished
        try:
            for run in range(max(1, RUNS // 5)):
                for i in range(len(sources)):
                    j = (i + k) % len(sources)
                    if not same_bits(finned.distances(sources[j], epsilon=1e-3, threads=2), expected[j]):
                        wrong.append((k, run, j))
            done.append(k)
        except BaseException as error:  # noqa: B036 (raised again on the test's thread)
            errors.append((k, error))

    threads = [threading.Thread(target=work, args=(k,)) for k in range(3)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    if errors:
        k, error = errors[0]
        raise AssertionError(f"Python thread {k} raised ({len(errors)} of 3 did): {error!r}") from error
    assert sorted(done) == [0, 1, 2], done
    assert wrong == []
