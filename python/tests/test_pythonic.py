"""Issue 34: the package feels like Python: real types, slicing, a long-form
table, the LV phantom, and the README's quick start runs as written."""
import math
import re

import numpy as np
import pandas
import pfdm
import pytest
from conftest import SOURCE_DIR


@pytest.fixture(scope="module")
def lv_fit():
    points, truth = pfdm.simulate(phantom="lv", frames=3, tags=600, seed=4)
    return points, truth, pfdm.fit(points, local=False)


def test_lv_phantom_comes_with_its_truth(lv_fit):
    points, truth, fit = lv_fit
    assert len(points) == 3 and truth["phantom"] == "lv"
    assert len(truth["frames"]) == 3
    # The fit reads the phantom's shortening (17 %) within half a point
    # (17.02 measured; 17.09 and 17.22 with seeds 2 and 1).
    assert fit[-1].clinical["longitudinal_shortening_percent"] == pytest.approx(
        truth["frames"][-1]["longitudinal_shortening_percent"], abs=0.5)
    with pytest.raises(TypeError, match="lesion needs phantom='lv'"):
        pfdm.simulate(lesion=True)
    with pytest.raises(ValueError, match="phantom must be 'model' or 'lv'"):
        pfdm.simulate(phantom="cube")


def test_frames_index_slice_and_iterate(lv_fit):
    _, _, fit = lv_fit
    assert [f.frame for f in fit[0:2]] == [0, 1]
    assert [f.frame for f in fit[::-1]] == [2, 1, 0]
    assert fit[-1].frame == 2 and fit[np.int64(1)].frame == 1
    assert [f.frame for f in fit] == [0, 1, 2]
    with pytest.raises(IndexError, match="frame 3 of a fit of 3 frames"):
        fit[3]


def test_dyssynchrony_is_fit_jsons(lv_fit):
    _, _, fit = lv_fit
    d = fit.dyssynchrony
    assert d == fit.to_dict()["dyssynchrony"]
    assert d["unit"] == "frames" and len(d["time_to_peak"]) == 17
    # The index is the sample standard deviation of the measured segments'
    # times to peak, counted here a second way.
    times = [t for t in d["time_to_peak"][:16] if t is not None]
    assert len(times) == d["segments"]
    assert d["index"] == pytest.approx(np.std(times, ddof=1), abs=1e-9)


def test_to_dataframe_holds_fit_json_numbers(lv_fit):
    _, _, fit = lv_fit
    table = fit.to_dataframe()
    assert list(table.columns) == ["frame", "time_ms", "quantity", "segment",
                                   "layer", "value", "ci95_low", "ci95_high"]
    # A mid-wall fit has no wall: no row of a layer.
    assert table.layer.isna().all()
    assert table.ci95_low.isna().all()  # uncertainty off
    document = fit.to_dict()
    twist = table[(table.quantity == "net_twist_deg") & table.segment.isna()]
    assert list(twist.frame) == [0, 1, 2]
    assert list(twist.value) == [f["clinical"]["net_twist_deg"]
                                 for f in document["frames"]]
    # One row per segment, frame and segment number (16 segments here).
    ecc = table[table.quantity == "ecc_percent"]
    assert len(ecc) == 3 * len(document["regions"])
    region = document["regions"][5]
    mine = ecc[ecc.segment == region["name"]].sort_values("frame")
    assert list(mine.value) == pytest.approx(region["ecc_percent"])
    # A mid-wall fit has no cavity: none of its rows claims one.
    assert not any(table.quantity.str.startswith("cavity"))
    assert table.time_ms.isna().all()  # The phantom carries no times.


def test_keywords_take_python_types(lv_fit):
    points, _, _ = lv_fit
    fit = pfdm.fit(points, local=True, local_grid=(7, 12),
                   contours=["lv-endo", "lv-epi"], knots=9)
    assert fit.settings["local"] is True
    assert fit.settings["local_grid"] == "7x12"
    assert fit.functions.shape[1] == 9
    with pytest.raises(pfdm.InputError,
                       match=r"^knots must be between 2 and 100, got 1$"):
        pfdm.fit(points, knots=1)


def test_readme_python_quick_start_runs():
    readme = (SOURCE_DIR / "README.md").read_text()
    section = readme[readme.index("\n## Python"):]
    snippet = re.search(r"```python\n(.*?)```", section, re.S).group(1)
    namespace = {}
    exec(compile(snippet, "README.md", "exec"), namespace)
    fit = namespace["fit"]
    assert isinstance(namespace["table"], pandas.DataFrame)
    assert namespace["tau"].shape == (5, 17)
    assert fit.ejection_fraction is None and fit.volume_surface == "midwall"
    # uncertainty=True: every number with its interval around it.
    table = namespace["table"]
    twist = table[(table.quantity == "net_twist_deg") & (table.frame == 4)]
    assert len(twist) == 1
    low, value, high = twist[["ci95_low", "value", "ci95_high"]].iloc[0]
    assert low < value < high
    assert math.isfinite(fit[-1].clinical["net_twist_deg"])
