#!/usr/bin/env bash
# Results do not depend on the units (doc/solver.md, "When a step has
# converged"): a block on a Signorini wall at g = 0 with Tresca friction,
# static and quasistatic (implicit rule), with every load (surface traction, friction
# bound) scaled by s = 1, 1e-6 and 1e-12. The problem is homogeneous of
# degree one in the loads, so u/s must be the same at every scale: the
# Newton test is relative, with no absolute floor that a small load falls
# under. Compares the double-precision nodal displacement at the end.
set -euo pipefail
exe=$1; work=$2
rm -rf "$work"; mkdir -p "$work"; cd "$work"
for class in static quasistatic; do
  scheme=implicit; [ "$class" = static ] && scheme="left point"  # the default
  for scale in 1 1e-6 1e-12; do
    cat > "${class}_$scale.prm" <<PRM
set dimension = 2
subsection geometry
  set subdivisions       = 4, 1
  set global refinements = 2
end
subsection material
  subsection elasticity
    set parametrisation = young
    set young modulus   = 100
    set poisson ratio   = 0.3
  end
end
subsection problem
  set class       = $class
  set time scheme = $scheme
end
subsection time
  set end time  = 0.4
  set time step = 0.1
end
subsection data
  set constants        = s=$scale
  set surface traction = s*2*t*x/4; -s*3*t*(0.25 + x/4)
  set friction bound   = s*0.3
end
subsection normal law
  set law = signorini
end
subsection output
  set directory       = ${class}_$scale
  set precision       = double
  set terminal        = quiet
end
PRM
    "$exe" "${class}_$scale.prm"
  done
done
/usr/bin/python3 - <<'PY'
import glob, sys
import h5py, numpy as np
failed = False
for cls in ['static', 'quasistatic']:
    def scaled(scale):
        last = sorted(glob.glob(f'{cls}_{scale}/nodal_*.h5'))[-1]
        with h5py.File(last, 'r') as f:
            return np.array(f['displacement']) / float(scale)
    reference = scaled('1')
    for scale in ['1e-6', '1e-12']:
        difference = np.abs(scaled(scale) - reference).max() / np.abs(reference).max()
        ok = difference <= 1e-7
        failed |= not ok
        print(f"{cls:12s} s = {scale:6s}: max |u/s - u(s=1)| / max|u| = {difference:.1e} "
              f"{'ok' if ok else 'FAIL (> 1e-7)'}")
sys.exit(1 if failed else 0)
PY
