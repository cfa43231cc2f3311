"""Fit.intervals: every derived number's value, sd, bias and 95 % interval."""
import json

import numpy as np
import pfdm


def test_intervals_are_arrays_beside_the_values_and_fit_json():
    points, _ = pfdm.simulate(frames=2, tags=300, seed=5)
    off = pfdm.fit(points, knots=7)
    assert off.intervals is None
    assert "_ci95" not in off.to_json()
    fit = pfdm.fit(points, knots=7, uncertainty="on")
    got = fit.intervals
    gcs = got["frames"]["gcs_percent"]
    assert gcs["value"].shape == (2,) and gcs["ci95"].shape == (2, 2)
    # ED against itself: no strain, no spread; ES spreads.
    assert gcs["sd"][0] < 1e-9 and gcs["sd"][1] > 0.01
    # Centred on the value minus the local field's noise bias.
    assert gcs["bias"].shape == (2,) and abs(gcs["bias"][0]) < 1e-9
    np.testing.assert_allclose(gcs["ci95"][:, 1] - gcs["value"] + gcs["bias"],
                               1.959963984540054 * gcs["sd"], atol=1e-12)
    np.testing.assert_allclose(gcs["ci95"].mean(axis=1),
                               gcs["value"] - gcs["bias"], atol=1e-12)
    ecc = got["segments"]["ecc_percent"]
    assert ecc["value"].shape == (2, 17) and ecc["ci95"].shape == (2, 17, 2)
    # The same numbers as fit.json's.
    document = json.loads(fit.to_json())
    np.testing.assert_allclose(document["frames"][1]["clinical"]["gcs_percent_ci95"],
                               gcs["ci95"][1])
    np.testing.assert_allclose(document["regions"][4]["ecc_percent_ci95"][1],
                               ecc["ci95"][1, 4])
    ef = got["ejection_fraction"]
    assert ef["value"].shape == (3,) and np.all(ef["sd"][1:] > 0.0)
    # Which intervals are calibrated on this kind of data, as fit.json says.
    assert got["data"] == "midwall tags"
    assert got["calibrated"] == document["uncertainty_calibrated"]["keys"]
    assert "gls_percent" in got["calibrated"]
    assert "gcs_percent" not in got["calibrated"]  # 85 % with a lesion
    assert "esv_ml" in got["calibrated"]  # 95 % of 300 draws
    # Each frame says how its covariance was scaled, as fit.json does.
    assert off.frames[1].uncertainty is None
    scaled = fit.frames[1].uncertainty
    assert scaled == document["frames"][1]["uncertainty"]
    assert 0.0 < scaled["sigma_mm"] < 1.0  # the simulation's 0.5 mm noise
    assert scaled["noise_sigma_mm"] == scaled["sigma_mm"]  # one surface
    assert "normal_sigma_mm" not in scaled


def test_one_walls_contours_name_their_kind_and_its_calibrated_numbers():
    points, _ = pfdm.simulate(phantom="lv", frames=2, tags=300, seed=5,
                              wall_tags="epi", sampling="sax-slices")
    got = pfdm.fit(points, knots=7, uncertainty="on").intervals
    assert got["data"] == "epicardial contours"
    assert "gcs_percent" in got["calibrated"]
    assert "edv_ml" in got["calibrated"]  # 95 % of draws (88 before the
    # length's derivative was the top's rise)
    assert "lv_mass_g" not in got["calibrated"]  # one wall: no mass


def test_knot_sds_are_an_array_beside_the_functions_as_parameters_csv(tmp_path):
    points, _ = pfdm.simulate(frames=2, tags=300, seed=5)
    assert pfdm.fit(points, knots=7).function_sds is None
    fit = pfdm.fit(points, knots=7, uncertainty="on")
    sds = fit.function_sds
    assert sds.shape == fit.functions.shape == (2, 7, 18)
    names = list(fit.function_names)
    # Held by the gauge: no spread. Frame 0's a3 is held too, but the
    # highest points' noise sets its length, so it has one.
    assert np.all(sds[:, :, names.index("a0")] == 0.0)
    assert np.all(sds[0, 1:, names.index("a3")] > 0.0)
    assert np.all(sds[:, 1:-1, names.index("a1")] > 0.0)
    fit.write(tmp_path)
    rows = np.genfromtxt(tmp_path / "parameters.csv", delimiter=",",
                         names=True, dtype=None, encoding="utf-8")
    for row in rows:
        f = names.index(row["function"])
        assert abs(sds[row["frame"], row["knot"], f] - row["sd"]) <= \
            1e-9 * max(1.0, abs(row["sd"]))
