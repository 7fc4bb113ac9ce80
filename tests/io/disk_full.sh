#!/usr/bin/env bash
# disk_full.sh EXE PRM WORKDIR
# A run whose output directory is on a 1 MiB file system that fills up
# during the run stops with exit code 6 and an I/O error naming the file
# and "No space left on device"; steps.csv and probes.csv end on a complete
# row, solution.pvd is complete and lists only files that exist. Needs a
# tmpfs mount (root); skipped (exit 77) where mounting is not allowed.
set -euo pipefail
exe=$1; prm=$2; work=$3
rm -rf "$work"; mkdir -p "$work/disk"; cd "$work"
mount -t tmpfs -o size=1m tmpfs disk 2> /dev/null || { echo "cannot mount a tmpfs here: skipped"; exit 77; }
trap 'cd / && umount "$work/disk" 2> /dev/null || true' EXIT
{ cat "$prm"
  printf 'subsection geometry\n  set global refinements = 4\nend\n'
  printf 'subsection time\n  set time step = 0.04\nend\n'
  printf 'subsection output\n  set directory = disk/out\n  set vtu interval = 1\n'
  printf '  set probe points = 4, 0\n  set terminal = quiet\nend\n'; } > run.prm
status=0; "$exe" run.prm 2> run.err || status=$?
[ "$status" -eq 6 ] || { echo "FAIL: exit code $status, not 6"; cat run.err; exit 1; }
grep -q "hemicontact: I/O error: cannot write .*disk/out.*: No space left on device." run.err ||
  { echo "FAIL: the message does not name the file and the cause"; cat run.err; exit 1; }
for table in steps probes; do
  header=$(head -1 disk/out/$table.csv | tr -cd , | wc -c)
  last=$(tail -1 disk/out/$table.csv | tr -cd , | wc -c)
  [ "$(tail -c 1 disk/out/$table.csv | od -An -c | tr -d ' ')" = '\n' ] && [ "$header" -eq "$last" ] ||
    { echo "FAIL: $table.csv does not end on a complete row"; tail -2 disk/out/$table.csv; exit 1; }
done
tail -1 disk/out/solution.pvd | grep -q "</VTKFile>" || { echo "FAIL: solution.pvd is incomplete"; exit 1; }
for f in $(grep -o 'file="[^"]*"' disk/out/solution.pvd | cut -d'"' -f2); do
  [ -s "disk/out/$f" ] || { echo "FAIL: solution.pvd lists $f, which is missing"; exit 1; }
done
! ls disk/out/*.tmp > /dev/null 2>&1 || { echo "FAIL: a .tmp file was left"; exit 1; }
echo "exit 6: $(cat run.err)"
echo "steps.csv: $(($(wc -l < disk/out/steps.csv) - 1)) complete rows; solution.pvd: $(grep -c DataSet disk/out/solution.pvd) complete files"
