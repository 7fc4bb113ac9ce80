#!/usr/bin/env bash
# damaged_checkpoint.sh EXE PRM WORKDIR
# A run stopped after 8 steps keeps the checkpoints of steps 6 and 8. The
# newest is damaged: its .mesh file truncated, its field data changed, its
# .state edited (one energy value taken out, with or without the state's
# own checksum recomputed), or a .state renamed so that it looks newer
# than it is (step 6's state as step 10's). The resume names the damaged
# file, falls back to the newest intact checkpoint of the run and ends
# bitwise equal to the uninterrupted run. With both checkpoints damaged
# the resume is refused (exit code 2) and names them. A .state of another
# format version is named with both versions and skipped, not called
# damaged.
set -euo pipefail
exe=$1; prm=$2; work=$3
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"; mkdir -p "$work"; cd "$work"
write_prm() { # NAME DIRECTORY STOP_AFTER
  { cat "$prm"
    printf 'subsection output\n  set directory = %s\n  set vtu interval = 2\n' "$2"
    printf '  set probe points = 4, 0; 2, 0\n  set terminal = quiet\nend\n'
    printf 'subsection checkpoint\n  set interval = 3\n  set stop after = %s\nend\n' "$3"; } > "$1"
}
write_prm whole.prm whole 0
write_prm stop.prm parts 8
write_prm parts.prm parts 0
"$exe" whole.prm
status=0; "$exe" stop.prm 2> stop.err || status=$?
[ "$status" -eq 5 ] || { echo "FAIL: the stopped run exited with $status, not 5"; cat stop.err; exit 1; }
cp -r parts parts-saved

# take the first energy term out of a .state (its count lowered to match);
# with 'fixed' the state's checksum line is recomputed for the new content
take_out_energy() { # FILE [fixed]
  python3 - "$@" << 'PY'
import sys, zlib
path = sys.argv[1]
text = open(path).read()
cut = text.rstrip('\n').rfind('\n') + 1
body, checksum = text[:cut], text[cut:]
tokens = body.split(' ')
# 22 serialization::archive V 0 1 step k n_steps 0 0 count item_version
# 0 0 (length name value) per energy term ...
assert tokens[15] == 'kinetic', tokens[:16]
tokens[10] = str(int(tokens[10]) - 1)
del tokens[14:17]
body = ' '.join(tokens)
if len(sys.argv) > 2:
    checksum = 'crc32 %d\n' % zlib.crc32(body.encode())
open(path, 'w').write(body + checksum)
PY
}

for damage in truncate flip edited short renamed; do
  rm -rf parts; cp -r parts-saved parts
  newest=8; file=parts/checkpoint/step-000008.mesh; fallback=6
  case $damage in
    truncate) truncate -s 100 $file ;;
    # one byte of the field data changed, the size kept
    flip) file=parts/checkpoint/step-000008.mesh_fixed.data
          printf 'X' | dd of=$file bs=1 seek=200 conv=notrunc 2> /dev/null ;;
    edited) file=parts/checkpoint/step-000008.state; take_out_energy $file ;;
    short) file=parts/checkpoint/step-000008.state; take_out_energy $file fixed ;;
    renamed) newest=10; file=parts/checkpoint/step-000010.state; fallback=8
             mv parts/checkpoint/step-000006.state $file ;;
  esac
  "$exe" --resume parts.prm 2> resume.err ||
    { echo "FAIL ($damage): the resume failed"; cat resume.err; exit 1; }
  grep -q "the checkpoint of step $newest is damaged: '$file" resume.err ||
    { echo "FAIL ($damage): the damaged checkpoint is not named"; cat resume.err; exit 1; }
  echo "$damage: $(head -1 resume.err)"
  bash "$here/compare_runs.sh" whole parts bitwise
done

# a whole .state of another format version (the class version, the fifth
# token, set to 1, its checksum recomputed) is no damage: it is named with
# both versions and skipped
rm -rf parts; cp -r parts-saved parts
python3 - parts/checkpoint/step-000008.state << 'PY'
import sys, zlib
path = sys.argv[1]
text = open(path).read()
body = text[:text.rstrip('\n').rfind('\n') + 1]
tokens = body.split(' ')
assert tokens[1] == 'serialization::archive', tokens[:5]
tokens[4] = '1'
body = ' '.join(tokens)
open(path, 'w').write(body + 'crc32 %d\n' % zlib.crc32(body.encode()))
PY
"$exe" --resume parts.prm 2> resume.err ||
  { echo "FAIL (version): the resume failed"; cat resume.err; exit 1; }
grep -q "the checkpoint of step 8 is skipped: 'parts/checkpoint/step-000008.state' was written by checkpoint format version 1, this program reads version 2" resume.err ||
  { echo "FAIL (version): not named as another format version"; cat resume.err; exit 1; }
! grep -q "damaged" resume.err ||
  { echo "FAIL (version): called damaged"; cat resume.err; exit 1; }
echo "version: $(head -1 resume.err)"
bash "$here/compare_runs.sh" whole parts bitwise

rm -rf parts; cp -r parts-saved parts
truncate -s 100 parts/checkpoint/step-000008.mesh
truncate -s 0 parts/checkpoint/step-000006.state
status=0; "$exe" --resume parts.prm 2> refused.err || status=$?
[ "$status" -eq 2 ] || { echo "FAIL: resuming from two damaged checkpoints exited with $status, not 2"; cat refused.err; exit 1; }
grep -q "input error: checkpoint: no checkpoint in 'parts/checkpoint' can be resumed from" refused.err ||
  { echo "FAIL: no clear refusal"; cat refused.err; exit 1; }
echo "both damaged: $(tail -1 refused.err)"
