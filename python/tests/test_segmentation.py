"""pfdm.fit(segmentation=...) and pfdm.contours_from_segmentation on a NIfTI
label map written here by hand (numpy and struct, not pfdm's writer): a
truncated ellipsoidal LV shell with an RV crescent, two frames."""
import struct
import warnings

import numpy as np
import pytest

import pfdm
from conftest import scratch

SPACING = (1.5, 1.5, 8.0)
ORIGIN = (-60.0, 40.0, -30.0)


def write_nifti1(path, labels):
    """A NIfTI-1 .nii of int16 labels (x, y, slice, time), axis-aligned
    sform (code 1) with SPACING and ORIGIN: world = ORIGIN + SPACING * ijk."""
    dim = [labels.ndim] + list(labels.shape) + [1] * (7 - labels.ndim)
    pixdim = [1.0, *SPACING, 1.0, 1.0, 1.0, 1.0]
    header = bytearray(352)
    struct.pack_into("<i", header, 0, 348)
    struct.pack_into("<8h", header, 40, *dim)
    struct.pack_into("<hh", header, 70, 4, 16)  # DT_INT16, 16 bits.
    struct.pack_into("<8f", header, 76, *pixdim)
    struct.pack_into("<f", header, 108, 352.0)  # vox_offset
    struct.pack_into("<f", header, 112, 1.0)  # scl_slope
    struct.pack_into("<h", header, 254, 1)  # sform_code
    rows = [[SPACING[0], 0, 0, ORIGIN[0]], [0, SPACING[1], 0, ORIGIN[1]],
            [0, 0, SPACING[2], ORIGIN[2]]]
    struct.pack_into("<12f", header, 280, *sum(rows, []))
    header[344:348] = b"n+1\0"
    with open(path, "wb") as out:
        out.write(bytes(header))
        out.write(labels.astype("<i2").tobytes(order="F"))


def lv_mask(radius_scale):
    """96 x 96 x 12 voxels: cavity (3) inside an ellipsoid of semi-axes
    20 r, 20 r, 50 mm, myocardium (2) out to 29, 29, 58 mm, cut at z = 20 mm
    above the centre; RV (1) outside within 12 mm at angles -180 to -60."""
    i, j, k = np.meshgrid(np.arange(96), np.arange(96), np.arange(12),
                          indexing="ij")
    x, y = (i - 47.5) * SPACING[0], (j - 47.5) * SPACING[1]
    z = k * SPACING[2] - 60.0
    labels = np.zeros(i.shape, np.int16)
    epi = (x / 29) ** 2 + (y / 29) ** 2 + (z / 58) ** 2 <= 1
    endo = (x / (20 * radius_scale)) ** 2 + (y / (20 * radius_scale)) ** 2 + \
        (z / 50) ** 2 <= 1
    rv_shell = (x / 41) ** 2 + (y / 41) ** 2 + (z / 70) ** 2 <= 1
    angle = np.degrees(np.arctan2(y, x))
    below = z <= 20
    labels[rv_shell & ~epi & (angle < -60) & below] = 1
    labels[epi & below] = 2
    labels[endo & below] = 3
    return labels


@pytest.fixture(scope="module")
def mask_file():
    folder = scratch("segmentation")
    labels = np.stack([lv_mask(1.0), lv_mask(0.8)], axis=3)
    write_nifti1(folder / "mask.nii", labels)
    cavity_ml = [(labels[..., t] == 3).sum() * np.prod(SPACING) / 1000
                 for t in range(2)]
    return folder / "mask.nii", cavity_ml


def test_contours_from_segmentation(mask_file):
    path, _ = mask_file
    c = pfdm.contours_from_segmentation(path, labels="lv=3,myo=2,rv=1")
    assert c["shape"] == (96, 96, 12, 2)
    assert c["geometry"] == "sform"
    assert c["slice_thickness_mm"] == pytest.approx(8.0)
    assert len(c["endo"]) == 2 and len(c["epi"]) == 2
    # The apex at slice 0, the base at the last slice below the cut (z = 20
    # mm: slice 10).
    assert c["apex_slice"] == 0
    assert c["base_slice"] == [10, 10]
    # Slice 7 (z = -4 mm from the centre, world z = -30 + 56): its
    # endocardial points lie on the cavity's cut, radius 20 sqrt(1 -
    # (4 / 50)^2) = 19.94 mm, within half a voxel.
    endo = c["endo"][0]
    mid = endo[np.abs(endo[:, 2] - 26.0) < 1e-4]
    assert len(mid) > 60
    centre = np.array([ORIGIN[0] + 47.5 * 1.5, ORIGIN[1] + 47.5 * 1.5])
    radius = np.hypot(mid[:, 0] - centre[0], mid[:, 1] - centre[1])
    assert np.abs(radius - 19.94).max() < 0.75
    # The RV insertions: two per slice, at -60 and 180 degrees.
    rv = c["rv_insertion"]
    assert rv.shape[1] == 3 and len(rv) >= 12 and len(rv) % 2 == 0
    angles = np.degrees(np.arctan2(rv[:, 1] - centre[1], rv[:, 0] - centre[0]))
    assert np.all(np.minimum(np.abs(angles + 60), 180 - np.abs(angles)) < 8)
    assert c["warnings"] == [] and c["misaligned"] == []


def test_fit_segmentation_volumes(mask_file):
    path, cavity_ml = mask_file
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # No misaligned slice here.
        fit = pfdm.fit(segmentation=str(path), labels="acdc", local="off")
    assert fit.model_info["wall"] == "solid"
    for t in range(2):
        assert fit[t].clinical["cavity_volume_ml"] == pytest.approx(
            cavity_ml[t], rel=0.05)
    assert fit.settings["contour_types"] == ["SAX_LV_ENDOCARDIAL",
                                             "SAX_LV_EPICARDIAL"]
    record = fit.to_dict()["segmentation"]
    assert record["labels"] == {"lv": 3, "myo": 2, "rv": 1}
    assert record["slices"] == 12 and record["frames"] == 2
    assert record["misaligned"] == []
    # write() writes what the CLI writes, the slices with the walls too:
    # three slices at ED and ES, each titled.
    out = scratch("segmentation_write") / "fit"
    fit.write(out)
    assert (out / "slices.svg").read_text().count("<text") == 6
    assert "The segmentation and the fit" in (out / "report.html").read_text()


def test_segmentation_errors(mask_file):
    path, _ = mask_file
    with pytest.raises(pfdm.InputError, match="no voxel labelled lv=7"):
        pfdm.contours_from_segmentation(path, labels="lv=7,myo=2")
    with pytest.raises(pfdm.InputError, match="not both"):
        pfdm.fit(str(path), segmentation=str(path))
    with pytest.raises(pfdm.InputError, match="no such file"):
        pfdm.fit(segmentation=str(path) + ".missing")
