"""What contours cannot show is None in Python's dicts, as it is null in fit.json.

Contours have no material points, so a turn about the long axis is not seen:
rotation, twist, torsion and shear are None in every frame of a fit of the
independent LV phantom's points with ids made unique per frame; the same
points as tags give numbers.
"""
import pfdm
from conftest import run_cli, scratch

ROTATION_KEYS = ("net_twist_deg", "apex_rotation_deg", "base_rotation_deg",
                 "torsion_deg_per_cm", "shear_angle_deg", "gcl_percent")


def as_contours(csv, out):
    """csv (frame,id,x,y,z) with every id unique to its frame."""
    lines = csv.read_text().splitlines()
    rows = [lines[0]]
    for line in lines[1:]:
        frame, point_id, rest = line.split(",", 2)
        rows.append(f"{frame},{int(point_id) + 1000000 * int(frame)},{rest}")
    out.write_text("\n".join(rows) + "\n")


def test_rotation_of_contours_is_none_and_of_tags_a_number():
    folder = scratch("not_measured")
    tags_csv = folder / "lv.csv"
    code, _, err = run_cli("simulate", "--phantom", "lv", "--out", tags_csv)
    assert code == 0, err
    contours_csv = folder / "lv_contours.csv"
    as_contours(tags_csv, contours_csv)

    tags = pfdm.fit(str(tags_csv))
    contours = pfdm.fit(str(contours_csv))
    assert len(contours) == len(tags) == 5
    for frame in range(5):
        for key in ROTATION_KEYS:
            assert isinstance(tags[frame].clinical[key], float), key
            assert contours[frame].clinical[key] is None, key
        assert isinstance(contours[frame].clinical["radial_contraction_percent"],
                          float)
    # The phantom twists 13 degrees by end-systole; the mid-wall fit 8.4.
    assert 6.0 < tags[4].clinical["net_twist_deg"] < 11.0
    for region in contours.regions:
        assert region["rotation_deg"] == [None] * 5
        assert region["ecl_percent"] == [None] * 5
        assert all(isinstance(e, float) for e in region["ecc_percent"])
    assert all(isinstance(r, float) for r in tags.regions[15]["rotation_deg"])
    assert contours.to_dict()["not_measured"]["frames"] == [0, 1, 2, 3, 4]
    assert "not_measured" not in tags.to_dict()


def test_a_frame_that_lost_slices_has_no_volume_nor_ejection_fraction():
    """Three short-axis slices: at end-systole the base has left the basal
    one, and that frame's volume, the ESV and the ratio are None (NaN in the
    DataFrame and the intervals); the other frames keep theirs."""
    points, _ = pfdm.simulate("lv", sampling="sax-slices", slices=3)
    result = pfdm.fit(points, surface="endo", uncertainty=True)
    volumes = [frame.clinical["cavity_volume_ml"] for frame in result]
    assert volumes[4] is None
    assert all(isinstance(v, float) for v in volumes[:4])
    ef = result.ejection_fraction
    assert ef["ratio"] is None and ef["esv_ml"] is None
    assert isinstance(ef["edv_ml"], float)
    assert result.to_dict()["not_measured"]["short_span"]["frames"] == [4]
    reasons = [r["code"] for r in result[4].stats["quality_reasons"]]
    assert "short_span" in reasons
