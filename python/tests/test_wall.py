"""The solid (issue 15) through Python: tags through the wall give the cavity,
the myocardium and the wall's functions; the CLI's fit.json, to the digit."""
import json

import numpy as np
import pytest

import pfdm
from conftest import run_cli, scratch


def without_timing(document):
    """fit.json without what differs between two runs of one fit."""
    document.pop("timing")
    for frame in document["frames"]:
        frame.pop("solve_seconds")
    return document


@pytest.fixture(scope="module")
def wall_tags():
    folder = scratch("wall")
    csv = folder / "lv.csv"
    code, _, err = run_cli("simulate", "--phantom", "lv", "--wall_tags", "wall",
                           "--frames", 3, "--tags", 1000, "--out", csv)
    assert code == 0, err
    return folder, csv


def test_tags_through_the_wall_fit_a_solid(wall_tags):
    folder, csv = wall_tags
    fit = pfdm.fit(str(csv), local=False)
    assert fit.model_info["wall"] == "solid"
    assert fit.model_info["wall_reason"].startswith("tags spread ")
    assert fit.volume_surface == "cavity"
    names = list(fit.function_names)
    h = fit.functions[:, :, names.index("h")]
    # The phantom's wall: 10 mm at the equator, thinner toward the apex.
    assert 7.0 < h[0, len(fit.knot_u) // 2] < 12.0
    assert (h[-1, 1:] > h[0, 1:]).all()  # It thickens in systole.
    ed, es = fit[0].clinical, fit[2].clinical
    assert ed["cavity_volume_ml"] == pytest.approx(107.0, rel=0.05)
    assert ed["lv_mass_g"] == pytest.approx(1.05 * ed["myocardial_volume_ml"])
    assert es["wall_thickening_percent"] > 10.0
    assert fit[0].model.volume_ml() == pytest.approx(
        fit[0].model.volume_ml(w=-1))
    assert fit[0].model.volume_ml(w=1) > fit[0].model.volume_ml(w=0)
    assert fit.ejection_fraction["ratio"] > 0.3
    # The same fit as the CLI's.
    code, _, err = run_cli("fit", "--local", "off", "--points", csv, "--out",
                           folder / "cli")
    assert code == 0, err
    cli = json.loads((folder / "cli" / "fit.json").read_text())
    ours = fit.to_dict()
    assert without_timing(ours) == without_timing(cli)


def test_segments_say_what_they_cannot_show_through_the_wall(wall_tags):
    _, csv = wall_tags
    # Held depths (the default): the motion shows, the thickening is the
    # ring's; ranked, the segment reads as its ring.
    through = pfdm.fit(str(csv), local=False).segments["through_the_wall"]
    assert "its motion does" in through
    assert "--local_transmural on" in through
    ranked = pfdm.fit(str(csv), local=False, tag_depths="ranked")
    assert "reads as its ring" in ranked.segments["through_the_wall"]
    # Through the wall: a third of the wall's thickening is the field's bend.
    transmural = pfdm.fit(str(csv), local_transmural="on").segments
    assert "each third of the wall" in transmural["through_the_wall"]


def test_strain_per_layer_in_the_long_table(wall_tags):
    _, csv = wall_tags
    fit = pfdm.fit(str(csv), local=False)
    table = fit.to_dataframe()
    layers = table[table.layer.notna()]
    # 3 frames x 17 segments x 3 layers of Ecc, Ell and a third's thickening.
    assert len(layers) == 3 * 17 * 3 * 3
    assert set(layers.layer) == {"endocardium", "midwall", "epicardium"}
    region = fit.to_dict()["regions"][7]
    endo = layers[(layers.segment == region["name"]) &
                  (layers.layer == "endocardium") &
                  (layers.quantity == "ecc_percent")].sort_values("frame")
    assert list(endo.value) == pytest.approx(
        region["layers"]["endocardium"]["ecc_percent"])
    # The endocardium shortens more than the epicardium at ES (the phantom:
    # -25.5 % against -6.3 % in the mid segments).
    epi = region["layers"]["epicardium"]["ecc_percent"][2]
    assert endo.value.iloc[2] < epi - 10.0
    # Err across the wall, one per segment and frame, no layer.
    err = table[(table.quantity == "err_percent") & table.layer.isna()]
    assert len(err) == 3 * 17
    assert err[err.frame == 2].value.min() > 10.0


def test_midwall_keeps_one_surface(wall_tags):
    _, csv = wall_tags
    fit = pfdm.fit(str(csv), wall="midwall", local=False)
    assert fit.model_info["wall"] == "midwall"
    assert fit.ejection_fraction is None
    assert "midwall_volume_ml" in fit[0].clinical
    names = list(fit.function_names)
    np.testing.assert_array_equal(fit.functions[:, :, names.index("h")], 0.0)
    # No wall, no layers: absent, not zeros.
    assert "layers" not in fit.to_dict()["regions"][7]
    assert fit.to_dataframe().layer.isna().all()


def test_surface_ed_frame_and_trigger_times_reach_the_fit(wall_tags):
    """--surface endo makes the volumes the cavity's (an ejection fraction);
    --ed_frame moves ED; a time_ms column reaches the points and the frames."""
    folder, csv = wall_tags
    lines = csv.read_text().splitlines()
    timed = folder / "timed.csv"
    timed.write_text("\n".join(
        [lines[0] + ",time_ms"] +
        [line + "," + str(40 * int(line.split(",")[0]) + 10) for line in lines[1:]])
        + "\n")
    points = pfdm.read_points(str(timed))
    assert points.time_ms == [10.0, 50.0, 90.0]
    fit = pfdm.fit(str(timed), surface="endo", ed_frame=1, local=False)
    assert fit.settings["surface"] == "endo"
    assert fit.settings["ed_frame"] == 1
    assert fit.volume_surface == "cavity"
    assert fit.ejection_fraction["ed_frame"] == 1
    assert fit.to_dict()["frames"][2]["time_ms"] == 90.0
    with pytest.raises(pfdm.InputError, match="^surface must be auto, endo"):
        pfdm.fit(str(timed), surface="inner")


def test_incompressible_holds_the_wall(wall_tags):
    """--incompressible as a keyword: the weight in the settings and the term
    in every frame's problem after frame 0 (docs/accuracy.md)."""
    _, csv = wall_tags
    fit = pfdm.fit(str(csv), local=False, incompressible=1.0)
    document = fit.to_dict()
    assert document["settings"]["incompressible_weight"] == 1.0
    costs = [frame["final_cost"]["incompressibility"]
             for frame in document["frames"]]
    assert costs[0] == 0.0
    assert all(cost > 0.0 for cost in costs[1:])
    with pytest.raises(pfdm.InputError, match="incompressible"):
        pfdm.fit(str(csv), local=False, incompressible=-1.0)


def test_local_transmural_as_a_keyword(wall_tags):
    """--local_transmural as a keyword: in the settings, and a solid's layers
    then move apart (its endocardium's Ecc differs from the plain field's);
    a bad value names the keyword."""
    folder, csv = wall_tags
    plain = pfdm.fit(str(csv))
    layered = pfdm.fit(str(csv), local_transmural=True)
    assert plain.to_dict()["settings"]["local_transmural"] is False
    assert layered.to_dict()["settings"]["local_transmural"] is True
    endo = [region["layers"]["endocardium"]["ecc_percent"][-1]
            for region in layered.to_dict()["regions"][:16]]
    endo_plain = [region["layers"]["endocardium"]["ecc_percent"][-1]
                  for region in plain.to_dict()["regions"][:16]]
    assert max(abs(a - b) for a, b in zip(endo, endo_plain)) > 0.1
    # The CLI's flag gives the same fit.
    code, _, err = run_cli("fit", "--local_transmural", "on", "--points", csv,
                           "--out", folder / "cli_transmural")
    assert code == 0, err
    cli = json.loads((folder / "cli_transmural" / "fit.json").read_text())
    ours = layered.to_dict()
    assert without_timing(ours) == without_timing(cli)
    with pytest.raises(pfdm.InputError, match="local_transmural"):
        pfdm.fit(str(csv), local=False, local_transmural=True)


def test_tag_depths_as_a_keyword(wall_tags):
    """--tag_depths as a keyword: in the settings and each tracked frame's
    entry; held (the default), a tracked frame after the first is one solve
    (no ranking);
    the CLI's flag gives the same fit; a bad value names the keyword; with
    --local_transmural on the depths follow it too (ranked: among
    neighbours)."""
    folder, csv = wall_tags
    ranked = pfdm.fit(str(csv), local=False, tag_depths="ranked")
    held = pfdm.fit(str(csv), local=False)
    assert ranked.to_dict()["settings"]["tag_depths"] == "ranked"
    assert held.to_dict()["settings"]["tag_depths"] == "held"
    frames = held.to_dict()["frames"]
    assert len(frames) >= 3
    assert "tag_depths" not in frames[0]
    assert [f["tag_depths"] for f in frames[1:]] == ["held"] * (len(frames) - 1)
    assert ranked.to_dict()["frames"][1]["tag_depths"] == "ranked"
    assert frames[2]["correspondence_rounds"] == 1
    code, _, err = run_cli("fit", "--tag_depths", "ranked", "--local", "off",
                           "--points", csv, "--out", folder / "cli_ranked")
    assert code == 0, err
    cli = json.loads((folder / "cli_ranked" / "fit.json").read_text())
    ours = ranked.to_dict()
    assert without_timing(ours) == without_timing(cli)
    with pytest.raises(pfdm.InputError, match="tag_depths"):
        pfdm.fit(str(csv), tag_depths="kept")
    transmural = pfdm.fit(str(csv), local_transmural=True,
                          tag_depths="ranked").to_dict()
    assert transmural["settings"]["tag_depths"] == "ranked"
    assert transmural["frames"][1]["tag_depths"] == "ranked"
