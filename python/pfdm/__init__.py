"""pfdm: deformable models with parameter functions fitted to LV points.

Park, Metaxas and Young (CVPR 1994): a superellipsoid whose shape, twist,
bending and axis offsets are functions along the long axis, fitted to tracked
tags (SPAMM) or contours of the left ventricle over the cycle.  NumPy arrays
in and out; the clinical numbers as fit.json's dicts, or as a long-form
pandas DataFrame (``Fit.to_dataframe``).

>>> points, truth = pfdm.simulate(phantom="lv", frames=3, tags=600)
>>> fit = pfdm.fit(points)
>>> fit[-1].clinical["net_twist_deg"]
"""
from ._pfdm import (FUNCTION_NAMES, FUNCTION_UNITS, Fit, FitFrame,
                    InputError, Model, PointSequence, __version__,
                    contours_from_segmentation, read_mesh_points, read_points)
from ._fit import fit
from ._simulate import simulate
from . import _frames

_frames.extend_fit_class(Fit)
for _named in (Fit, FitFrame, InputError, Model, PointSequence, fit, simulate):
    _named.__module__ = "pfdm"
del _named

__all__ = [
    "FUNCTION_NAMES", "FUNCTION_UNITS", "Fit", "FitFrame", "InputError",
    "Model", "PointSequence", "contours_from_segmentation", "fit",
    "read_mesh_points", "read_points",
    "simulate", "__version__",
]
