#!/usr/bin/python3
"""Prints the README's real-data table from the fits the examples write.

    for e in biv_me_guidepoints biv_me_meshes cap_mean_shape ukdhp_ed_mesh; do
      bash examples/$e.sh; done
    /usr/bin/python3 scripts/real_data_table.py

Each row: the example, its frames and points, the RMS over its frames, the
cavity volumes and ejection fraction the fit reads, the reference the data
come with (the same patient's own meshes or the surfaces' own volumes, from
docs/real_data.md), and the frames' verdicts.
"""
import json
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
OUT = ROOT / "out" / "examples"

# example script, its fit.json under out/examples, what the data's own
# surfaces measure (docs/real_data.md).
CASES = [
    ("biv_me_guidepoints.sh", "biv-me-guidepoints/fit.json",
     "biv-me's meshes: 174.5 / 72.0 ml, EF 0.59"),
    ("biv_me_meshes.sh", "biv-me-meshes/fit/fit.json",
     "the meshes: EF 0.59"),
    ("cap_mean_shape.sh", "cap-mean/fit/fit.json",
     "the surfaces: 128.0 / 49.5 ml, EF 0.61"),
    ("ukdhp_ed_mesh.sh", "ukdhp-ed/fit/fit.json",
     "the mesh's label 1: 151 ml"),
]


def row(script, path, reference):
    fit = json.loads((OUT / path).read_text())
    frames = fit["frames"]
    rms = [f["rms_mm"] for f in frames]
    points = [f["n_points"] for f in frames]
    ef = fit.get("ejection_fraction") or {}
    volumes = [f.get("cavity_volume_ml") for f in frames]
    if ef and len(frames) > 1:
        fitted = (f"{ef['edv_ml']:.1f} / {ef['esv_ml']:.1f} ml, "
                  f"EF {ef['ratio']:.2f}")
    else:
        fitted = f"{volumes[0]:.1f} ml (one frame)"
    quality = fit["quality"]
    verdicts = (f"{quality['frames_ok']} ok, {quality['frames_warning']} "
                f"warning, {quality['frames_failed']} failed")
    spread = (f"{min(points)}-{max(points)}" if min(points) != max(points)
              else f"{points[0]}")
    rms_range = (f"{min(rms):.2f}-{max(rms):.2f}" if len(rms) > 1
                 else f"{rms[0]:.2f}")
    return (f"| `examples/{script}` | {len(frames)} x {spread} | "
            f"{rms_range} | {fitted} | {reference} | "
            f"{verdicts} |")


def main():
    print("| example | frames x points | RMS (mm) | fit: EDV / ESV, EF | "
          "reference | verdicts |")
    print("| --- | --- | --- | --- | --- | --- |")
    for case in CASES:
        if not (OUT / case[1]).exists():
            sys.exit(f"{OUT / case[1]} is absent: run examples/{case[0]}")
        print(row(*case))


if __name__ == "__main__":
    main()
