#!/usr/bin/env bash
# The quasistatic class does not use the density and the initial velocity
# (doc/theory.md, section 9.2): values other than the defaults are named in
# one line at start-up (a density of 0 included, which the dynamic class
# refuses), and the run equals the one with the defaults.
set -euo pipefail
exe=$1; prm=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
write_prm() { # NAME DENSITY VELOCITY
  { cat "$prm"
    printf 'subsection material\n  set density = %s\nend\n' "$2"
    printf 'subsection data\n  set initial velocity = %s\nend\n' "$3"
    printf 'subsection output\n  set directory = %s\nend\n' "$1"; } > "$1.prm"
}
write_prm set 0 "0.1*x; 0"
write_prm defaults 1 0
"$exe" set.prm > set.out 2> set.err
"$exe" defaults.prm > defaults.out 2> defaults.err
[ "$(grep -c 'hemicontact: note: the quasistatic class does not use' set.err)" -eq 1 ] ||
  { echo "FAIL: no note (or more than one)"; cat set.err; exit 1; }
grep -q "'material/density' = 0 and 'data/initial velocity' = '0.1\*x; 0'" set.err ||
  { echo "FAIL: the note does not name both values"; cat set.err; exit 1; }
! grep -q "note:" defaults.err || { echo "FAIL: a note with the defaults"; cat defaults.err; exit 1; }
cmp -s set.out defaults.out || { echo "FAIL: the ignored values changed the run"; diff set.out defaults.out | head; exit 1; }
echo "note: $(grep -o "does not use .* (no" set.err)"
