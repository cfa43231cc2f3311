#!/usr/bin/python3
"""The full calibration of the frames' covariance (issue 30), as a table.

Runs LvUncertaintyCalibrationTest.* (src/pfdm/testing/
lv_uncertainty_calibration_test.cc) with more seeds and points than CI does
(PFDM_CALIBRATION_SEEDS, PFDM_CALIBRATION_SCALE), reads the lines it prints
and writes the table between the markers in docs/uncertainty.md, with the
machine's load while it ran.

    scripts/uncertainty_calibration.py [--build build] [--seeds 400]
        [--scale 2] [--doc docs/uncertainty.md] [--filter '*']
        [--from OUTPUT ...]   # tables from saved test outputs, no run
"""
import argparse
import collections
import os
import re
import subprocess
import sys
import time

BEGIN = "<!-- calibration table: scripts/uncertainty_calibration.py -->"
END = "<!-- end of calibration table -->"
LINE = re.compile(
    r"calibration (\S+) frame (\d) (\S+) knot (\d+) coverage ([\d.]+) "
    r"sd ([\d.eE+-]+) -> ([\d.eE+-]+) ratio ([\d.naif]+)")
POOLED = re.compile(r"calibration (\S+) pooled ([\d.]+) seeds (\d+) "
                    r"points (\d+)")


def run(build, seeds, scale, test_filter):
    env = dict(os.environ, PFDM_CALIBRATION_SEEDS=str(seeds),
               PFDM_CALIBRATION_SCALE=str(scale))
    load_before = os.getloadavg()[0]
    start = time.time()
    result = subprocess.run(
        [os.path.join(build, "pfdm_tests"),
         "--gtest_filter=LvUncertaintyCalibrationTest." + test_filter],
        env=env, capture_output=True, text=True)
    seconds = time.time() - start
    load_after = os.getloadavg()[0]
    return result, seconds, (load_before, load_after)


def table(output):
    rows = collections.OrderedDict()
    pooled = {}
    for line in output.splitlines():
        m = LINE.search(line)
        if m:
            case, frame, function, knot = m.group(1, 2, 3, 4)
            rows.setdefault(case, []).append(
                (int(frame), function, int(knot), float(m.group(5)),
                 float(m.group(6)), float(m.group(8))))
        m = POOLED.search(line)
        if m:
            pooled[m.group(1)] = (float(m.group(2)), int(m.group(3)),
                                  int(m.group(4)))
    lines = ["| case | points N | seeds | pooled coverage | coverage per "
             "function (frame: min-max over knots) | sd(4N)/sd(N) |",
             "| --- | --- | --- | --- | --- | --- |"]
    for case, values in rows.items():
        by_function = collections.OrderedDict()
        for frame, function, _, coverage, _, ratio in values:
            by_function.setdefault((frame, function), []).append(
                (coverage, ratio))
        cells = []
        ratios = []
        for (frame, function), items in by_function.items():
            c = [x[0] for x in items]
            ratios += [x[1] for x in items]
            cells.append("%s f%d %.2f-%.2f" % (function, frame, min(c), max(c)))
        p, seeds, points = pooled.get(case, (float("nan"), 0, 0))
        lines.append("| %s | %d | %d | %.3f | %s | %.3f-%.3f |" % (
            case, points, seeds, p, ", ".join(cells), min(ratios),
            max(ratios)))
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--build", default="build")
    parser.add_argument("--seeds", type=int, default=400)
    parser.add_argument("--scale", type=int, default=1)
    parser.add_argument("--doc", default="docs/uncertainty.md")
    parser.add_argument("--filter", default="*")
    parser.add_argument("--from", dest="saved", nargs="*")
    parser.add_argument("--note", default="")
    args = parser.parse_args()
    if args.saved:
        output = "".join(open(f).read() for f in args.saved)
        text = table(output)
        note = args.note or "From saved outputs."
        code = 0
    else:
        result, seconds, load = run(args.build, args.seeds, args.scale,
                                    args.filter)
        sys.stdout.write(result.stdout)
        text = table(result.stdout)
        code = result.returncode
        note = ("%d seeds, points x%d, %.0f s on %d cores, load average %.1f "
                "before and %.1f after (the machine shared); gtest exit %d, "
                "%s." % (args.seeds, args.scale, seconds, os.cpu_count(),
                         load[0], load[1], code,
                         time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())))
    block = "%s\n%s\n\n%s\n%s" % (BEGIN, text, note, END)
    with open(args.doc) as f:
        doc = f.read()
    if BEGIN in doc and END in doc:
        doc = doc[:doc.index(BEGIN)] + block + doc[doc.index(END) + len(END):]
    else:
        doc += "\n" + block + "\n"
    with open(args.doc, "w") as f:
        f.write(doc)
    print(text)
    print(note)
    return code


if __name__ == "__main__":
    sys.exit(main())
