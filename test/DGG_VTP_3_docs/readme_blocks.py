#!/usr/bin/python3
"""Every code block of a Markdown file (README.md, doc/cli.md, doc/python.md), exercised: the front
door and the references it sends readers to cannot rot.

Extracts the fenced blocks of the file, prints their count by language, then
- python: runs the blocks in order, in one namespace (a later block may use an earlier one's names),
  with PYTHONPATH=$DGGVTP_PYTHONPATH (e.g. build/python), in a temporary directory where data/ is
  $DGGVTP_DATA/.. (data/meshes of the repository) and matplotlib draws off screen;
- sh/bash: runs each command line (continuations joined) with bash in the same directory, the
  programs found in $DGGVTP_BIN (e.g. build/bin, also linked as build/bin there); the lines in
  SKIP_COMMANDS are not run, and each is printed with its reason;
- cpp: each block must be a whole program: g++ -std=gnu++17 -fsyntax-only -I include (and CGAL's,
  Boost's and Eigen's system include directories);
- text, console, cmake and blocks without a language are not programs to run here: counted, not
  run (SKIP_LANGUAGES).
Exit 0 when every block that is run passes, 1 otherwise. Without DGGVTP_PYTHONPATH, the Python
blocks are skipped (said so); without DGGVTP_BIN, the sh blocks are.

usage: DGGVTP_PYTHONPATH=build/python DGGVTP_BIN=build/bin DGGVTP_DATA=data/meshes \\
       /usr/bin/python3 test/DGG_VTP_3_docs/readme_blocks.py [FILE.md, README.md by default]
"""
import collections
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

# command lines of sh blocks that are not run, each with its reason
SKIP_COMMANDS = {
    "/usr/bin/python3 -m venv --system-site-packages venv": "the install; run as written by the CTest python_pip_install",
    "venv/bin/pip install --no-build-isolation .": "the install; run as written by the CTest python_pip_install",
    "venv/bin/pip install --no-build-isolation ./python": "the install; run as written by the CTest python_pip_install",
    "cmake -S . -B build -DCMAKE_BUILD_TYPE=Release && cmake --build build -j2 --target dggvtp":
        "builds the program (minutes); the test runs the one already built in $DGGVTP_BIN",
}
SKIP_LANGUAGES = {
    "": "no language: commands that install Debian packages or build (the two commands of README.md; CI runs them)",
    "text": "a usage synopsis, not a command",
    "console": "a terminal session on a cluster, not a command to run here",
    "cmake": "a fragment of a CMakeLists.txt (the CTests DGG_VTP_3.cmake_package_* build a consumer)",
}


def blocks(text):
    """(line, language, body) of each fenced block"""
    out, lines, k = [], text.split("\n"), 0
    while k < len(lines):
        m = re.match(r"^```(\S*)\s*$", lines[k])
        if m:
            end = lines.index("```", k + 1)
            out.append((k + 1, m.group(1), "\n".join(lines[k + 1:end])))
            k = end
        k += 1
    return out


def commands(body):
    joined = re.sub(r"\\\n\s*", " ", body)
    lines = (re.sub(r"\s+#.*$", "", c).strip() for c in joined.split("\n"))  # comments off
    return [c for c in lines if c and not c.startswith("#")]


def main():
    readme = Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "README.md"
    name = readme.resolve().relative_to(ROOT).as_posix() if readme.resolve().is_relative_to(ROOT) else readme.name
    found = blocks(readme.read_text())
    counts = collections.Counter(lang or "(none)" for _, lang, _ in found)
    print(f"{readme}: {len(found)} fenced blocks: " + ", ".join(f"{n} {l}" for l, n in sorted(counts.items())))
    pythonpath = os.environ.get("DGGVTP_PYTHONPATH")
    bindir = os.environ.get("DGGVTP_BIN")
    data = Path(os.environ.get("DGGVTP_DATA", ROOT / "data" / "meshes")).resolve()
    failures, ran = [], collections.Counter()
    with tempfile.TemporaryDirectory(prefix="readme_blocks_") as tmp:
        tmp = Path(tmp)
        (tmp / "data").mkdir()
        (tmp / "data" / "meshes").symlink_to(data)
        env = dict(os.environ, MPLBACKEND="Agg")
        if bindir:
            (tmp / "build").mkdir()
            (tmp / "build" / "bin").symlink_to(Path(bindir).resolve())
            env["PATH"] = str(Path(bindir).resolve()) + os.pathsep + env["PATH"]
        python_program = []
        for line, lang, body in found:
            where = f"{name}:{line} ({lang or 'no language'})"
            if lang in SKIP_LANGUAGES:
                print(f"skip {where}: {SKIP_LANGUAGES[lang]}")
            elif lang in ("sh", "bash"):
                for c in commands(body):
                    if c in SKIP_COMMANDS:
                        print(f"skip {where}: {c!r}: {SKIP_COMMANDS[c]}")
                    elif not bindir:
                        print(f"skip {where}: {c!r}: DGGVTP_BIN not set")
                    else:
                        r = subprocess.run(["bash", "-e", "-c", c], cwd=tmp, env=env, capture_output=True, text=True)
                        ran["sh"] += 1
                        if r.returncode:
                            failures.append(f"{where}: {c!r} exit {r.returncode}: {r.stderr.strip()[-800:]}")
            elif lang == "python":
                # each block runs after the earlier ones, as a reader's session would
                python_program.append(f"# {where}\n{body}\nprint('ok: {where}', flush=True)\n")
                if not pythonpath:
                    print(f"skip {where}: DGGVTP_PYTHONPATH not set")
            elif lang == "cpp":
                source = tmp / f"block_{line}.cpp"
                source.write_text(body + "\n")
                r = subprocess.run(["g++", "-std=gnu++17", "-fsyntax-only", "-I", str(ROOT / "include"),
                                    "-I", "/usr/include/eigen3", str(source)], capture_output=True, text=True)
                ran["cpp"] += 1
                if r.returncode:
                    failures.append(f"{where}: not a whole program:\n{r.stderr.strip()[-2000:]}")
                else:
                    print(f"ok: {where} compiles")
            else:
                failures.append(f"{where}: a language this test does not know: say how to check it")
        if pythonpath and python_program:
            env["PYTHONPATH"] = str(Path(pythonpath).resolve())
            r = subprocess.run([sys.executable, "-W", "error::DeprecationWarning", "-c", "\n".join(python_program)],
                               cwd=tmp, env=env, capture_output=True, text=True)
            print(r.stdout, end="")
            ran["python"] += len(python_program)
            if r.returncode:
                failures.append(f"python blocks: exit {r.returncode}:\n{r.stderr.strip()[-2000:]}")
    print("run: " + ", ".join(f"{n} {l}" for l, n in sorted(ran.items())))
    for f in failures:
        print("FAIL " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
