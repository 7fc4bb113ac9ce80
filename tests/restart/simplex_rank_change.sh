#!/usr/bin/env bash
# simplex_rank_change.sh EXE PRM WORKDIR
# A simplex (parallel::fullydistributed) checkpoint written on 2 ranks and
# resumed on 1 is refused: exit code 2 and a message naming both counts;
# the checkpoint is left as it was and still resumes on 2 ranks.
set -euo pipefail
exe=$1; prm=$2; work=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
rm -rf "$work"; mkdir -p "$work"; cd "$work"
{ cat "$prm"
  printf 'subsection output\n  set directory = run\n  set terminal = quiet\nend\n'
  printf 'subsection checkpoint\n  set interval = 2\n  set stop after = 4\nend\n'; } > stop.prm
sed 's/set stop after = 4/set stop after = 0/' stop.prm > resume.prm
status=0; mpirun -np 2 "$exe" stop.prm 2> stop.err || status=$?
[ "$status" -eq 5 ] || { echo "FAIL: the stopped run exited with $status, not 5"; cat stop.err; exit 1; }
before=$(cd run/checkpoint && cksum * | sort)
status=0; "$exe" --resume resume.prm 2> refused.err || status=$?
[ "$status" -eq 2 ] || { echo "FAIL: the resume on 1 rank exited with $status, not 2"; cat refused.err; exit 1; }
grep -q "written by 2 MPI ranks and this run has 1" refused.err ||
  { echo "FAIL: the message does not name both counts"; cat refused.err; exit 1; }
[ "$(cd run/checkpoint && cksum * | sort)" = "$before" ] ||
  { echo "FAIL: the refused resume changed the checkpoint"; exit 1; }
echo "refused on 1 rank: $(head -c 300 refused.err)"
mpirun -np 2 "$exe" --resume resume.prm 2> resumed.err ||
  { echo "FAIL: the resume on 2 ranks failed"; cat resumed.err; exit 1; }
echo "resumed on 2 ranks: $(tail -n +2 run/steps.csv | wc -l) steps in steps.csv"
