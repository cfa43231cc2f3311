// numpydoc docstrings of the compiled classes and their methods: what
// help(pfdm.Fit) and IDEs show.  The properties' own one-line docstrings
// say the same per attribute.
#ifndef PFDM_PYTHON_CLASS_DOCS_H_
#define PFDM_PYTHON_CLASS_DOCS_H_

namespace pfdm::python {

inline constexpr const char* kFitClassDoc =
    R"doc(A fitted sequence, as returned by ``pfdm.fit``.

``fit[t]`` is frame t's FitFrame (negative t and slices work, see
``pfdm.Fit.__getitem__``); ``len(fit)`` the number of frames.  fit.json's
sections are dicts; ``write`` writes the CLI's output files.

Attributes
----------
frames : list of FitFrame
    One per frame.
points : PointSequence
    The data that was fitted.
functions : numpy.ndarray, shape (frames, knots, 18)
    Every frame's parameter functions at the knots, columns in the order
    of ``function_names``.
knot_u : numpy.ndarray, shape (knots,)
    Each knot's latitude u, apex to base.
function_names : list of str
    The 18 functions' names.
function_units : list of str
    Their units: 'mm', 'rad' or '1'.
settings : dict
    fit.json's settings.
model_info : dict
    fit.json's model: name, knots, u range, per function its mode and unit.
ejection_fraction : dict or None
    ratio, ed_frame, es_frame, edv_ml, esv_ml, es_by_midwall,
    cavity_closure; None when the fitted surface is not the cavity's.
volume_surface : str
    What the volumes enclose: 'cavity', 'midwall' or 'epicardial'.
intervals : dict or None
    Every derived number's value, sd and 95 % interval with
    ``uncertainty='on'``; None without.
regions : list of dict
    The 16 AHA segments' numbers per frame.
dyssynchrony : dict
    index: the standard deviation of the segments' time from ED to their
    peak Ecc, in unit ('ms' where frame times are known, else 'frames');
    time_to_peak and peak_frame per segment.
)doc";

inline constexpr const char* kFitFrameClassDoc =
    R"doc(One fitted frame of a Fit.

Attributes
----------
frame : int
    The frame's index.
model : Model
    The fitted model.
functions : numpy.ndarray, shape (knots, 18)
    The parameter functions at the knots (see ``Fit.function_names``).
stats : dict
    Fit statistics: n_points, rms_mm, iterations, termination, quality...
pose : dict
    center_mm and quaternion_wxyz.
clinical : dict
    The clinical summary and the volumes; None for what the data cannot
    determine (rotations of a frame without tracked points).
ids : numpy.ndarray, shape (N,), int64
    The data points' ids.
points : numpy.ndarray, shape (N, 3)
    The data points (mm).
material : numpy.ndarray, shape (N, 2)
    Each data point's material point (u, v) on the model.
residuals : numpy.ndarray, shape (N, 3)
    Model point minus data point (mm).
loss_weights : numpy.ndarray, shape (N,)
    Each point's weight under the robust loss, in (0, 1].
)doc";

inline constexpr const char* kModelClassDoc =
    R"doc(One state of the deformable model: its parameter functions and its pose.

Attributes
----------
name : str
    The preset: 'paper' or 'superellipsoid'.
num_knots : int
    K, knots per function.
u_range : tuple of float
    (u_min, u_max): latitude of the apex and of the base rim.
knot_u : numpy.ndarray, shape (K,)
    Each knot's latitude u, apex to base.
functions : numpy.ndarray, shape (K, 18)
    Every function at each knot.
center : numpy.ndarray, shape (3,)
    The pose's translation (mm).
quaternion_wxyz : numpy.ndarray, shape (4,)
    The pose's rotation, world from model.
)doc";

inline constexpr const char* kPointSequenceClassDoc =
    R"doc(Frames of 3D points (mm) with integer ids.

The same id in several frames is the same material point (a tracked tag);
an id seen once is an untracked surface sample (a contour point).

Parameters
----------
frames : list of array_like or array_like
    A list of (N_t, 3) position arrays (mm), or one (F, N, 3) array.
ids : list of array_like, optional
    One integer array per frame; None: point i of every frame is material
    point i.
source : str, default 'arrays'
    Named in error messages and fit.json.

Raises
------
InputError
    Bad shapes, non-finite positions, repeated ids or empty frames.

Attributes
----------
source : str
    Where the points came from (a path, 'arrays', 'phantom').
contour_types : list of str
    Guide points: the contour types kept; else empty.
time_ms : list of float
    Per frame, its time from the trigger (ms) where the input gave one.
num_frames : int
    Number of frames.
)doc";

inline constexpr const char* kEvaluateDoc =
    R"doc(The model's surface points x(u, v) in world coordinates.

Parameters
----------
u : array_like
    Latitude, apex (u_min) to base (u_max); beyond, the functions hold
    their end values.
v : array_like
    Longitude, -pi to pi; broadcasts with u.

Returns
-------
numpy.ndarray
    Shape broadcast(u, v) + (3,), mm.
)doc";

inline constexpr const char* kSurfaceDoc =
    R"doc(The model surface as a triangle mesh, open at the base rim.

Parameters
----------
rings : int, default 33
    Rings equally spaced in u from apex to base.
meridians : int, default 48
    Points per ring.

Returns
-------
vertices : numpy.ndarray, shape (V, 3)
    mm.
faces : numpy.ndarray, shape (F, 3), int
    Outward-facing triangles.

Examples
--------
PyVista: ``pv.PolyData(vertices, np.hstack([np.full((len(faces), 1), 3),
faces]))``; trimesh: ``trimesh.Trimesh(vertices, faces)``.
)doc";

inline constexpr const char* kFunctionDoc =
    R"doc(One parameter function at the knots.

Parameters
----------
name : str
    One of ``pfdm.FUNCTION_NAMES``, e.g. 'tau' or 'a3'.

Returns
-------
numpy.ndarray, shape (K,)
    In the function's unit (``pfdm.FUNCTION_UNITS``).
)doc";

inline constexpr const char* kVolumeDoc =
    R"doc(The volume inside a surface of the model, closed by a flat lid at the rim.

Parameters
----------
w : float, optional
    The surface: -1 a solid's endocardium (the cavity, the default for a
    solid), 0 the mid-wall, +1 the epicardium; a single surface's own by
    default.

Returns
-------
float
    ml.
)doc";

inline constexpr const char* kWriteDoc =
    R"doc(Writes the files ``pfdm fit --out`` writes.

fit.json, parameters.csv, parameters.svg, report.html, the frames' meshes
(and slices.svg for a segmentation), each whole or not at all, fit.json
last.

Parameters
----------
out : str or os.PathLike
    The folder; made if absent.
vtk_format : str, default 'vtp'
    'vtp', 'vtk' or 'both', optionally ',ascii' or ',binary'.
vtk_precision : str, default 'float'
    'float' or 'double'.

Raises
------
InputError
    The folder holds files pfdm did not write, or cannot be written.
)doc";

}  // namespace pfdm::python

#endif  // PFDM_PYTHON_CLASS_DOCS_H_
