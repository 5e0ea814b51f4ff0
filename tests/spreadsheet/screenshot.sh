#!/usr/bin/env bash
# Remakes docs/figures/spreadsheet-sites.png, the picture of the workbook's sheet "sites" in
# docs/spreadsheet.md: trebuchet-calc writes the workbook, LibreOffice headless exports it as
# HTML (every number as shown, the input cells yellow), the sheet's first 27 rows are laid out
# like a spreadsheet (fixed columns, texts running over empty cells, grid lines) and headless
# Chromium photographs them. LibreOffice's own PNG export of a sheet needs its Draw module.
# Usage: bash tests/spreadsheet/screenshot.sh BUILD_DIR/calc/trebuchet-calc [OUT.png]
set -euo pipefail
calc=$(realpath "$1")
out=$(realpath -m "${2:-$(dirname "$0")/../../docs/figures/spreadsheet-sites.png}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$calc" --spreadsheet workbook.xlsx > /dev/null
soffice -env:UserInstallation="file://$work/profile" --headless --convert-to html workbook.xlsx > /dev/null 2>&1
python3 - workbook.html sites.html <<'PY'
import re, sys
html = open(sys.argv[1], encoding='utf-8').read()
sheet = html[html.index('<A NAME="table6">'):html.index('<A NAME="table7">')]  # the 7th sheet, "sites"
sheet = sheet[sheet.index('<table'):]
# Column A, then B to O (level to A), then P (status); Q (valid) is left out.
widths = [200] + [66] * 14 + [250]
sheet = re.sub(r'<colgroup[^>]*></colgroup>\s*', '', sheet)
sheet = sheet.replace('<table cellspacing="0" border="0">', '<table cellspacing="0" border="0" style="width:%dpx">' % sum(widths) +
                      ''.join('<col style="width:%dpx">' % w for w in widths), 1)
rows = sheet.split('<tr')
style = ('<style>body { margin: 8px; background: white; } table { table-layout: fixed; border-collapse: collapse; } '
         'td { white-space: nowrap; overflow: visible; font-family: "DejaVu Sans", sans-serif; font-size: 12px; height: 19px; '
         'padding: 0 3px; border: 1px solid #dcdcdc; }</style>')
open(sys.argv[2], 'w', encoding='utf-8').write('<!DOCTYPE html><html><head><meta charset="utf-8">' + style + '</head><body>' +
                                               '<tr'.join(rows[:28]) + '</table></body></html>')
PY
chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size=1370,580 --screenshot="$out" "file://$work/sites.html" > /dev/null 2>&1
echo "wrote $out"
