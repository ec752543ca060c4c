#!/usr/bin/python3
"""Every named parameter of the package is documented, where a reader looks for it.

Each CGAL_DGG_VTP_3_NAMED_PARAMETER(name) of include/CGAL/DGG_VTP_3/parameters.h must
- have a comment of its own (/// lines right above it), which the reference shows for the function
  that makes it, and
- be described in a \\cgalParamNBegin{...name} entry of a public header's reference, with its
  description, type and default, on the function or constructor that takes it.

usage: named_parameters.py REPOSITORY_ROOT
"""
import re
import sys
from pathlib import Path

from failures import report


def main():
    root = Path(sys.argv[1] if len(sys.argv) > 1 else Path(__file__).resolve().parents[2])
    include = root / "include" / "CGAL" / "DGG_VTP_3"
    lines = (include / "parameters.h").read_text().split("\n")
    public = "\n".join(p.read_text() for p in sorted(include.glob("*.h")))
    failures, names = [], []
    for k, line in enumerate(lines):
        m = re.match(r"^CGAL_DGG_VTP_3_NAMED_PARAMETER\((\w+)\)", line)
        if not m:
            continue
        name = m.group(1)
        names.append(name)
        if k == 0 or not lines[k - 1].lstrip().startswith("///"):
            failures.append(f"parameters.h:{k + 1}: {name} has no /// comment of its own")
        if not re.search(r"\\cgalParamNBegin\{(DGG_VTP_3::parameters::)?" + name + r"\}", public):
            failures.append(f"{name}: no \\cgalParamNBegin{{DGG_VTP_3::parameters::{name}}} in a public header")
    print(f"{len(names)} named parameters: {' '.join(names)}")
    if not names:
        failures.append("no CGAL_DGG_VTP_3_NAMED_PARAMETER found in parameters.h")
    return report(failures)


if __name__ == "__main__":
    sys.exit(main())
