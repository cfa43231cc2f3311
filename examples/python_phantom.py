#!/usr/bin/env python3
# %% [markdown]
# # pfdm from Python: the independent LV phantom, fitted and plotted
#
#     PYTHONPATH=build/python /usr/bin/python3 examples/python_phantom.py
#
# A script in cells (`# %%`, as VS Code, Spyder and Jupytext open them).
# Writes out/examples/python-phantom/: the CLI's output files (fit/), and,
# where matplotlib is installed, functions.png (twist and a3 against the
# knot, one line per frame), strain.png (each mid segment's circumferential
# strain over the frames, from `to_dataframe`) and surface.png (the last
# frame's surface with its data points).  Without matplotlib it prints the
# numbers instead.

# %%
import argparse
import pathlib

import numpy as np
import pfdm

parser = argparse.ArgumentParser(description="Fits the LV phantom from Python.")
parser.add_argument("--frames", type=int, default=5)
parser.add_argument("--tags", type=int, default=2000)
parser.add_argument("--out", default="out/examples/python-phantom")
args, _ = parser.parse_known_args()
out = pathlib.Path(args.out)

# %% [markdown]
# The phantom is not the model: its truth is measured on its own material
# points.  The fit takes the CLI's defaults; keywords are its flags.  The
# RV insertion points place the AHA segments (anterior, anteroseptal, ...).

# %%
points, truth = pfdm.simulate(phantom="lv", frames=args.frames, tags=args.tags)
insertion = truth["rv_insertion"]
fit = pfdm.fit(points, rv_insertion=insertion["anterior"] + insertion["inferior"])
fit.write(out / "fit")

# The phantom's tags lie on a mid-wall surface: its volume is not the
# cavity's (tags through the wall or contours of both walls give that).
volume = fit.volume_surface + "_volume_ml"
for frame in fit:
    c = frame.clinical
    print(f"frame {frame.frame}: rms {frame.stats['rms_mm']:.3f} mm, "
          f"net twist {c['net_twist_deg']:+.2f} deg, "
          f"longitudinal shortening {c['longitudinal_shortening_percent']:.1f} % "
          f"(truth {truth['frames'][frame.frame]['longitudinal_shortening_percent']:.1f}), "
          f"{volume} {c[volume]:.1f}")
fraction = (fit.ejection_fraction or
            fit.to_dict()[fit.volume_surface + "_volume_fraction"])
print(f"{fit.volume_surface} volume fraction {fraction['ratio']:.3f}")

# %%
tau = fit.function_names.index("tau")
a3 = fit.function_names.index("a3")
twist_deg = np.degrees(fit.functions[:, :, tau])  # (frames, knots)
a3_mm = fit.functions[:, :, a3]
table = fit.to_dataframe()
ecc = table[(table.quantity == "ecc_percent") &
            table.segment.str.startswith("mid", na=False)]
vertices, faces = fit[-1].surface()
print(f"last frame's surface: {len(vertices)} vertices, {len(faces)} "
      f"triangles (pyvista.PolyData or trimesh.Trimesh take them)")

# %%
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    plt = None
    print("matplotlib not installed: twist (deg) per knot, last frame:",
          np.array2string(twist_deg[-1], precision=2))

if plt is not None:
    figure, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    knots = np.arange(twist_deg.shape[1])
    for t in range(len(fit)):
        left.plot(knots, twist_deg[t], label=f"frame {t}")
        right.plot(knots, a3_mm[t] / a3_mm[0], label=f"frame {t}")
    left.set(xlabel="knot (apex to base)", ylabel="twist tau (deg)")
    right.set(xlabel="knot (apex to base)", ylabel="a3 / a3 at frame 0")
    left.legend()
    figure.tight_layout()
    figure.savefig(out / "functions.png", dpi=120)

    figure, axes = plt.subplots(figsize=(6, 4))
    for segment, rows in ecc.groupby("segment"):
        axes.plot(rows.frame, rows.value, marker="o", label=segment)
    axes.set(xlabel="frame", ylabel="Ecc (%)", title="mid segments")
    axes.legend(fontsize="small")
    figure.tight_layout()
    figure.savefig(out / "strain.png", dpi=120)

    figure = plt.figure(figsize=(6, 6))
    axes = figure.add_subplot(projection="3d")
    axes.plot_trisurf(*vertices.T, triangles=faces, alpha=0.4)
    axes.scatter(*fit[-1].points.T, s=1, color="k")
    axes.set_box_aspect(np.ptp(vertices, axis=0))
    figure.savefig(out / "surface.png", dpi=120)
    print(f"wrote {out}/fit, {out}/functions.png, {out}/strain.png and "
          f"{out}/surface.png")
else:
    print(f"wrote {out}/fit")
