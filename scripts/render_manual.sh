#!/usr/bin/env bash
# Renders the manual (doc/DGG_VTP_3) to HTML with doxygen (Debian's package `doxygen`); any
# Doxygen warning is an error (exit status 1).
# usage: scripts/render_manual.sh [OUTPUT_DIR]   (default build/doc; the manual: OUTPUT_DIR/html/index.html)
set -euo pipefail
out=$(realpath -m "${1:-$(dirname "$0")/../build/doc}")
cd "$(dirname "$0")/.."
if ! command -v doxygen >/dev/null; then
  echo "doxygen not found (Debian: apt-get install doxygen)" >&2
  exit 77
fi
rm -rf "$out/html"
mkdir -p "$out"
python3 doc/DGG_VTP_3/bib_to_doxygen.py doc/DGG_VTP_3/DGG_VTP_3.bib > "$out/bibliography.txt"
cd doc/DGG_VTP_3
DGG_VTP_3_DOC_OUTPUT="$out" doxygen Doxyfile
echo "manual: $out/html/index.html"
