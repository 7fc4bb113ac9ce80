#!/usr/bin/env bash
# A manufactured solution with a kink inside the body (grad u jumps at
# x = 0.5) is named with the field, the place and the time before the
# study's first level; the shipped smooth one (pos(x - 0.4)^3 cut-offs) is
# not.
set -euo pipefail
exe=$1; prm=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
study() { # NAME EXTRA-LINES...
  local name=$1; shift
  { cat "$prm"; printf '%s\n' "$@"
    printf 'subsection geometry\n  set global refinements = 2\nend\n'
    printf 'subsection convergence study\n  set type = single\nend\n'
    printf 'subsection output\n  set directory = %s\n  set terminal = quiet\nend\n' "$name"; } > "$name.prm"
  "$exe" "$name.prm" > "$name.out" 2> "$name.err" ||
    { echo "FAIL: the $name study failed"; cat "$name.err"; exit 1; }
}
study kink 'subsection manufactured solution' \
  '  set exact displacement = (1-y)*abs(x-0.5)*sin(t); 0.1*y*(1-y)*t^2' 'end'
grep -q "warning: the manufactured solution is not smooth: grad [uw] jumps by .* near x = (0.5 " kink.err ||
  { echo "FAIL: no warning of the kink at x = 0.5"; cat kink.err; exit 1; }
study smooth
if grep -q "not smooth" smooth.err; then echo "FAIL: the smooth solution was reported"; cat smooth.err; exit 1; fi
echo "kink: $(grep -o 'grad [uw] jumps.*t = [0-9.e+-]*' kink.err); smooth: no warning"
