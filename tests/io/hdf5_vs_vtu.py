"""hdf5_vs_vtu.py VTU_DIR HDF5_DIR: the HDF5 output of a run (solution.xdmf
and one .h5 per output time) holds the same output times and, at the last
one, the same velocity and von Mises fields at the same points as the VTU
output of the same run (single precision, like the VTU files)."""
import glob
import re
import sys
import xml.etree.ElementTree as ET

import h5py
import meshio
import numpy as np

vtu_dir, h5_dir = sys.argv[1], sys.argv[2]

# the series: one grid per output time, each naming an existing .h5 file
grids = ET.parse(h5_dir + "/solution.xdmf").getroot().iter("Grid")
times, files = [], []
for grid in grids:
    time = grid.find("Time")
    if time is None:
        continue
    times.append(float(time.get("Value")))
    items = [item.text.strip() for item in grid.iter("DataItem")]
    files.append(sorted({t.split(":")[0] for t in items if ":" in t})[0])
pvd = open(vtu_dir + "/solution.pvd").read()
vtu_times = [float(t) for t in re.findall(r'timestep="([^"]+)"', pvd)]
assert np.allclose(times, vtu_times), (times, vtu_times)


def by_point(points, values):
    """Values sorted by the rounded point coordinates (patch vertices
    repeat across cells: keep one value per point)."""
    keys = np.round(points, 9)
    order = np.lexsort(keys.T[::-1])
    keys, values = keys[order], values[order]
    first = np.ones(len(keys), dtype=bool)
    first[1:] = np.any(keys[1:] != keys[:-1], axis=1)
    return keys[first], values[first]


h5 = h5py.File(h5_dir + "/" + files[-1], "r")
dim = h5["nodes"].shape[1]
h5_points = np.zeros((h5["nodes"].shape[0], 3))
h5_points[:, :dim] = h5["nodes"][()]
h5_velocity = np.array(h5["velocity"][()]).reshape(len(h5_points), -1)[:, :dim]

pieces = sorted(glob.glob(vtu_dir + "/solution_*.vtu"))
last = max(int(re.search(r"solution_(\d+)\.", p).group(1)) for p in pieces)
points, velocity = [], []
for piece in glob.glob(f"{vtu_dir}/solution_{last:05d}.*.vtu"):
    mesh = meshio.read(piece)
    points.append(mesh.points)
    velocity.append(mesh.point_data["velocity"][:, :dim])
vtu_points, vtu_velocity = np.vstack(points), np.vstack(velocity)

a_points, a_velocity = by_point(h5_points, h5_velocity)
b_points, b_velocity = by_point(vtu_points, vtu_velocity)
assert a_points.shape == b_points.shape, (a_points.shape, b_points.shape)
assert np.allclose(a_points, b_points), "different points"
scale = np.abs(b_velocity).max()
difference = np.abs(a_velocity - b_velocity).max() / scale
assert scale > 0 and difference < 1e-6, difference
print(f"{h5_dir}: {len(times)} output times, {len(a_points)} points, "
      f"velocity equal to the VTU output (max relative difference {difference:.1e})")
