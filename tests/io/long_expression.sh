#!/usr/bin/env bash
# long_expression.sh EXE WORKDIR
# A data expression of 1.6 MB, longer than an expression may be, gives one
# paragraph on standard error (exit 2) that quotes at most the first 200
# characters of the expression.
set -euo pipefail
exe=$1; work=$2
rm -rf "$work"; mkdir -p "$work"; cd "$work"
{
  printf 'subsection data\n  set body force = 0; '
  for i in $(seq 0 129999); do printf 'sin(x*%d)+' "$i"; done
  printf '1\nend\n'
} > long.prm
echo "expression of $(wc -c < long.prm) bytes"
rc=0; "$exe" long.prm > long.out 2> long.err || rc=$?
[ "$rc" = 2 ] || { echo "FAIL: exit $rc, expected 2"; head -c 1000 long.err; exit 1; }
size=$(wc -c < long.err)
[ "$(wc -l < long.err)" = 1 ] && [ "$size" -lt 1000 ] || { echo "FAIL: $size bytes, $(wc -l < long.err) lines on standard error:"; head -c 1000 long.err; exit 1; }
grep -q "input error: data: cannot parse 'body force' = '0; sin(x\*0)+.*\.\.\.' (.* characters)" long.err || { echo "FAIL: unexpected message:"; cat long.err; exit 1; }
echo "one paragraph of $size bytes: $(cat long.err)"
