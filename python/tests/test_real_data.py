"""biv-me guide points through Python equal the CLI's fit (skips without ../shared/data)."""
import json

import pfdm
import pytest
from conftest import SOURCE_DIR, run_cli, scratch

GUIDE_POINTS = SOURCE_DIR.parent / "shared" / "data" / "biv-me-patient1" / "guidepoints"


@pytest.mark.skipif(not GUIDE_POINTS.is_dir(), reason="real data absent")
def test_guide_points_fit_and_mitral_valve_volumes_equal_the_clis():
    out = scratch("guide_points")
    code, _, err = run_cli("fit", "--points", GUIDE_POINTS, "--out", out / "cli")
    assert code == 0, err
    cli = json.loads((out / "cli" / "fit.json").read_text())
    fit = pfdm.fit(GUIDE_POINTS)
    ours = fit.to_dict()
    for document in (ours, cli):
        document.pop("timing")
        for frame in document["frames"]:
            frame.pop("solve_seconds")
    assert ours == cli
    # Both take the long axis from the guide points' landmarks; the
    # settings stay the user's (no --apex/--base).
    assert cli["model"]["axis_source"] == (
        "APEX_POINT and MITRAL_VALVE, AORTA_VALVE")
    assert "apex_hint" not in cli["settings"]
    assert fit.points.contour_types == cli["settings"]["contour_types"]
    assert "mitral valve plane" in fit.ejection_fraction["cavity_closure"]
    # Frame 0's RV_INSERT points anchor the AHA segments, as in the CLI.
    assert cli["segments_anatomical"] is True
    assert cli["segments"]["anchor"] == "10 RV_INSERT points of GPFile_000.txt"
    assert cli["regions"][1]["name"] == "basal anteroseptal"
    assert len(fit) == 25
    # Slice 2 holds the outflow tract alone at frames 6 and 13: left out,
    # as in the CLI, and said so; the pull toward the previous frame is on.
    assert [(c["frame"], c["contour"]) for c in ours["left_out_contours"]] == [
        (6, "SAX_LV_ENDOCARDIAL 2"), (13, "SAX_LV_ENDOCARDIAL 2")]
    assert ours["model"]["temporal_prior_weight_used"] == 0.05
    assert fit.volume_surface == "cavity"  # Endocardial contours.
    # Contours: no turn about the axis is seen, so none is reported.
    assert all(frame.clinical["net_twist_deg"] is None for frame in fit.frames)
    assert fit.regions[0]["rotation_deg"] == [None] * 25
    assert isinstance(fit[9].clinical["radial_contraction_percent"], float)
    # biv-me's own mesh: 174.5 ml.  The local field's contour rounds stop
    # when they stall, so the solver's path decides where within about
    # 174.9-175.7 ml they leave it (174.9, 175.4 and, run to their limit of
    # 10 rounds, 175.1-175.7 after changes to the direct solve that left
    # the minimum alone; 174.9 from the landmarks' axis).
    assert fit[0].clinical["cavity_volume_ml"] == pytest.approx(175.3, abs=0.5)
    # A flat lid at the rim instead: other volumes, same shapes.
    rim = pfdm.fit(GUIDE_POINTS, base_plane="rim")
    assert "flat lid" in rim.ejection_fraction["cavity_closure"]
    assert (rim[0].clinical["cavity_volume_ml"] !=
            fit[0].clinical["cavity_volume_ml"])
    assert (rim.functions == fit.functions).all()
