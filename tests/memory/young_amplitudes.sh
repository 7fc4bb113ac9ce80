#!/usr/bin/env bash
# young_amplitudes.sh EXE WORKDIR PRM: a run with a Prony kernel given as
# 'mu amplitudes' = 20, 5 and 'lambda amplitudes' = 30, 7.5 gives the same
# steps.csv, to a relative 1e-12, as the same kernel given as 'young
# amplitudes' = 52, 13 with 'poisson ratio' = 0.3 (mu_m = E_m/(2 (1 + nu)),
# lambda_m = E_m nu/((1 + nu)(1 - 2 nu)); doc/theory.md, section 11.4). The
# kernel matters: the same run without memory differs by more than 1e-3.
set -euo pipefail
exe=$1; work=$2; prm=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
run() { # NAME RELAXATION-LINES
  { cat "$prm"
    printf 'subsection relaxation\n%b\nend\n' "$2"
    printf 'subsection output\n  set directory = %s\n  set terminal = quiet\nend\n' "$1"; } > "$1.prm"
  "$exe" "$1.prm" > /dev/null
  cut -d, -f1-19 "$1/steps.csv" > "$1.csv"   # the counts and energies (not the defects, the wall time)
}
run lame '  set kernel = prony\n  set mu amplitudes = 20, 5\n  set lambda amplitudes = 30, 7.5\n  set relaxation times = 0.2, 1'
run young '  set kernel = prony\n  set mu amplitudes =\n  set lambda amplitudes =\n  set young amplitudes = 52, 13\n  set poisson ratio = 0.3\n  set relaxation times = 0.2, 1'
run none '  set kernel = none'
numdiff -q -r 1e-12 -a 1e-14 -s ',\n' lame.csv young.csv > /dev/null ||
  { echo "FAIL: the two forms of the kernel differ:"; numdiff -r 1e-12 -a 1e-14 -s ',\n' lame.csv young.csv | head; exit 1; }
if numdiff -q -r 1e-3 -a 1e-12 -s ',\n' lame.csv none.csv > /dev/null; then
  echo "FAIL: the run without memory gives the same numbers: the kernel is not tested"; exit 1
fi
echo "young amplitudes with poisson ratio = mu and lambda amplitudes: yes"
