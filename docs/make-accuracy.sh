#!/usr/bin/env bash
# Regenerates the table in docs/accuracy.md from `tabletop bench --laws`
# (tests/app/BenchLawsTest.cpp fails when the page and the program differ).
# Usage, after building: docs/make-accuracy.sh [TABLETOP]
set -euo pipefail
cd "$(dirname "$0")/.."
tabletop=${1:-build/src/app/tabletop}
table=$(mktemp)
trap 'rm -f "$table"' EXIT
"$tabletop" bench --laws --rates 30,60,240,1000 > "$table" 2> /dev/null
python3 - "$table" <<'PY'
import sys
page = "docs/accuracy.md"
text = open(page).read()
begin, end = "<!-- laws: begin -->\n", "<!-- laws: end -->\n"
head, rest = text.split(begin)
_, tail = rest.split(end)
table = open(sys.argv[1]).read()
open(page, "w").write(head + begin + "```\n" + table + "```\n" + end + tail)
PY
