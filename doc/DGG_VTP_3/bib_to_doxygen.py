"""Writes the manual's bibliography page (Doxygen) from DGG_VTP_3.bib, for \\cgalCite{key}:
one anchor cite_<key> per entry. Doxygen's own \\cite needs bibtex, which a plain Debian with
doxygen does not have; the few simple entries here need no more than this.

usage: python3 bib_to_doxygen.py DGG_VTP_3.bib > bibliography.txt
"""
import re
import sys


def entries(text):
    """(key, {field: value}) for each @type{key, field = {value}, ...} of a BibTeX file."""
    for match in re.finditer(r"@\w+\s*\{\s*([\w:-]+)\s*,(.*?)\n\}", text, re.S):
        fields = {}
        for name, value in re.findall(r"(\w+)\s*=\s*\{((?:[^{}]|\{[^{}]*\})*)\}", match.group(2)):
            value = re.sub(r"\\url\{([^}]*)\}", r"\1", value)
            fields[name.lower()] = " ".join(value.replace("{", "").replace("}", "").split())
        yield match.group(1), fields


def reference(fields):
    parts = [fields["author"].replace(" and ", ", ")] if "author" in fields else []
    parts.append("<em>" + fields["title"] + "</em>")
    venue = fields.get("journal", "")
    if "volume" in fields:
        venue += " " + fields["volume"] + ("(" + fields["number"] + ")" if "number" in fields else "")
    if "pages" in fields:
        venue += ": " + fields["pages"].replace("--", "-")
    parts += [p for p in (venue.strip(), fields.get("year"), fields.get("howpublished")) if p]
    return ". ".join(parts) + "." + (" " + fields["note"] + "." if "note" in fields else "")


def main():
    with open(sys.argv[1], encoding="utf-8") as bib:
        text = bib.read()
    print("/*!\n\\page dggvtp_bibliography Bibliography\n")
    for key, fields in entries(text):
        print("\\anchor cite_%s\n<b>[%s]</b> %s\n" % (key, key, reference(fields)))
    print("*/")


if __name__ == "__main__":
    main()
