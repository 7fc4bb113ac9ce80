#!/usr/bin/env bash
# checkpoint_disk_full.sh EXE PRM WORKDIR
# A run that writes a checkpoint (about 0.9 MB) every step into a tmpfs of
# 300 kB to 2 MB stops with exit code 6 and an I/O error naming the
# checkpoint directory and the missing space, never with an abort inside
# p4est; every checkpoint it wrote before is complete: a resume from a copy
# of the directory runs to the end. Needs a tmpfs mount (root); skipped
# (exit 77) where mounting is not allowed.
set -euo pipefail
exe=$1; prm=$2; work=$3
rm -rf "$work"; mkdir -p "$work/disk"; cd "$work"
mount -t tmpfs -o size=100k tmpfs disk 2> /dev/null || { echo "cannot mount a tmpfs here: skipped"; exit 77; }
umount disk
trap 'cd / && umount "$work/disk" 2> /dev/null || true' EXIT
write_prm() { # NAME DIRECTORY
  { cat "$prm"
    printf 'subsection geometry\n  set global refinements = 5\nend\n'
    printf 'subsection time\n  set end time = 0.1\n  set time step = 0.01\nend\n'
    printf 'subsection output\n  set directory = %s\n  set terminal = quiet\nend\n' "$2"
    printf 'subsection checkpoint\n  set interval = 1\nend\n'; } > "$1"
}
write_prm run.prm disk/out
write_prm resume.prm copy
for size in 300k 400k 500k 600k 700k 800k 900k 1000k 1500k 2000k; do
  mount -t tmpfs -o size=$size tmpfs disk
  status=0; "$exe" run.prm > run.out 2> run.err || status=$?
  [ "$status" -eq 6 ] || { echo "FAIL ($size): exit code $status, not 6"; cat run.err; exit 1; }
  grep -q "I/O error: cannot write the checkpoint of step [0-9]* in 'disk/out/checkpoint': No space left on device (about [0-9]* KiB needed, [0-9]* KiB free)" run.err ||
    { echo "FAIL ($size): the message does not name the directory and the cause"; cat run.err; exit 1; }
  rm -rf copy; cp -a disk/out copy
  umount disk
  written=$(ls copy/checkpoint 2> /dev/null | grep -c '\.state$' || true)
  if [ "$written" -gt 0 ]; then
    "$exe" --resume resume.prm > resume.out 2> resume.err ||
      { echo "FAIL ($size): the resume from the checkpoints written failed"; cat resume.err; exit 1; }
    [ "$(tail -1 copy/steps.csv | cut -d, -f1)" -eq 10 ] || { echo "FAIL ($size): the resume did not reach step 10"; exit 1; }
  fi
  echo "$size: exit 6, $written checkpoint(s) before it$( [ "$written" -eq 0 ] || echo ", resumed to the end"): $(cut -c1-200 run.err)"
done
