#!/usr/bin/env bash
# The static class does not use the density, the viscosity, the initial
# values and the time scheme (doc/theory.md, section 9.2): values other than
# the defaults are named in one line at start-up (a density and a viscosity
# of 0 included, which the velocity classes refuse), and the run equals the
# one with the defaults.
set -euo pipefail
exe=$1; prm=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
write_prm() { # NAME DENSITY VISCOSITY_MU DISPLACEMENT SCHEME
  { cat "$prm"
    printf 'subsection material\n  set density = %s\n' "$2"
    printf '  subsection viscosity\n    set mu = %s\n  end\nend\n' "$3"
    printf 'subsection data\n  set initial displacement = %s\nend\n' "$4"
    printf 'subsection problem\n  set time scheme = %s\nend\n' "$5"
    printf 'subsection output\n  set directory = %s\nend\n' "$1"; } > "$1.prm"
}
write_prm set 0 0 "0.1*x; 0" implicit
write_prm defaults 1 1 0 "left point"
"$exe" set.prm > set.out 2> set.err
"$exe" defaults.prm > defaults.out 2> defaults.err
[ "$(grep -c 'hemicontact: note: the static class does not use' set.err)" -eq 1 ] ||
  { echo "FAIL: no note (or more than one)"; cat set.err; exit 1; }
grep -q "'material/density' = 0, 'material/viscosity', 'data/initial displacement' = '0.1\*x; 0' and 'problem/time scheme'" set.err ||
  { echo "FAIL: the note does not name every value"; cat set.err; exit 1; }
! grep -q "note:" defaults.err || { echo "FAIL: a note with the defaults"; cat defaults.err; exit 1; }
cmp -s set.out defaults.out || { echo "FAIL: the ignored values changed the run"; diff set.out defaults.out | head; exit 1; }
echo "note: $(grep -o "does not use .* (no" set.err)"
