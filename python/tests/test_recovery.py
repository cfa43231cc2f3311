"""Recovery on the phantom through the Python API equals the CLI's numbers."""
import csv
import json
import math

import numpy as np
import pfdm
from conftest import run_cli, scratch

# Timing differs run to run; nothing else may.
TIMING = ("solve_seconds",)


def without_timing(document):
    document.pop("timing")
    for frame in document["frames"]:
        for key in TIMING:
            frame.pop(key)
    return document


def test_fit_from_a_path_gives_the_cli_fit_json_to_the_last_digit(cli_phantom):
    _, points_csv, cli_json = cli_phantom
    fit = pfdm.fit(str(points_csv))
    ours = fit.to_dict()
    assert without_timing(ours) == without_timing(cli_json)
    # The per-frame dicts are the same entries, pose and clinical included.
    for frame, entry in zip(fit.frames, cli_json["frames"]):
        assert frame.stats["rms_mm"] == entry["rms_mm"]
        assert frame.stats["n_points"] == 600
        assert frame.pose == entry["pose"]
        clinical = dict(entry["clinical"],
                        midwall_volume_ml=entry["midwall_volume_ml"])
        assert frame.clinical == clinical
    # Tags on one surface: its volume fraction, not an ejection fraction.
    assert fit.volume_surface == "midwall"
    assert fit.ejection_fraction is None
    assert fit.to_dict()["midwall_volume_fraction"] == (
        cli_json["midwall_volume_fraction"])
    assert fit.regions == cli_json["regions"]
    assert len(fit.regions) == 17


def test_written_outputs_equal_the_clis_byte_for_byte(cli_phantom):
    folder, points_csv, _ = cli_phantom
    out = scratch("written_outputs")
    pfdm.fit(points_csv).write(out / "py")  # A pathlib.Path works too.
    cli_files = sorted(p.name for p in (folder / "cli").iterdir())
    assert sorted(p.name for p in (out / "py").iterdir()) == cli_files
    assert "fit.json" in cli_files and "frame_002.vtp" in cli_files
    for name in cli_files:
        cli_bytes = (folder / "cli" / name).read_bytes()
        py_bytes = (out / "py" / name).read_bytes()
        if name == "report.html":  # Its footer: what made it and when.
            keep = lambda text: [line for line in text.splitlines()
                                 if not line.startswith("<footer")]
            assert keep(py_bytes.decode()) == keep(cli_bytes.decode())
            assert "Made by pfdm " in py_bytes.decode()
        elif name == "fit.json":
            keep = lambda text: [line for line in text.splitlines()
                                 if "_seconds\"" not in line]
            assert keep(py_bytes.decode()) == keep(cli_bytes.decode())
        else:
            assert py_bytes == cli_bytes, name


def test_functions_array_is_parameters_csv(cli_phantom):
    folder, points_csv, _ = cli_phantom
    fit = pfdm.fit(points_csv)
    names = list(pfdm.FUNCTION_NAMES)
    assert fit.function_names == names and len(names) == 18
    assert names[-4:] == ["h", "dtau", "shift", "squeeze"]
    assert fit.function_units[names.index("tau")] == "rad"
    assert fit.function_units[names.index("a3")] == "mm"
    assert fit.function_units[names.index("eps1")] == "1"
    functions = fit.functions
    assert functions.shape == (3, 17, 18)  # frames, knots, functions
    rows = 0
    with open(folder / "cli" / "parameters.csv") as f:
        for row in csv.DictReader(f):
            t, k = int(row["frame"]), int(row["knot"])
            f_index = names.index(row["function"])
            # The CSV's 10 significant digits, as C++ streams print them.
            assert "%.10g" % functions[t, k, f_index] == row["value"]
            assert "%.10g" % fit.knot_u[k] == row["u"]
            rows += 1
    assert rows == 3 * 17 * 18
    np.testing.assert_array_equal(fit.frames[2].functions, functions[2])
    np.testing.assert_array_equal(fit.frames[2].model.function("tau"),
                                  functions[2, :, names.index("tau")])


def test_fit_from_arrays_equals_fit_from_the_file(cli_phantom):
    _, points_csv, _ = cli_phantom
    from_file = pfdm.fit(points_csv)
    positions, ids = pfdm.read_points(points_csv).to_arrays()
    from_arrays = pfdm.fit(pfdm.PointSequence(positions, ids))
    np.testing.assert_array_equal(from_arrays.functions, from_file.functions)
    for a, b in zip(from_arrays.frames, from_file.frames):
        np.testing.assert_array_equal(a.material, b.material)
        np.testing.assert_array_equal(a.residuals, b.residuals)
        assert a.clinical == b.clinical
    assert from_arrays.settings["points"] == "arrays"


def test_simulate_gives_the_clis_phantom_and_its_truth_is_recovered(cli_phantom):
    _, points_csv, _ = cli_phantom
    points, truth = pfdm.simulate(frames=3, tags=600)
    from_csv = pfdm.read_points(points_csv)
    for t in range(3):
        np.testing.assert_array_equal(points.positions(t), from_csv.positions(t))
        np.testing.assert_array_equal(points.ids(t), from_csv.ids(t))
    assert len(truth) == 3
    fit = pfdm.fit(points)
    names = list(pfdm.FUNCTION_NAMES)
    tau, a1 = names.index("tau"), names.index("a1")
    # The apex pole knot (cos u = 0) is the regularizer's, not the data's.
    for t in range(3):
        fitted, true = fit.frames[t].functions, truth[t].functions
        np.testing.assert_allclose(np.degrees(fitted[1:, tau]),
                                   np.degrees(true[1:, tau]), atol=1.0)
        np.testing.assert_allclose(fitted[1:, a1], true[1:, a1], rtol=0.03)
    # Net twist is measured between the material rings at 0.2 and 0.85 of
    # the length (knots are uniform in that fraction on frame 0).
    net_twist = fit.frames[2].clinical["net_twist_deg"]
    true_tau = truth[2].function("tau")
    fraction = np.linspace(0.0, 1.0, len(true_tau))
    true_twist = math.degrees(np.interp(0.85, fraction, true_tau)
                              - np.interp(0.2, fraction, true_tau))
    assert abs(net_twist - true_twist) < 1.0
    assert fit.frames[0].stats["rms_mm"] < 0.6


def test_a_robust_loss_records_its_scale_and_weighs_each_point(cli_phantom):
    folder, points_csv, _ = cli_phantom
    fit = pfdm.fit(points_csv, loss="huber", local=False)
    assert fit.settings["loss_scale"] == "auto"
    scales = fit.settings["loss_scale_mm"]
    assert len(scales) == 3 and all(0.1 < s < 5.0 for s in scales)
    code, _, err = run_cli("fit", "--points", points_csv, "--loss", "huber",
                           "--local", "off", "--out", folder / "huber")
    assert code == 0, err
    with open(folder / "huber" / "fit.json") as f:
        assert json.load(f)["settings"]["loss_scale_mm"] == scales
    for frame in fit.frames:
        weights = frame.loss_weights
        assert weights.shape == (len(frame.residuals),)
        # huber: 1 within the scale, scale / |r| beyond.
        distances = np.linalg.norm(frame.residuals, axis=1)
        scale = scales[frame.frame]
        np.testing.assert_allclose(
            weights, np.minimum(1.0, scale / np.maximum(distances, 1e-300)),
            rtol=1e-12)
    fixed = pfdm.fit(points_csv, loss="cauchy", loss_scale=2.5, local=False)
    assert fixed.settings["loss_scale"] == 2.5
    assert fixed.settings["loss_scale_mm"] == 2.5
    plain = pfdm.fit(points_csv, local=False)
    assert "loss_scale" not in plain.settings
    assert (plain.frames[1].loss_weights == 1.0).all()
