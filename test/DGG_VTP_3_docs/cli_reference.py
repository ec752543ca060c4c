#!/usr/bin/python3
"""The programs' reference (doc/cli.md) and their --help list the same options.

doc/cli.md has a section per program, a level-2 heading naming it (`dggvtp`, `dggvtp-batch`); in
it, each option is documented by a bullet that starts with its spellings in backquotes
("- `--source N`, `--source-point X Y Z`: ..."), and the synopsis (a text block) names them too.
The options of `PROGRAM --help` are its lines that start with two spaces and a long option. The
test fails, naming them, where an option is in one and not in the other: documented or in the
synopsis but unknown to --help, or listed by --help and not documented.

usage: cli_reference.py doc/cli.md DGGVTP DGGVTP_BATCH
"""
import re
import subprocess
import sys
from pathlib import Path

from failures import report

OPTION = r"--[a-z][a-z0-9-]*"


def help_options(program):
    text = subprocess.run([program, "--help"], capture_output=True, text=True, check=True).stdout
    return {m.group(1) for m in re.finditer(rf"^  ({OPTION})", text, re.M)}


def sections(markdown):
    """{program: its section's text}, by the level-2 headings that name a program"""
    found, current = {}, None
    for line in markdown.split("\n"):
        heading = re.match(r"^## .*?`(dggvtp(?:-batch)?)`", line)
        if heading:
            current = heading.group(1)
            found[current] = []
        elif line.startswith("## "):
            current = None
        elif current:
            found[current].append(line)
    return {k: "\n".join(v) for k, v in found.items()}


def documented(section):
    """the options of the section's bullets (their leading backquoted spellings) and of its
    synopsis (its text blocks)"""
    bullets = set()
    for line in section.split("\n"):
        lead = re.match(r"^- ((?:`[^`]+`(?:, | or | and |/)?)+)", line)
        if lead:
            for span in re.findall(r"`([^`]+)`", lead.group(1)):
                m = re.match(rf"^({OPTION})", span)
                if m:
                    bullets.add(m.group(1))
    synopsis = set()
    for block in re.findall(r"```text\n(.*?)```", section, re.S):
        synopsis |= set(re.findall(rf"(?<![\w-]){OPTION}", block))
    return bullets, synopsis


def main():
    reference = Path(sys.argv[1])
    programs = {"dggvtp": sys.argv[2], "dggvtp-batch": sys.argv[3]}
    parts = sections(reference.read_text())
    failures = []
    for name, program in programs.items():
        if name not in parts:
            failures.append(f"{reference} has no section (## ... `{name}`) for {name}")
            continue
        listed = help_options(program)
        bullets, synopsis = documented(parts[name])
        for option in sorted(listed - bullets):
            failures.append(f"{name} --help lists {option}, which {reference.name} does not document (a bullet "
                            f"starting with `{option} ...`)")
        for option in sorted(bullets - listed):
            failures.append(f"{reference.name} documents {option} for {name}, which {name} --help does not list")
        for option in sorted(synopsis - listed):
            failures.append(f"{reference.name}'s synopsis of {name} has {option}, which {name} --help does not list")
        print(f"{name}: {len(listed)} options in --help, {len(bullets)} documented, {len(synopsis)} in the synopsis")
    return report(failures)


if __name__ == "__main__":
    sys.exit(main())
