"""pfdm.simulate: the phantoms of ``pfdm simulate``."""
from . import _pfdm


def simulate(phantom="model", *, frames=None, tags=2000, noise=0.5,
             outliers=0.0, seed=1, kinematics="systole", wall_tags="midwall",
             lesion=False, breathing=True, region="full", sampling="tags",
             slices=0, geometry="prolate", thickening="designed"):
    """Makes a phantom's points and its truth, as ``pfdm simulate`` does.

    Parameters
    ----------
    phantom : {"model", "lv"}
        "model": points of the model's own equations (its truth: one
        `Model` per frame). "lv": the independent LV phantom, written
        without the model's equations (its truth: a dict, the CLI's
        ``*_truth.json``: per frame the measured length, shortening,
        rotations, twist, radial contraction, volumes, thickening and the
        AHA segments' numbers).
    frames : int, optional
        Number of frames; default 5 for "model", the kinematics' own for
        "lv" (systole 5, cycle 9).
    tags : int
        Tracked points per frame (sax-slices: points per frame in all).
    noise : float
        Gaussian noise per coordinate, mm.
    outliers : float
        Fraction of points per frame moved 5-10 mm (listed in the truth).
    seed : int
        Random seed.
    kinematics, wall_tags, lesion, breathing, region, sampling, slices,
    geometry, thickening
        "lv" only, as the CLI's flags of the same names: kinematics
        "systole", "cycle", "rigid-axial", "rigid-lateral", "rigid-tilt",
        "rigid-spin" or "static"; wall_tags "midwall", "wall" (through
        the wall), "endo" or "epi" (one wall); lesion a hypokinetic mid
        anteroseptal sector; breathing a rigid drift; region "full" or
        "midventricular"; sampling "tags" or "sax-slices" with `slices`
        planes (0: the default); geometry "prolate" or "cylinder" (a
        mid-ventricular segment without apex); thickening "designed" or
        "incompressible".

    Returns
    -------
    points : PointSequence
    truth : list of Model or dict
    """
    if phantom == "model":
        lv_only = dict(kinematics=("systole", kinematics),
                       wall_tags=("midwall", wall_tags),
                       lesion=(False, lesion), breathing=(True, breathing),
                       region=("full", region), sampling=("tags", sampling),
                       slices=(0, slices), geometry=("prolate", geometry),
                       thickening=("designed", thickening))
        given = [name for name, (default, value) in lv_only.items()
                 if value != default]
        if given:
            verb = "needs" if len(given) == 1 else "need"
            raise TypeError(f"simulate(): {', '.join(given)} {verb} "
                            "phantom='lv'")
        return _pfdm._simulate_model(
            frames=5 if frames is None else frames, tags=tags, noise=noise,
            outliers=outliers, seed=seed)
    if phantom == "lv":
        return _pfdm._simulate_lv(
            frames=0 if frames is None else frames, tags=tags, noise=noise,
            outliers=outliers, seed=seed, kinematics=kinematics,
            wall_tags=wall_tags, lesion=bool(lesion),
            breathing=bool(breathing), region=region, sampling=sampling,
            slices=slices, geometry=geometry, thickening=thickening)
    raise ValueError(f"simulate(): phantom must be 'model' or 'lv', "
                     f"not {phantom!r}")
