#!/usr/bin/python3
"""render_frame.py SERIES.pvd OUT.png [FIELD]: read every frame of a wash .pvd
series with VTK's own reader (python3-vtk9) and draw, per frame, FIELD
(default density) of the particles in a thin slab around the middle plane
z = 0.5, titled with the frame's TimeValue. Used for the picture in
docs/semantics.md (sedov at 30^3, --output-dt 0.025)."""
import os
import sys
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import vtk
from vtk.util.numpy_support import vtk_to_numpy

series, out = sys.argv[1], sys.argv[2]
field = sys.argv[3] if len(sys.argv) > 3 else "density"
files = [d.get("file") for d in ET.parse(series).getroot().find("Collection")]
fig, axes = plt.subplots(1, len(files), figsize=(4 * len(files), 4), squeeze=False)
for ax, name in zip(axes[0], files):
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(os.path.join(os.path.dirname(series), name))
    reader.Update()
    frame = reader.GetOutput()
    pos = vtk_to_numpy(frame.GetPoints().GetData())
    values = vtk_to_numpy(frame.GetPointData().GetArray(field))
    time = frame.GetFieldData().GetArray("TimeValue").GetValue(0)
    slab = abs(pos[:, 2] - 0.5) < 0.02
    dots = ax.scatter(pos[slab, 0], pos[slab, 1], c=values[slab], s=6, cmap="viridis")
    ax.set_title(f"{name}: t = {time:.4f}")
    ax.set_aspect("equal")
    fig.colorbar(dots, ax=ax, shrink=0.8, label=field)
fig.tight_layout()
fig.savefig(out, dpi=80)
