#!/usr/bin/python3
"""wash_read.py: wash output as numpy arrays.

A frame is a dict from column name to a 1D float64 array, rows in ascending id
order, named as in the CSV files: id, x, y[, z], vx, vy[, vz], density, mass,
smoothing_length, then every field (a vector field v as v_x, v_y[, v_z]).

    import sys; sys.path.insert(0, "scripts")
    import wash_read
    wash_read.steps("out/sim.h5")            # [(group, step, time), ...]
    f = wash_read.load("out/sim.h5")         # the last step; step=K for Step#K
    f = wash_read.load("out/sim_000100.csv") # a CSV frame or a --dump file
    pos = wash_read.vector(f, "pos")         # (N, 3) array; "vel", "acc", ...
    f.time, f.step                           # of an HDF5 step (None for CSV)

From the shell: `python3 scripts/wash_read.py FILE [STEP]` prints each
column's range (and lists the steps of an .h5 file).

.h5 files need h5py (Debian python3-h5py); CSV needs only numpy.
"""
import csv
import sys

import numpy as np


class Frame(dict):
    """Columns by name, plus the step's time and step number (HDF5 only)."""

    time = None
    step = None


def steps(path):
    """The (group name, step, time) of every step of an --format hdf5 file, in order."""
    import h5py

    with h5py.File(path, "r") as f:
        groups = sorted(f, key=lambda g: int(g.split("#")[1]))
        return [(g, int(f[g].attrs["step"]), float(f[g].attrs["time"])) for g in groups]


def load(path, step=-1):
    """One frame of a .h5 file (Step#<step>, or the last one for -1) or a CSV file."""
    frame = Frame()
    if path.endswith(".h5"):
        import h5py

        with h5py.File(path, "r") as f:
            group = f[steps(path)[step][0]] if step < 0 else f["Step#%d" % step]
            for name, dataset in group.items():
                frame[name] = dataset[()]
            frame.time = float(group.attrs["time"])
            frame.step = int(group.attrs["step"])
        return frame
    with open(path, newline="") as fh:
        header = next(csv.reader(fh))
    # float64 reads the files' %.17g text back as the doubles the run held.
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    for k, name in enumerate(header):
        frame[name] = data[:, k].astype(np.uint64) if name == "id" else data[:, k]
    return frame


def vector(frame, name):
    """A vector column as an (N, components) array: pos, vel or a vector field."""
    if name == "pos":
        names = [a for a in ("x", "y", "z") if a in frame]
    elif name == "vel":
        names = [a for a in ("vx", "vy", "vz") if a in frame]
    else:
        names = [name + "_" + a for a in "xyz" if name + "_" + a in frame]
    if not names:
        raise KeyError("no vector %r in this frame (its columns: %s)" % (name, ", ".join(frame)))
    return np.stack([frame[n] for n in names], axis=1)


def main(argv):
    if len(argv) < 2:
        sys.exit(__doc__)
    path = argv[1]
    if path.endswith(".h5"):
        for group, step, time in steps(path):
            print("%s: step %d, time %.17g" % (group, step, time))
    frame = load(path, int(argv[2]) if len(argv) > 2 else -1)
    for name, values in frame.items():
        print("%-20s %d rows, min %.17g, max %.17g" % (name, len(values), values.min(), values.max()))


if __name__ == "__main__":
    main(sys.argv)
