#!/usr/bin/env bash
# parameter_encodings.sh EXE PRM WORKDIR
# A parameter file saved with Windows line ends (CRLF) and with a UTF-8
# byte order mark is read as the plain file: the runs print the same.
set -euo pipefail
exe=$1; prm=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
cp "$prm" plain.prm
sed 's/$/\r/' "$prm" > crlf.prm
{ printf '\xef\xbb\xbf'; sed 's/$/\r/' "$prm"; } > bom_crlf.prm
{ printf '\xef\xbb\xbf'; cat "$prm"; } > bom.prm
"$exe" plain.prm > plain.out
for f in crlf bom bom_crlf; do
  "$exe" $f.prm > $f.out
  cmp -s plain.out $f.out || { echo "FAIL: $f.prm runs differently"; diff plain.out $f.out | head; exit 1; }
  echo "$f.prm: the same run as the plain file"
done
