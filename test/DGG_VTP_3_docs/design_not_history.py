#!/usr/bin/python3
"""The user manual and the public headers say what the package does and why, not its history.

CGAL's manuals say what, how, why, with examples; the measurements live in
benchmark/DGG_VTP_3/README.md and the changes in CHANGELOG.md. This test fails on, in the manual
(doc/DGG_VTP_3/*.txt, the concept pages) and in the comments of the public headers
(include/CGAL/DGG_VTP_3.h, include/CGAL/DGG_VTP_3/*.h, not internal/):
- history: issue numbers, commits, dates, "found by the fuzzer", "(fixed)", "now" (as in "is
  solved now"), "used to";
- timings and speed-ups: a number of seconds or milliseconds (but for the progress callback's
  period, an interface promise), "N times faster/slower";
- repository paths: a file of the repository named by its folder (benchmark/, python/, test/,
  scripts/, cli/, loader/, examples/, doc/, internal/), README.md, CHANGELOG.md (the manual's
  examples are named by \\cgalExample, which is not a path of the repository).
A section titled "Implementation History" may say what changed, in at most 12 lines: history
words are allowed there (not timings or paths).

usage: design_not_history.py REPOSITORY_ROOT
"""
import re
import sys
from pathlib import Path

from failures import report

HISTORY = [r"\bissues?\s*#?\d+", r"\bcommit\s+[0-9a-f]{7,}", r"\b20\d\d-\d\d-\d\d\b", r"found by the fuzzer",
           r"\bthe fuzzer found\b", r"\(fixed\)", r"\bwas fixed\b", r"\bnow\b", r"\bused to\b"]
TIMINGS = [r"(?<![\w.])\d+(\.\d+)?(\s?-\s?\d+(\.\d+)?)?\s?(s|ms|seconds|milliseconds|minutes|hours)\b(?<!every 0\.1 s)",
           r"\d+(\.\d+)?(\s?-\s?\d+(\.\d+)?)? times (faster|slower)"]
PATHS = [r"(?<![\w{/])(benchmark|python|tests?|scripts|cli|loader|examples|doc|internal)/[\w./-]+",
         r"\bREADME\.md\b", r"\bCHANGELOG\.md\b"]
ALLOWED_TIMINGS = [r"every 0\.1 s", r"at most every 0\.1\s*s"]  # the callback's period: an interface promise


def comments(source):
    """(line number, text) of the comments of a C++ file"""
    out, in_block = [], False
    for number, line in enumerate(source.split("\n"), 1):
        text = ""
        if in_block:
            end = line.find("*/")
            text, in_block = (line, True) if end < 0 else (line[:end], False)
        else:
            slash, block = line.find("//"), line.find("/*")
            if slash >= 0 and (block < 0 or slash < block):
                text = line[slash + 2:]
            elif block >= 0:
                end = line.find("*/", block + 2)
                text, in_block = (line[block + 2:], True) if end < 0 else (line[block + 2:end], False)
        if text.strip():
            out.append((number, text))
    return out


def check(where, lines, failures, history_allowed=lambda n: False):
    for number, text in lines:
        if re.search(r"Copyright|SPDX|\$URL|\$Id|Author\(s\)", text):
            continue
        cleaned = text
        for allowed in ALLOWED_TIMINGS:
            cleaned = re.sub(allowed, "", cleaned)
        kinds = [("history", HISTORY)] if not history_allowed(number) else []
        kinds += [("a timing", TIMINGS), ("a repository path", PATHS)]
        for kind, patterns in kinds:
            for pattern in patterns:
                m = re.search(pattern, cleaned, re.I if kind == "history" else 0)
                if m:
                    failures.append(f"{where}:{number}: {kind} ({m.group(0)!r}): {text.strip()[:140]}")


def main():
    root = Path(sys.argv[1] if len(sys.argv) > 1 else Path(__file__).resolve().parents[2])
    failures = []
    manual_files = sorted((root / "doc" / "DGG_VTP_3").glob("*.txt")) + \
        sorted((root / "doc" / "DGG_VTP_3" / "Concepts").glob("*.h"))
    for manual in manual_files:
        text = manual.read_text().split("\n")
        history = [k + 1 for k, line in enumerate(text) if re.match(r"\\section\s+\S+\s+Implementation History", line)]
        section_end = {}
        for start in history:
            end = next((k + 1 for k in range(start, len(text)) if re.match(r"\\(section|subsection)\b", text[k])),
                       len(text))
            if end - start > 12:
                failures.append(f"{manual.relative_to(root)}:{start}: the Implementation History section has "
                                f"{end - start} lines: at most 12")
            section_end[start] = end
        in_history = lambda n: any(s <= n < e for s, e in section_end.items())
        check(manual.relative_to(root), list(enumerate(text, 1)), failures, in_history)
    headers = [root / "include" / "CGAL" / "DGG_VTP_3.h"] + sorted((root / "include" / "CGAL" / "DGG_VTP_3").glob("*.h"))
    for header in headers:
        check(header.relative_to(root), comments(header.read_text()), failures)
    print(f"{len(manual_files)} manual files, {len(headers)} public headers")
    return report(failures)


if __name__ == "__main__":
    sys.exit(main())
