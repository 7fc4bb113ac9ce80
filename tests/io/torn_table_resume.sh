#!/usr/bin/env bash
# torn_table_resume.sh EXE PRM WORKDIR
# A run stopped after 8 steps (checkpoint of step 8) whose steps.csv ends in
# a row cut short in its middle: the resume drops that row with a warning
# naming the file and the line, and every row of the resumed table is
# complete (as many fields as the header, steps increasing). A line that
# is not a row of numbers in the middle of steps.csv: the resume is refused
# (exit code 2) naming the file and the line, steps.csv is unchanged and no
# steps.csv.tmp is left.
set -euo pipefail
exe=$1; prm=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
{ cat "$prm"
  printf 'subsection time\n  set time step = 0.04\nend\n'
  printf 'subsection output\n  set directory = out\n  set probe points = 4, 0\n'
  printf '  set terminal = quiet\nend\n'
  printf 'subsection checkpoint\n  set interval = 4\nend\n'; } > run.prm
{ cat run.prm; printf 'subsection checkpoint\n  set stop after = 8\nend\n'; } > stop.prm
status=0; "$exe" stop.prm 2> stop.err || status=$?
[ "$status" -eq 5 ] || { echo "FAIL: the stopped run exited with $status, not 5"; cat stop.err; exit 1; }
cp -a out stopped

# the last row (step 8) cut in its middle, without its line end
size=$(stat -c %s out/steps.csv)
truncate -s $((size - 100)) out/steps.csv
"$exe" --resume run.prm 2> resume.err
grep -q "warning: line 9 of 'out/steps.csv' is cut short" resume.err ||
  { echo "FAIL: no warning naming the torn row"; cat resume.err; exit 1; }
awk -F, 'NR == 1 { n = NF; next }
         NF != n || $1 <= last { print "FAIL: line " NR " is not a complete row after step " last ": " $0; bad = 1 }
         { last = $1 }
         END { exit bad }' out/steps.csv
[ "$(tail -1 out/steps.csv | cut -d, -f1)" -eq 25 ] || { echo "FAIL: steps.csv does not end at step 25"; exit 1; }
echo "torn last row: $(head -1 resume.err)"

# a line that is not a row of numbers in the middle of the table
rm -rf out; cp -a stopped out
sed -i '5s/.*/not a row/' out/steps.csv
cp out/steps.csv damaged.csv
status=0; "$exe" --resume run.prm 2> damaged.err || status=$?
[ "$status" -eq 2 ] || { echo "FAIL: the resume exited with $status, not 2"; cat damaged.err; exit 1; }
grep -q "input error: checkpoint: line 5 of 'out/steps.csv' is not a complete row of numbers ('not a row')" damaged.err ||
  { echo "FAIL: the message does not name the file and the line"; cat damaged.err; exit 1; }
cmp damaged.csv out/steps.csv || { echo "FAIL: steps.csv was changed"; exit 1; }
! ls out/*.tmp > /dev/null 2>&1 || { echo "FAIL: a .tmp file was left: $(ls out/*.tmp)"; exit 1; }
echo "non-numeric line: exit 2: $(cat damaged.err)"
