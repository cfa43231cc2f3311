#!/usr/bin/python3
"""How far pfdm's numbers move when biv-me guide points move by a hair.

Usage: scripts/perturbation_sensitivity.py PFDM GPFILE_FOLDER [CONTOURS]
[EPSILON_MM]

Copies the guide-point folder, moves every point's x by -+EPSILON_MM
(alternately; default 1e-5), fits both folders with `pfdm fit --contours
CONTOURS --threads 1`, with the local field on (the default) and off, and
prints per frame the correspondence rounds and the largest change of a
segment's Ecc and of the cavity volume, then the medians and maxima.  A
method whose numbers are continuous in the data moves them by about
EPSILON_MM times a modest factor; docs/performance.md reads the output.
"""
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile


def perturb(folder, out, epsilon):
    shutil.copytree(folder, out)
    for name in os.listdir(out):
        if not name.startswith("GPFile_"):
            continue
        path = os.path.join(out, name)
        with open(path) as f:
            lines = f.read().split("\n")
        for i in range(1, len(lines)):
            parts = lines[i].split("\t")
            try:
                x = float(parts[0])
            except ValueError:
                continue
            parts[0] = "%.6f" % (x + (epsilon if i % 2 else -epsilon))
            lines[i] = "\t".join(parts)
        with open(path, "w") as f:
            f.write("\n".join(lines))


def fit(pfdm, folder, contours, local, out):
    subprocess.run([pfdm, "fit", "--points", folder, "--contours", contours,
                    "--local", local, "--threads", "1", "--out", out],
                   check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)
    with open(os.path.join(out, "fit.json")) as f:
        return json.load(f)


def changes(a, b):
    rows = []
    for t, (fa, fb) in enumerate(zip(a["frames"], b["frames"])):
        ecc = [abs(ra["ecc_percent"][t] - rb["ecc_percent"][t])
               for ra, rb in zip(a["regions"], b["regions"])
               if ra["ecc_percent"][t] is not None
               and rb["ecc_percent"][t] is not None]
        rows.append((t, fa["correspondence_rounds"], fb["correspondence_rounds"],
                     max(ecc, default=0.0),
                     abs(fa["cavity_volume_ml"] - fb["cavity_volume_ml"])))
    return rows


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    pfdm, folder = sys.argv[1], sys.argv[2]
    contours = sys.argv[3] if len(sys.argv) > 3 else "lv-cavity"
    epsilon = float(sys.argv[4]) if len(sys.argv) > 4 else 1e-5
    with tempfile.TemporaryDirectory() as work:
        moved = os.path.join(work, "moved")
        perturb(folder, moved, epsilon)
        for local in ("on", "off"):
            a = fit(pfdm, folder, contours, local, os.path.join(work, "a"))
            b = fit(pfdm, moved, contours, local, os.path.join(work, "b"))
            rows = changes(a, b)
            print("--local %s, points moved by -+%g mm:" % (local, epsilon))
            print("frame  rounds  rounds moved  max segment dEcc  dV ml")
            for t, ra, rb, ecc, volume in rows:
                print("%5d  %6d  %12d  %16.3f  %5.3f" % (t, ra, rb, ecc,
                                                        volume))
            print("median dEcc %.3f, largest %.3f; largest dV %.3f ml\n" % (
                statistics.median(r[3] for r in rows),
                max(r[3] for r in rows), max(r[4] for r in rows)))


if __name__ == "__main__":
    main()
