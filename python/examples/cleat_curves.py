#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Case R of the paper (contact length 0.28 m, cleat 0.10 x 0.10 m): the effective road of the
rigid disc, the springs model, the cam and the ring reference tire, plotted with matplotlib
when it is installed (python3-matplotlib), else written as one CSV.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/cleat_curves.py [OUT_DIR]
"""
import sys

import numpy as np

import tirenv

out_dir = sys.argv[1] if len(sys.argv) > 1 else "."
cleat = tirenv.Profile.cleat(0.10, 0.10)
x = tirenv.positions(-0.8, 0.8, 0.002)
curves = {}
for name in ("rigid", "springs", "cam", "ring"):
    model = tirenv.Model(name, tirenv.Tire())
    model.set(cleat, model.load_for_contact_length(0.28))
    curves[name] = model.envelope(x)                 # x_m, z_m, h_m, slope, fx_N, ...
    peak = curves[name]["h_m"].max()
    print(f"{name:8s} peak h {1000 * peak:6.2f} mm")

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    path = f"{out_dir}/cleat_curves.csv"
    table = np.column_stack([x] + [curves[n]["h_m"] for n in curves])
    np.savetxt(path, table, delimiter=",", fmt="%.9g", comments="",
               header="x_m," + ",".join(f"h_{n}_m" for n in curves))
    print(f"matplotlib is not installed (apt-get install python3-matplotlib): wrote {path}")
else:
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.fill_between(cleat.x, cleat.z * 1000, color="0.85", label="cleat")
    for name, c in curves.items():
        ax.plot(c["x_m"], c["h_m"] * 1000, label=name)
    ax.set_xlabel("tire centre x, m")
    ax.set_ylabel("effective height h, mm")
    ax.set_title("Case R: 0.10 x 0.10 m cleat, contact length 0.28 m")
    ax.legend()
    path = f"{out_dir}/cleat_curves.png"
    fig.savefig(path, dpi=120, bbox_inches="tight")
    print(f"wrote {path}")
