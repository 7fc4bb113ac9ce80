#!/usr/bin/env bash
# restart_equivalence.sh EXE PRM WORKDIR RANKS_BEFORE RANKS_AFTER [PROBES]
# A run stopped after 8 steps ('checkpoint/stop after', exit code 5) on
# RANKS_BEFORE ranks and resumed on RANKS_AFTER ranks ends with the same
# steps.csv, probes.csv and solution.pvd as the uninterrupted run on
# RANKS_BEFORE ranks: bitwise (and the contact CSVs too) with the default
# solver settings if the rank counts are equal, else to 1e-7 with a tight
# Newton tolerance.
set -euo pipefail
exe=$1; prm=$2; work=$3; before=$4; after=$5; probes=${6:-4, 0; 2, 0}
here=$(cd "$(dirname "$0")" && pwd)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
launch() { local np=$1; shift; if [ "$np" -gt 1 ]; then mpirun -np "$np" "$exe" "$@"; else "$exe" "$@"; fi; }
rm -rf "$work"; mkdir -p "$work"; cd "$work"
write_prm() { # NAME DIRECTORY STOP_AFTER
  { cat "$prm"
    printf 'subsection output\n  set directory = %s\n  set vtu interval = 2\n' "$2"
    printf '  set probe points = %s\n  set terminal = quiet\nend\n' "$probes"
    printf 'subsection checkpoint\n  set interval = 3\n  set stop after = %s\nend\n' "$3"
    # on another number of ranks the AMG and the Krylov paths differ: solve
    # tightly, so that compare_runs.sh's 1e-7 separates restart errors
    # from solver differences
    [ "$before" = "$after" ] ||
      printf 'subsection nonlinear solver\n  set tolerance = 1e-10\nend\n'; } > "$1"
}
mode=tolerance; [ "$before" != "$after" ] || mode=bitwise
write_prm whole.prm whole 0
write_prm stop.prm parts 8
write_prm parts.prm parts 0

launch "$before" whole.prm
status=0; launch "$before" stop.prm 2> stop.err || status=$?
[ "$status" -eq 5 ] || { echo "FAIL: the stopped run exited with $status, not 5"; cat stop.err; exit 1; }
grep -q "stopped after step 8" stop.err || { echo "FAIL: no interruption message"; cat stop.err; exit 1; }
echo "stopped after step 8 on $before rank(s), exit code 5; checkpoints: $(ls parts/checkpoint | grep -c '\.state$')"
launch "$after" --resume parts.prm
echo "resumed on $after rank(s)"
bash "$here/compare_runs.sh" whole parts $mode
