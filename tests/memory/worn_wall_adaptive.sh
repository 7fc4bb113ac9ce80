#!/usr/bin/env bash
# worn_wall_adaptive.sh EXE WORKDIR PRM: the worn wall kept across mesh
# adaptations (doc/theory.md 11.12, wall_position()). The run of PRM
# (tests/memory/wear_2d.prm: a compliant law up to a wall at g = 0.02, a
# foundation moving with v* = (1, 0)) with a strong wear, k_w = 0.5, so
# that the wall recedes far beyond g, and refinement every 4 steps
# (refine only: the interpolation moves the state exactly), in the
# quasistatic and the dynamic class. The adaptation must keep every node
# where it is: no node is "moved back onto the wall" (a node held at the
# worn wall g + omega is not beyond it), the stored energy is the same
# before and after each adaptation (relative 1e-9), the wear must exceed g
# (so that a wall taken at g would be crossed), and every contact node
# satisfies u_nu <= g + omega in the last contact CSV.
set -euo pipefail
exe=$1; work=$2; prm=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
for class in quasistatic dynamic; do
  { sed "s/set class *=.*/set class = $class/; s/set directory *=.*/set directory = $class/; s/set wear coefficient *=.*/set wear coefficient = 0.5/; s/set terminal *=.*/set terminal = test/" "$prm"
    printf 'subsection adaptivity\n  set interval = 4\n  set indicator = kelly\n  set refine fraction = 0.3\n  set coarsen fraction = 0\n  set max level = 5\nend\n'
    printf 'subsection output\n  set precision = double\nend\n'; } > $class.prm
  "$exe" $class.prm > $class.log 2>&1 || { echo "FAIL: $class run"; cat $class.log; exit 1; }
done
/usr/bin/python3 - <<'PY'
import glob, re, sys
import pandas as pd
g = 0.02
for cls in ("quasistatic", "dynamic"):
    log = open(f"{cls}.log").read()
    if "crossed the wall" in log:
        sys.exit(f"FAIL ({cls}): an adaptation moved nodes onto a wall:\n" +
                 "\n".join(l for l in log.splitlines() if "crossed" in l))
    pairs = [(float(a), float(b)) for a, b in
             re.findall(r"energy before ([-0-9.e+]+), after ([-0-9.e+]+)", log)]
    if len(pairs) < 2:
        sys.exit(f"FAIL ({cls}): {len(pairs)} adaptations, expected at least 2")
    for before, after in pairs:
        if abs(after - before) > 1e-9 * abs(before):
            sys.exit(f"FAIL ({cls}): the adaptation changed the stored energy "
                     f"from {before} to {after}")
    last = sorted(glob.glob(f"{cls}/contact_*.csv"))[-1]
    c = pd.read_csv(last)
    omega = c["wear"].max()
    if not omega > 2 * g:
        sys.exit(f"FAIL ({cls}): the wear {omega} does not exceed 2 g: the test "
                 "does not see a worn wall")
    print(f"{cls}: {len(pairs)} adaptations, energy kept (largest change "
          f"{max(abs(a - b) / abs(b) for b, a in pairs):.1e} relative), largest "
          f"wear {omega:.3f} > g = {g}, no node moved")
PY
