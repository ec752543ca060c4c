#!/usr/bin/python3
"""Every relative link of the repository's Markdown files resolves, anchors included.

For each Markdown file of the repository (the files git tracks, or, outside a git checkout, every
*.md file but those of build folders and virtual environments), each inline link or image
[text](target) and each reference definition [name]: target whose target is not a URL (http:,
https:, mailto:) must name a file or folder that exists, relative to the Markdown file; an anchor
(#...) must be a heading of the target Markdown file, as GitHub makes it (lower case, punctuation
but - and _ dropped, spaces to -, -1, -2 ... for repeats), or an explicit <a name=...>/id=... there.
Links inside code (fenced blocks, `inline code`) are not links.

usage: markdown_links.py REPOSITORY_ROOT
"""
import os
import re
import subprocess
import sys
from pathlib import Path

from failures import report

SKIPPED_FOLDERS = re.compile(r"(^|/)(build[^/]*|venv|\.venv|\.git|node_modules|python/build)(/|$)")


def markdown_files(root):
    r = subprocess.run(["git", "-C", str(root), "ls-files", "--cached", "--others", "--exclude-standard", "*.md"],
                       capture_output=True, text=True)
    if r.returncode == 0 and r.stdout.strip():
        return sorted(root / p for p in r.stdout.split("\n") if p and (root / p).is_file())
    return sorted(p for p in root.rglob("*.md") if not SKIPPED_FOLDERS.search(p.relative_to(root).as_posix()))


def without_fences(text):
    """the text with its fenced code blocks blanked (line numbers kept)"""
    return re.sub(r"^(```|~~~).*?^\1[^\n]*$", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S | re.M)


def without_code(text):
    """the text with fenced blocks and inline code blanked (line numbers kept)"""
    return re.sub(r"`[^`\n]*`", "``", without_fences(text))


def slug(heading):
    """GitHub's anchor of a heading's text"""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # a link: its text
    text = re.sub(r"<[^>]+>", "", text).replace("`", "").strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)  # \w: letters, digits, _ (Unicode letters kept)
    return text.replace(" ", "-")


def anchors(path, cache={}):
    if path not in cache:
        found, seen = set(), {}
        text = path.read_text(errors="replace")
        for line in without_fences(text).split("\n"):
            m = re.match(r"^#{1,6}\s+(.*?)\s*#*\s*$", line)
            if m:
                base = slug(m.group(1))
                n = seen.get(base, 0)
                seen[base] = n + 1
                found.add(base if n == 0 else f"{base}-{n}")
        found |= set(re.findall(r"""<a\s+(?:name|id)=["']([^"']+)["']""", text))
        found |= set(re.findall(r"""\sid=["']([^"']+)["']""", text))
        cache[path] = found
    return cache[path]


def links(text):
    """(line, target) of the inline links, images and reference definitions"""
    out = []
    for number, line in enumerate(without_code(text).split("\n"), 1):
        for m in re.finditer(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)", line):
            out.append((number, m.group(1)))
        m = re.match(r"^\s{0,3}\[[^\]]+\]:\s*<?(\S+?)>?(\s|$)", line)
        if m and re.search(r"[./#:]", m.group(1)):  # a target, not prose ("[0, 1]: every ...")
            out.append((number, m.group(1)))
    return out


def main():
    root = Path(sys.argv[1] if len(sys.argv) > 1 else Path(__file__).resolve().parents[2]).resolve()
    failures, checked, files = [], 0, markdown_files(root)
    for md in files:
        for number, target in links(md.read_text(errors="replace")):
            if re.match(r"^[a-z][a-z0-9+.-]*:", target, re.I):  # http:, https:, mailto: ...
                continue
            checked += 1
            where = f"{md.relative_to(root)}:{number}"
            path_part, _, anchor = target.partition("#")
            resolved = md if not path_part else (md.parent / path_part).resolve()
            if path_part and not os.path.exists(resolved):
                failures.append(f"{where}: {target}: no such file or folder")
                continue
            try:
                resolved.relative_to(root)
            except ValueError:
                failures.append(f"{where}: {target}: outside the repository")
                continue
            if anchor and resolved.suffix == ".md" and anchor not in anchors(resolved):
                failures.append(f"{where}: {target}: no heading or anchor #{anchor} in {resolved.relative_to(root)}")
    print(f"{len(files)} Markdown files, {checked} relative links")
    return report(failures)


if __name__ == "__main__":
    sys.exit(main())
