#!/usr/bin/python3
"""Runs pfdm's benchmarks and rewrites the tables in docs/.

    /usr/bin/python3 scripts/performance_tables.py            # run, rewrite
    /usr/bin/python3 scripts/performance_tables.py --no-run   # rewrite only

Each benchmark writes Google Benchmark JSON (--benchmark_format=json) into
--results (default build/benchmark_results/); `pfdm batch` is timed on a
manifest of phantom cases and its numbers saved in the same folder as
batch.json.  The text of docs/performance.md (docs/solvers.md for the
solvers' table) between the markers
<!-- performance-tables:NAME:begin --> and <!-- ...:end --> is then replaced
by tables made from those files, with the machine, date and load average
each run recorded, so the tables never drift from the code.  Timings on a
loaded machine are inflated and noisy: run this on a quiet one.
Standard library only.
"""

import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BENCHMARKS = ["fit_benchmark", "cost_function_benchmark", "solvers_benchmark",
              "job_benchmark", "local_benchmark", "wall_benchmark",
              "uncertainty_benchmark"]
LINEAR_SOLVERS = {0: "DENSE_NORMAL_CHOLESKY", 1: "DENSE_QR",
                  2: "SPARSE_NORMAL_CHOLESKY", 3: "DENSE_SCHUR"}
DEFAULT_LINEAR_SOLVER = 3  # SolverOptions' (solvers/solver.h).
SPARSE_LIBRARIES = {0: "SuiteSparse", 1: "CXSparse", 2: "Eigen"}
SOLVERS = {0: "direct", 1: "damped (dt = 1,000)",
           2: "integrator (euler, jacobi)", 3: "integrator (euler, model)",
           4: "integrator (rkc, model)"}
BATCH_CASES = 6
BATCH_TAGS = 2000
# As benchmarks/thread_cpu.h's kIdleOthersCores.
IDLE_OTHERS_CORES = 0.1


def run_benchmarks(build, results, names):
    os.makedirs(results, exist_ok=True)
    for name in names:
        out = os.path.join(results, name + ".json")
        print("running", name, "...", file=sys.stderr, flush=True)
        subprocess.run([os.path.join(build, name), "--benchmark_format=json",
                        "--benchmark_out=" + out,
                        "--benchmark_out_format=json"],
                       check=True, stdout=subprocess.DEVNULL)


def run_batch(build, results):
    """Times `pfdm batch --jobs 2` on phantom cases; writes batch.json."""
    pfdm = os.path.join(build, "pfdm")
    with tempfile.TemporaryDirectory(prefix="pfdm_batch_bench_") as tmp:
        rows = ["case,points"]
        for i in range(BATCH_CASES):
            points = os.path.join(tmp, "case%d.csv" % i)
            subprocess.run([pfdm, "simulate", "--frames", "5", "--tags",
                            str(BATCH_TAGS), "--seed", str(i + 1), "--out",
                            points], check=True, stdout=subprocess.DEVNULL)
            rows.append("case%d,%s" % (i, points))
        manifest = os.path.join(tmp, "manifest.csv")
        with open(manifest, "w") as f:
            f.write("\n".join(rows) + "\n")
        record = {"context": context(), "cases": BATCH_CASES,
                  "tags": BATCH_TAGS, "frames": 5, "runs": []}
        for jobs in (1, 2):
            start = time.monotonic()
            subprocess.run([pfdm, "batch", "--manifest", manifest, "--jobs",
                            str(jobs), "--out", os.path.join(tmp, "out%d" %
                                                             jobs)],
                           check=True, stdout=subprocess.DEVNULL)
            seconds = time.monotonic() - start
            record["runs"].append({"jobs": jobs, "seconds": seconds,
                                   "cases_per_minute":
                                       60.0 * BATCH_CASES / seconds})
    with open(os.path.join(results, "batch.json"), "w") as f:
        json.dump(record, f, indent=2)


def context():
    return {"date": time.strftime("%Y-%m-%dT%H:%M:%S+00:00", time.gmtime()),
            "host_name": os.uname().nodename, "num_cpus": os.cpu_count(),
            "load_avg": list(os.getloadavg())}


def load(results, name):
    path = os.path.join(results, name + ".json")
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return json.load(f)


def medians(document):
    """{run name without the repetition suffix: median row}."""
    rows = {}
    for b in document["benchmarks"]:
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") != \
                "median":
            continue
        key = re.sub(r"/(iterations|repeats|real_time).*$", "", b["run_name"])
        rows[key] = b
    return rows


def args(key):
    """'BM_X/points:10/threads:1' -> {'points': 10, 'threads': 1}."""
    out = {}
    for part in key.split("/")[1:]:
        if ":" in part:
            name, value = part.split(":", 1)
            out[name] = int(value)
        elif part.isdigit():
            out.setdefault("arg", int(part))
    return out


def number(x, digits=2):
    if x >= 1000:
        return "{:,.0f}".format(x)
    if x >= 100:
        return "%.0f" % x
    if x >= 10:
        return "%.1f" % x
    return ("%." + str(digits) + "f") % x


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |",
             "| " + " | ".join("---" for _ in header) + " |"]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    return "\n".join(lines)


def describe(document, what):
    c = document["context"]
    load_avg = ", ".join("%.1f" % x for x in c.get("load_avg", []))
    return ("`%s`: %s, host `%s`, %s CPUs, load average %s at its start" %
            (what, c["date"][:16].replace("T", " ") + " UTC",
             c.get("host_name", "?"), c.get("num_cpus", "?"), load_avg))


def means(document):
    """{run name: mean row}, for counters where any repetition counts."""
    return {re.sub(r"/(iterations|repeats|real_time).*$", "", b["run_name"]): b
            for b in document["benchmarks"]
            if b.get("aggregate_name") == "mean"}


def speedup_table(document, prefix, time_counter):
    """Two threads against one, per configuration of the benchmarks named
    prefix*: each run's busiest two threads' CPU (a share of a core) and
    the cores' worth of CPU other processes used meanwhile (thread_cpu.h,
    from /proc/stat less the benchmark's own CPU, the mean over the
    repetitions).  The speed-up is only given when both runs had the
    machine to themselves (others under IDLE_OTHERS_CORES): with the
    second core busy, two threads' time says nothing about threads."""
    found = medians(document)
    mean = means(document)
    pairs = {}
    for key, b in found.items():
        if not key.startswith(prefix) or "thread1_cpu_share" not in b:
            continue
        a = args(key)
        if "threads" not in a:
            continue
        rest = re.sub(r"/threads:\d+", "", key)
        pairs.setdefault(rest, {})[a["threads"]] = (b, mean.get(key, b))
    rows = []
    for rest, runs in sorted(pairs.items()):
        if 1 not in runs or 2 not in runs:
            continue
        (one, one_mean), (two, two_mean) = runs[1], runs[2]
        busy = max(one_mean["others_cores"], two_mean["others_cores"])
        verdict = ("%.2fx" % (one[time_counter] / two[time_counter])
                   if busy < IDLE_OTHERS_CORES else
                   "not shown: other processes used %.2f cores" % busy)
        rows.append([re.sub(r"^BM_\w+/", "", rest) or "-",
                     number(one[time_counter]), number(two[time_counter]),
                     "%.2f, %.2f" % (two["thread1_cpu_share"],
                                     two["thread2_cpu_share"]),
                     "%.2f, %.2f" % (one_mean["others_cores"],
                                     two_mean["others_cores"]),
                     verdict])
    if not rows:
        return ""
    return ("\n\nTwo threads against one: the CPU the 2-thread run's "
            "busiest thread got and what its other threads got together, "
            "exited ones included (1 = a whole core), the cores' worth other "
            "processes used during each run (from /proc/stat less the "
            "benchmark's own CPU), and the speed-up only where both runs "
            "had other processes under %.1f core:\n\n" % IDLE_OTHERS_CORES +
            table(["configuration", "1 thread ms", "2 threads ms",
                   "2-thread run: CPU of its threads",
                   "others' cores (1 thread, 2 threads)", "speed-up"], rows))


def fit_table(document):
    rows = []
    for key, b in medians(document).items():
        if not key.startswith("BM_FitFrame"):
            continue
        a = args(key)
        rows.append((a["points"], a["autodiff"],
                     a["solver"] != DEFAULT_LINEAR_SOLVER,
                     a["sparse"] != 2, a["solver"], a["threads"], [
            "{:,}".format(a["points"]), str(a["threads"]),
            LINEAR_SOLVERS.get(a["solver"], str(a["solver"])),
            SPARSE_LIBRARIES[a["sparse"]] if a["solver"] == 2 else "-",
            "autodiff" if a["autodiff"] else "analytic",
            number(b["ms_per_iter"]), number(b["evaluation_ms_per_iter"]),
            number(b["linear_ms_per_iter"]), number(b["frame_ms"], 1),
            number(b["x_floor"], 1), "%d" % b["iterations"]]))
    rows.sort(key=lambda r: r[:6])
    return table(["points", "threads", "linear solver", "sparse library",
                  "Jacobian", "ms/iter", "evaluation ms/iter",
                  "linear ms/iter", "frame ms", "x floor", "iterations"],
                 [r[-1] for r in rows]) + \
        speedup_table(document, "BM_FitFrame", "frame_ms")


def cost_table(document):
    names = {"BM_Analytic/0": "one point, residual only",
             "BM_Analytic/1": "one point, analytic Jacobian",
             "BM_Autodiff/0": "one point, residual only (autodiff functor)",
             "BM_Autodiff/1": "one point, autodiff Jacobian",
             "BM_PointGroup/0": "1,024-point group, residual only",
             "BM_PointGroup/1": "1,024-point group, knots varied",
             "BM_PointGroup/2": "1,024-point group, knots and pose varied"}
    rows = []
    for key, b in medians(document).items():
        if key in names:
            # Counters with kInvert come out in seconds per point.
            rows.append([names[key], number(1e9 * b["ns_per_point"], 1)])
    return table(["cost function", "ns per point"], rows)


def job_table(document, batch):
    rows = []
    closest = []
    for key, b in medians(document).items():
        a = args(key)
        if key.startswith("BM_ClosestMaterialPoints"):
            closest.append([
                ("exhaustive" if a["exhaustive"] else "early stop") +
                (", Jet derivatives" if a.get("jet") else ""),
                str(a["threads"]), number(b["real_time"]),
                number(1e6 * b["us_per_point"], 2),
                number(b.get("evaluations_per_point", float("nan")), 2)])
            continue
        biv_me = ["biv-me patient 1, LV endo contours, 25 frames",
                  "biv-me patient 1, lv-cavity (`pfdm fit`'s axis), "
                  "25 frames",
                  "biv-me patient 1, lv-cavity,lv-epi (`pfdm fit`'s axis), "
                  "25 frames"]
        case = ("phantom, {:,} tags x 5 frames".format(a["tags"])
                if key.startswith(("BM_PhantomJob", "BM_OutputsJob")) else
                biv_me[a.get("contours", 0)])
        if key.startswith("BM_OutputsJob"):
            case += (", outputs as before (.vtk and .vtp, doubles)"
                     if a["outputs"] else ", default outputs (.vtp, float32)")
        rows.append([case, str(a.get("threads", a.get("arg", 1))),
                     number(b["job_ms"]), number(b["read_ms"]),
                     number(b.get("start_ms", float("nan"))),
                     number(b.get("checks_ms", float("nan"))),
                     "%s (%s)" % (number(b["frame0_ms"]),
                                  number(b["frame0_correspondence_ms"])),
                     "%s (%s)" % (number(b["tracked_ms"]),
                                  number(b["tracked_minimizer_ms"])),
                     number(b.get("analysis_ms", float("nan"))),
                     number(b["outputs_ms"]),
                     "%.1f" % b["frame0_x_tracked"],
                     "%.0f %%" % (100 * b["outputs_share"]),
                     "%.0f %%" % (100 * b.get("outputs_cpu_share",
                                               float("nan"))),
                     "%.0f %%" % (100 * (b["outputs_ms"] +
                                         b.get("analysis_ms", 0.0)) /
                                  b["job_ms"])])
    text = table(["case", "threads", "job ms", "read ms",
                  "start ms", "checks ms",
                  "frame 0 ms (closest points)",
                  "later frame ms (minimizer)", "analysis ms", "outputs ms",
                  "frame 0 / later frame", "outputs share",
                  "outputs share of CPU time",
                  "analysis and outputs share"], rows)
    text += speedup_table(document, "BM_PhantomJob", "job_ms")
    if closest:
        text += ("\n\nFrame 0's first closest-point search alone (20,000 "
                 "tags against the initialized model):\n\n")
        text += table(["search", "threads", "ms", "CPU us per point",
                       "surface evaluations per point"], closest)
    if batch:
        text += "\n\n`pfdm batch` on %d phantom cases of {:,} tags x 5 " \
                "frames (%s):\n\n".format(batch["tags"]) % (
                    batch["cases"], describe(batch, "batch"))
        text += table(["--jobs", "seconds", "cases per minute"],
                      [[str(r["jobs"]), "%.1f" % r["seconds"],
                        "%.1f" % r["cases_per_minute"]]
                       for r in batch["runs"]])
    return text


def solvers_table(document):
    rows = []
    for key, b in medians(document).items():
        a = args(key)
        rows.append((a["points"], a["solver"], [
            "{:,}".format(a["points"]), SOLVERS[a["solver"]],
            "{:,}".format(int(b["iterations"])),
            # NaN: the run never reached the direct solve's RMS.
            "never" if b["jacobian_evals_to_rms"] != b["jacobian_evals_to_rms"]
            else "%s (%s)" % ("{:,}".format(int(b["jacobian_evals_to_rms"])),
                              number(b["evals_to_rms_vs_direct"])),
            number(b["time_to_rms_vs_direct"], 2),
            number(b["time_vs_direct"], 2),
            "yes" if b["at_rest"] else "no (step cap)",
            "%.4f" % b["rms_vs_direct"]]))
    rows.sort(key=lambda r: r[:2])
    return table(["points", "solver", "steps",
                  "Jacobian evals to RMS (vs direct)",
                  "time to RMS vs direct", "time to the end vs direct",
                  "at rest", "final RMS vs direct"],
                 [r[-1] for r in rows])


def local_table(document):
    rows = []
    off = {}
    for key, b in medians(document).items():
        a = args(key)
        if not a["local"]:
            off[a["points"]] = b["frame_ms"]
    for key, b in medians(document).items():
        a = args(key)
        rows.append((a["points"], a["local"], [
            "{:,}".format(a["points"]), "on" if a["local"] else "off",
            number(b["frame_ms"], 1),
            number(b["local_ms"], 1) if a["local"] else "-",
            "%d" % b["local_iterations"] if a["local"] else "-",
            number(b["frame_ms"] / off[a["points"]], 2)
            if a["points"] in off else "-",
            "%.3f" % b["rms_mm"]]))
    rows.sort(key=lambda r: r[:2])
    return table(["points", "local", "frame ms", "local field ms",
                  "local iterations", "vs global only", "RMS mm"],
                 [r[-1] for r in rows])


def wall_table(document):
    rows = []
    surface = {}
    for key, b in medians(document).items():
        a = args(key)
        if not a["solid"]:
            surface[a["points"]] = b
    for key, b in medians(document).items():
        a = args(key)
        base = surface.get(a["points"])
        rows.append((a["points"], a["solid"], [
            "{:,}".format(a["points"]),
            ["midwall", "solid, ranked", "solid, held"][a["solid"]],
            number(b["frame0_ms"], 1),
            number(b.get("first_tracked_ms", float("nan")), 1),
            number(b["frame_ms"], 1),
            number(b["frame_ms"] / base["frame_ms"], 2)
            if base and base["frame_ms"] > 0 else "-",
            "%d (%d)" % (b.get("solves", 0), b.get("iterations", 0)),
            number(b["per_point_ns"], 0),
            number(b["per_point_ns"] / base["per_point_ns"], 2)
            if base and base["per_point_ns"] > 0 else "-",
            "%.3f" % b["rms_mm"]]))
    rows.sort(key=lambda r: r[:2])
    return table(["tags", "wall", "frame 0 ms", "frame 1 ms",
                  "tracked frame (frame 2) ms",
                  "tracked frame vs one surface", "solves (steps)",
                  "evaluation ns per tag and iteration",
                  "evaluation vs one surface", "RMS mm"],
                 [r[-1] for r in rows])


def uncertainty_table(document):
    rows = []
    for key, b in medians(document).items():
        if not key.startswith("BM_Uncertainty/"):
            continue
        a = args(key)
        rows.append((a["points"], [
            "{:,}".format(a["points"]), number(b["fit_ms"], 1),
            number(b["analysis_ms"], 1), number(b["covariance_ms"], 1),
            number(b["draws_ms"], 1), number(b["numbers_ms"], 0),
            "%.0f %%" % (100.0 * b["share"])]))
    rows.sort(key=lambda r: r[0])
    return table(["tags", "fit ms per frame", "analysis ms per frame",
                  "covariance ms", "noise draws ms", "numbers' sds ms",
                  "added / (fit + analysis)"], [r[-1] for r in rows]) + \
        speedup_table(document, "BM_UncertaintyThreads", "analysis_ms")


def replace(readme, name, text):
    pattern = re.compile(r"(<!-- performance-tables:%s:begin -->\n).*?"
                         r"(<!-- performance-tables:%s:end -->)" % (name, name),
                         re.S)
    if not pattern.search(readme):
        sys.exit("no performance-tables:%s markers in its page" % name)
    return pattern.sub(lambda m: m.group(1) + text + "\n" + m.group(2),
                       readme)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--results", default=None,
                        help="JSON folder (default BUILD/benchmark_results)")
    parser.add_argument("--docs", default=os.path.join(ROOT, "docs"),
                        help="the folder of performance.md and solvers.md")
    parser.add_argument("--no-run", action="store_true",
                        help="only rewrite the tables from saved JSON")
    parser.add_argument("--only", nargs="*", default=None,
                        help="run only these benchmarks (and 'batch')")
    options = parser.parse_args()
    results = options.results or os.path.join(options.build,
                                              "benchmark_results")
    if not options.no_run:
        names = options.only if options.only is not None else \
            BENCHMARKS + ["batch"]
        run_benchmarks(options.build, results,
                       [n for n in names if n != "batch"])
        if "batch" in names:
            run_batch(options.build, results)

    # Each table's page: the solvers' beside the solvers' description.
    sections = {"fit": ("fit_benchmark", fit_table, "performance.md"),
                "cost": ("cost_function_benchmark", cost_table,
                         "performance.md"),
                "solvers": ("solvers_benchmark", solvers_table, "solvers.md"),
                "local": ("local_benchmark", local_table, "performance.md"),
                "wall": ("wall_benchmark", wall_table, "performance.md"),
                "uncertainty": ("uncertainty_benchmark", uncertainty_table,
                                "performance.md")}
    pages = {}

    def page(name):
        if name not in pages:
            with open(os.path.join(options.docs, name)) as f:
                pages[name] = f.read()
        return pages[name]

    for name, (benchmark, make, page_name) in sections.items():
        document = load(results, benchmark)
        if document:
            pages[page_name] = replace(
                page(page_name), name,
                describe(document, benchmark) + ":\n\n" + make(document))
    job = load(results, "job_benchmark")
    if job:
        pages["performance.md"] = replace(
            page("performance.md"), "job", describe(job, "job_benchmark") +
            ":\n\n" + job_table(job, load(results, "batch")))
    for name, text in pages.items():
        with open(os.path.join(options.docs, name), "w") as f:
            f.write(text)
        print("rewrote", name, "from", results, file=sys.stderr)


if __name__ == "__main__":
    main()
