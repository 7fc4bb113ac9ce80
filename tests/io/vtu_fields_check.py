"""vtu_fields_check.py BENCH_DIR RUN_DIR: bench/vtu_fields.py reads a VTU
piece of a 2D run: one patch of 4 vertices per cell and a finite, nonzero
velocity with 3 components at each vertex."""
import glob
import sys

import numpy as np

sys.path.insert(0, sys.argv[1])
import vtu_fields  # noqa: E402

pieces = sorted(glob.glob(sys.argv[2] + "/solution_*.0.vtu"))
assert len(pieces) >= 2, "no VTU pieces in " + sys.argv[2]
arrays = vtu_fields.read_vtu(pieces[-1])
points, velocity = arrays["points"], arrays["velocity"]
assert points.shape[0] % 4 == 0 and points.shape[1] == 3, points.shape
assert velocity.shape == (points.shape[0], 3), velocity.shape
assert np.all(np.isfinite(velocity)) and np.abs(velocity).max() > 0
print(f"{pieces[-1]}: {points.shape[0] // 4} cells, |w| up to {np.abs(velocity).max():.3g}")
