#!/usr/bin/python3
"""The demo installs what the demo needs, and no more (README.md, "Two commands").

scripts/demo.sh installs the Debian packages of `scripts/install_dependencies.sh --cli`, configures
the project as it is written there and builds dggvtp. This test checks that list against what that
build reads, on this machine (a Debian one, with the packages installed):

1. the demo's configuration succeeds and gives the target dggvtp where nothing outside the list
   is found: the project configured as demo.sh does, in a temporary folder, with the optional
   packages that the rest of the test command installs made absent (MPI, Python and pybind11,
   Boost.Test);
2. every file that build reads comes from the list, the packages they depend on, or those of
   priority "required" that every Debian system has: the headers the compiler read for dggvtp
   (the object's dependency file), the libraries it is linked with, the compiler, make and cmake,
   and the CMake package files that configuration used;
3. every package of the list is needed: it owns one of those files, or it is a metapackage (g++,
   libboost-dev) one of whose dependencies is needed.

usage: demo_dependencies.py SOURCE_DIR DGGVTP_OBJECT_DEPFILE DGGVTP_LINK_TXT
Exit 0 when all three hold, 1 otherwise (77: not a Debian system, or a package of the list is
not installed: nothing to compare with).
"""
import glob
import os
import re
import shlex
import subprocess
import sys
import tempfile
from pathlib import Path

# what the rest of the test command installs and the demo must do without (CMake's name of each)
ABSENT = {"MPI": "libopenmpi-dev", "Python3": "python3-dev", "pybind11": "pybind11-dev",
          "boost_unit_test_framework": "libboost-test-dev"}

# the tools of CTest's dashboards (include(CTest) finds them if they are there, and needs none)
CTEST_TOOLS = r"^(GIT|GITCOMMAND|MEMORYCHECK_|COVERAGE_|CVSCOMMAND|SVNCOMMAND|HGCOMMAND|P4COMMAND|BZRCOMMAND|DART|CTEST_)"


def dpkg_packages():
    """{name: (depends groups, provides, priority)} of the installed packages"""
    out = subprocess.run(["dpkg-query", "-W", "-f",
                          "${Package}\t${Status}\t${Priority}\t${Depends}\t${Pre-Depends}\t${Provides}\n"],
                         capture_output=True, text=True, check=True).stdout
    packages = {}
    for line in out.splitlines():
        name, status, priority, depends, pre, provides = (line.split("\t") + [""] * 6)[:6]
        if not status.endswith(" installed"):
            continue
        groups = [[re.sub(r"[ (].*|:.*", "", a.strip()) for a in g.split("|")]
                  for g in ", ".join(x for x in (depends, pre) if x).split(",") if g.strip()]
        packages[name] = (groups, [re.sub(r"[ (].*", "", p.strip()) for p in provides.split(",") if p.strip()],
                          priority)
    return packages


def closure(roots, packages):
    """the roots and every installed package they depend on (any installed alternative, virtual
    packages through what provides them), and the packages of priority required"""
    providers = {}
    for name, (_, provides, _) in packages.items():
        providers.setdefault(name, []).append(name)
        for p in provides:
            providers.setdefault(p, []).append(name)
    seen = set()
    todo = list(roots) + [n for n, (_, _, priority) in packages.items() if priority == "required"]
    while todo:
        name = todo.pop()
        if name in seen or name not in packages:
            continue
        seen.add(name)
        for group in packages[name][0]:
            for alternative in group:
                todo.extend(providers.get(alternative, []))
    return seen


def files_of(package):
    """the files of an installed package, as real paths"""
    out = set()
    for listing in glob.glob(f"/var/lib/dpkg/info/{package}.list") + glob.glob(f"/var/lib/dpkg/info/{package}:*.list"):
        for line in Path(listing).read_text().splitlines():
            if line and os.path.isfile(line):
                out.add(os.path.realpath(line))
    return out


def owner(path):
    """the package dpkg says owns `path` (tried as given and under /lib for merged /usr), or '?'"""
    for candidate in {path, re.sub(r"^/usr/lib/", "/lib/", path), re.sub(r"^/usr/bin/", "/bin/", path)}:
        r = subprocess.run(["dpkg", "-S", candidate], capture_output=True, text=True)
        if r.returncode == 0:
            return r.stdout.split(":")[0]
    return "?"


def demo_lines(source):
    """the install command's options and the configure command of scripts/demo.sh"""
    demo = (source / "scripts" / "demo.sh").read_text()
    install = re.search(r"^bash scripts/install_dependencies\.sh(.*)$", demo, re.M)
    configure = re.search(r"^(cmake -S \. -B build\b.*?)(\s*>\s*/dev/null)?$", demo, re.M)
    build = re.search(r"^cmake --build build .*--target dggvtp\b", demo, re.M)
    if not (install and configure and build):
        sys.exit("FAIL: scripts/demo.sh no longer installs, configures and builds dggvtp as this test reads it")
    return install.group(1).split(), shlex.split(configure.group(1))


def configured_files(source, configure):
    """configures the project as the demo does, the optional packages absent: the files of the
    CMake cache it leaves (FILEPATH entries, and the package files of the *_DIR entries)"""
    with tempfile.TemporaryDirectory(prefix="demo_configure_") as build:
        command = [configure[0], "-S", str(source), "-B", build] + [
            a for a in configure[1:] if a not in ("-S", "-B", ".", "build")]
        command += [f"-DCMAKE_DISABLE_FIND_PACKAGE_{p}=ON" for p in ABSENT] + ["-DPython3_EXECUTABLE=/nonexistent/python3"]
        r = subprocess.run(command, capture_output=True, text=True)
        if r.returncode != 0 or "CMake Error" in r.stderr:
            print(f"FAIL: the demo's configuration without {', '.join(sorted(ABSENT.values()))} fails:\n{r.stderr[-3000:]}")
            return None
        targets = subprocess.run(["cmake", "--build", build, "--target", "help"], capture_output=True, text=True).stdout
        if not re.search(r"^\.\.\. dggvtp$", targets, re.M):
            print("FAIL: the demo's configuration has no target dggvtp")
            return None
        files = set()
        for line in (Path(build) / "CMakeCache.txt").read_text().splitlines():
            m = re.match(r"^([A-Za-z0-9_]+):(FILEPATH|PATH)=(/.+)$", line)
            if not m:
                continue
            name, kind, value = m.groups()
            if re.match(CTEST_TOOLS, name):  # include(CTest) looks for them, and does without
                continue
            if kind == "FILEPATH" and os.path.isfile(value):
                files.add(os.path.realpath(value))
            elif name.endswith("_DIR") and os.path.isdir(value):
                files.update(os.path.realpath(f) for f in glob.glob(os.path.join(value, "*onfig.cmake")))
        return files


def main():
    source, depfile, link = Path(sys.argv[1]).resolve(), Path(sys.argv[2]), Path(sys.argv[3])
    if not Path("/var/lib/dpkg/status").exists():
        print("SKIPPED: not a Debian system (no dpkg)")
        return 77
    options, configure = demo_lines(source)
    if "--cli" not in options:
        print(f"FAIL: scripts/demo.sh installs with {options or 'no option'}, not --cli: the whole test command's list")
        return 1
    listed = subprocess.run(["bash", str(source / "scripts" / "install_dependencies.sh"), *options, "--list"],
                            capture_output=True, text=True, check=True).stdout.split()
    packages = dpkg_packages()
    missing = [p for p in listed if p not in packages]
    if missing:
        print(f"SKIPPED: not installed here: {' '.join(missing)}")
        return 77
    print(f"the demo installs: {' '.join(listed)}")
    failures = []

    used = configured_files(source, configure)
    if used is None:
        return 1
    # the headers of dggvtp's compilation, the libraries it links, the tools
    headers = re.split(r"(?<!\\)\s+", depfile.read_text().replace("\\\n", " "))
    used |= {os.path.realpath(h) for h in headers if h.startswith("/") and os.path.isfile(h)}
    used |= {os.path.realpath(t) for t in shlex.split(link.read_text())
             if t.startswith("/") and re.search(r"\.(so[.0-9]*|a)$", t) and os.path.isfile(t)}
    cache = {}
    for name in ("CMAKE_CXX_COMPILER", "CMAKE_MAKE_PROGRAM", "CMAKE_COMMAND"):
        found = re.search(rf"^{name}:[A-Z]+=(.+)$", (depfile.parents[3] / "CMakeCache.txt").read_text(), re.M)
        if found and os.path.isfile(found.group(1)):
            cache[name] = os.path.realpath(found.group(1))
    used |= set(cache.values())
    inside = (str(source) + os.sep, str(depfile.parents[3]) + os.sep)
    used = {f for f in used if not f.startswith(inside)}
    print(f"files the build of dggvtp reads outside the repository: {len(used)}")

    # 2. each of them from the list's closure
    allowed = closure(listed, packages)
    owned = set()
    for p in allowed:
        owned |= files_of(p)
    strays = sorted(f for f in used if f not in owned)
    by_owner = {}
    for f in strays:
        by_owner.setdefault(owner(f), []).append(f)
    for package, files in sorted(by_owner.items()):
        failures.append(f"{len(files)} files of {package}, which the demo does not install: {files[:3]}")

    # 3. each listed package needed
    def needed(package, depth=0):
        mine = {f for f in files_of(package) if not f.startswith("/usr/share/doc/")}
        if mine & used:
            return True
        if mine or depth > 2:  # a package with files of its own that the build does not read
            return False
        return any(needed(a, depth + 1) for group in packages[package][0] for a in group if a in packages)
    for p in listed:
        if not needed(p):
            failures.append(f"{p} is installed by the demo, but building dggvtp reads none of its files")

    for f in failures:
        print("FAIL: " + f)
    if not failures:
        print(f"ok: the {len(used)} files come from the {len(listed)} packages of the list (and what they depend "
              f"on), and each package of the list is read")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
