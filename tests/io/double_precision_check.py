"""double_precision_check.py RUN_DIR RESUMED_DIR: the nodal.xdmf collection
of RUN_DIR lists the output times of its solution.pvd, each naming its
nodal_NNNNN.h5; at the last time the velocity there agrees with the VTU
output to float precision and is not float-representable (true doubles);
RESUMED_DIR (the same run stopped and resumed) holds the same collection
and bit for bit the same datasets."""
import glob
import re
import sys
import xml.etree.ElementTree as ET

import h5py
import meshio
import numpy as np

run_dir, resumed_dir = sys.argv[1], sys.argv[2]


def collection(directory):
    """(time, file) of every grid of nodal.xdmf."""
    entries = []
    for grid in ET.parse(directory + "/nodal.xdmf").getroot().iter("Grid"):
        time = grid.find("Time")
        if time is None:
            continue
        items = [i.text.strip() for i in grid.iter("DataItem")]
        files = {t.split(":")[0] for t in items}
        assert len(files) == 1, files
        entries.append((float(time.get("Value")), files.pop()))
    return entries


entries = collection(run_dir)
pvd = open(run_dir + "/solution.pvd").read()
vtu_times = [float(t) for t in re.findall(r'timestep="([^"]+)"', pvd)]
assert [t for t, _ in entries] == vtu_times, (entries, vtu_times)

# the last output time: the double values against the VTU's floats
time, name = entries[-1]
with h5py.File(run_dir + "/" + name, "r") as f:
    nodes = f["nodes"][...]
    velocity = f["velocity"][...]
    assert velocity.dtype == np.float64
step = re.search(r"nodal_([0-9]+)\.h5", name).group(1)
points, values = [], []
for piece in sorted(glob.glob(f"{run_dir}/solution_{step}.*.vtu")):
    mesh = meshio.read(piece)
    points.append(mesh.points[:, :2].astype(np.float64))
    values.append(mesh.point_data["velocity"][:, :2])
points, values = np.concatenate(points), np.concatenate(values)
lookup = {tuple(np.round(p, 5)): v for p, v in zip(points, values)}
worst = 0.0
for x, v in zip(nodes, velocity):
    vtu = lookup[tuple(np.round(x, 5))]
    scale = max(np.abs(v).max(), 1e-300)
    worst = max(worst, np.abs(vtu - v).max() / scale)
assert worst < 1e-6, worst
not_float = np.count_nonzero(velocity.astype(np.float32).astype(np.float64)
                             != velocity)
assert not_float > velocity.size // 2, (not_float, velocity.size)
print(f"{len(entries)} output times; at t = {time}: {len(nodes)} nodes, "
      f"velocity as in the VTU output to float precision, "
      f"{not_float} of {velocity.size} values not float-representable")

# the resumed run: the same collection, bit for bit the same data
assert collection(resumed_dir) == entries, collection(resumed_dir)
for _, name in entries:
    with h5py.File(run_dir + "/" + name, "r") as a, \
         h5py.File(resumed_dir + "/" + name, "r") as b:
        for key in a.keys():
            assert np.array_equal(a[key][...], b[key][...]), (name, key)
print("resumed run: the same collection and datasets, bit for bit")
