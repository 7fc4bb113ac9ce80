#!/usr/bin/env bash
# json_entries.sh EXE SOURCE_DIR WORKDIR
# A JSON parameter file that starts with a UTF-8 byte order mark is read as
# JSON (the same run as without the mark); one that has a key twice in an
# object, or a subsection or entry that is not declared (a typo), is
# refused (exit 2) naming the key path, as the .prm reader names them.
set -euo pipefail
exe=$1; src=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
settings='"time": {"end time": "0.05", "time step": "0.01"},
 "geometry": {"global refinements": "2"},
 "output": {"directory": "DIR", "vtu interval": "0", "terminal": "quiet"}'
echo "{ ${settings//DIR/plain} }" > plain.json
{ printf '\xef\xbb\xbf'; echo "{ ${settings//DIR/bom} }"; } > bom.json
"$exe" plain.json > plain.out
"$exe" bom.json > bom.out 2> bom.err || { echo "FAIL: the JSON file with a byte order mark was not accepted"; cat bom.err; exit 1; }
bash "$src/tests/restart/compare_runs.sh" plain bom
echo "bom.json: the same run as plain.json"

echo '{ "time": {"end time": "0.05", "time step": "0.01", "end time": "0.02"} }' > twice.json
rc=0; "$exe" twice.json > twice.out 2> twice.err || rc=$?
[ "$rc" = 2 ] || { echo "FAIL: a key given twice: exit $rc, expected 2"; cat twice.err; exit 1; }
grep -q "has the key 'time/end time' twice" twice.err || { echo "FAIL: the message does not name the key path:"; cat twice.err; exit 1; }
[ "$(wc -l < twice.err)" = 1 ] || { echo "FAIL: the message is not one paragraph:"; cat twice.err; exit 1; }
echo "twice.json: refused: $(cat twice.err)"

# a subsection, an entry of a subsection, an entry at the top level and an
# entry of a law's subsection misspelt; a subsection given as a value
for case in '{ "normal laws": {"law": "signorini"} }|the subsection '"'"'normal laws'"'"', but there is no such subsection at the top level' \
            '{ "normal law": {"lawz": "signorini"} }|the entry '"'"'normal law/lawz'"'"', but there is no such entry in subsection '"'"'normal law'"'"'' \
            '{ "dimenzion": "2" }|the entry '"'"'dimenzion'"'"', but there is no such entry at the top level' \
            '{ "normal law": {"signorini": {"penetration limitt": "0"}} }|the entry '"'"'normal law/signorini/penetration limitt'"'"', but there is no such entry in subsection '"'"'normal law/signorini'"'"'' \
            '{ "time": "1" }|gives '"'"'time'"'"' as an entry (a value), but it is a subsection at the top level'; do
  echo "${case%%|*}" > typo.json
  rc=0; "$exe" typo.json > typo.out 2> typo.err || rc=$?
  [ "$rc" = 2 ] || { echo "FAIL: ${case%%|*}: exit $rc, expected 2"; cat typo.err; exit 1; }
  grep -qF "${case#*|}" typo.err || { echo "FAIL: ${case%%|*}: the message does not say: ${case#*|}"; cat typo.err; exit 1; }
  [ "$(wc -l < typo.err)" = 1 ] || { echo "FAIL: the message is not one paragraph:"; cat typo.err; exit 1; }
  echo "${case%%|*}: refused: $(cat typo.err)"
done
