"""pfdm.fit: Pythonic keywords over the compiled fit, which takes the CLI's
strings (``local="on"``, ``contours="lv-endo,lv-epi"``,
``local_grid="13x24"``)."""
import numbers
import re

from . import _pfdm


def _on_off(name, value):
    if isinstance(value, bool):
        return "on" if value else "off"
    if value in ("on", "off"):
        return value
    raise TypeError(f"fit() argument '{name}' must be bool, not "
                    f"{type(value).__name__}")


def _names(name, value):
    if isinstance(value, str):
        return value
    try:
        items = list(value)
    except TypeError:
        items = None
    if items is None or not all(isinstance(item, str) for item in items):
        raise TypeError(f"fit() argument '{name}' must be a str or a list of "
                        f"str, not {type(value).__name__}")
    return ",".join(items)


def _grid(value):
    if isinstance(value, str):
        return value
    try:
        rows, columns = value
    except (TypeError, ValueError):
        raise TypeError("fit() argument 'local_grid' must be (rings, sectors), "
                        f"not {value!r}") from None
    for number in (rows, columns):
        if not isinstance(number, numbers.Integral) or isinstance(number, bool):
            raise TypeError("fit() argument 'local_grid' must be two ints, "
                            f"not {value!r}")
    return f"{rows}x{columns}"


def _number(name, value, kind):
    wanted = numbers.Integral if kind is int else numbers.Real
    if isinstance(value, bool) or not isinstance(value, wanted):
        raise TypeError(f"fit() argument '{name}' must be {kind.__name__}, "
                        f"not {type(value).__name__}")
    return kind(value)


def _without_dashes(message, keywords):
    """The CLI's message with its flags named as fit's keywords."""
    return re.sub(r"--([a-z_]+)",
                  lambda m: m.group(1) if m.group(1) in keywords else m.group(0),
                  message)


_INTS = ("knots", "ed_frame", "threads", "max_steps")
_FLOATS = ("smoothness", "prior", "untracked_prior", "untracked_prior_radii",
           "temporal_prior",
           "incompressible", "time_step", "rest_tolerance", "local_stiffness")


def fit(points=None, *, segmentation=None, labels="acdc", format="auto",
        contours=("lv-cavity",), base_plane="auto", rv_insertion=None,
        model="paper", knots=17, wall="auto", surface="auto", ed_frame=0,
        smoothness=1.0, prior=0.001, untracked_prior=0.01,
        untracked_prior_radii=0.3, temporal_prior=0.05, incompressible=0.0,
        loss="none",
        loss_scale="auto", threads=1, apex=None, base=None, solver="direct",
        linear_solver="DENSE_SCHUR", time_step=0.0,
        rest_tolerance=1e-6, max_steps=20000, damping="model",
        damping_scale="", jacobian="analytic", local=True,
        local_grid=(13, 24), local_stiffness=0.02, local_transmural=False,
        tag_depths="held", uncertainty=False):
    """Fits every frame, as ``pfdm fit`` does with the flags of the same names.

    Parameters
    ----------
    points : PointSequence, str or list of (N, 3) arrays
        The data: a PointSequence, a path (a frame,id,x,y,z CSV, a biv-me
        GPFile or a folder of them, read as `read_points` with `format` and
        `contours`), or one (N, 3) array per frame whose row i is the same
        material point in every frame (tracked tags). Or None, with:
    segmentation : str, optional
        A NIfTI label map (4D, or a folder of 3D files, one per frame): the
        walls' contours, base and RV insertion are taken from it
        (`contours_from_segmentation`; docs/segmentation.md).
    labels : str
        The label values: "acdc", "mnms", or "lv=3,myo=2,rv=1".
    format : {"auto", "csv", "gpfile"}
        How a path is read; "auto" by its name.
    contours : str or list of str
        GPFile contour types to keep, e.g. ``["lv-endo", "lv-epi"]`` (both
        walls: a solid); "lv-cavity" is the endocardium with the aortic valve.
    base_plane : {"auto", "rim"}
        Where the cavity is closed: "auto" at the mitral valve points of
        guide points read from a path, else "rim" (a lid at the base rim).
    rv_insertion : (3,) or (6,) array_like or str, optional
        The anterior RV insertion (x, y, z) in mm, or it and the inferior one:
        the anchor of the AHA segments. Without it, guide points' RV_INSERT;
        else the segments are not anatomical (fit.json says so).
    model : {"paper", "superellipsoid"}
        The paper's LV set-up (a0 constant, eps = 1) or free exponents.
    knots : int
        Knots per parameter function, 2 to 100 (the paper: 17).
    wall : {"auto", "midwall", "solid"}
        One surface, or the wall as a solid from endocardium to epicardium;
        "auto": solid for both walls' contours or tags spread across the wall.
    surface : {"auto", "endo", "midwall", "epi"}
        The wall the points lie on; "endo" gives a cavity volume and an
        ejection fraction. "auto": from contour types or mesh labels.
    ed_frame : int
        End-diastole, the reference of strains and the ejection fraction.
    smoothness : float
        Smoothness weight of the functions, relative to one knot's data.
    prior : float
        Pull toward the previous frame's functions.
    untracked_prior : float
        Frames without tracked points (contours): pull toward frame 0.
    untracked_prior_radii : float
        That pull's (and temporal_prior's) share on the radii a1 and a2 at
        knots the points cover all round: 0 leaves them to the data, 1
        pulls as elsewhere (docs/gauge.md, Radii).
    temporal_prior : float
        Frames without tracked points, in sequences of 20 frames or more:
        pull toward the previous frame (the default settles every frame of
        biv-me's patient 1 and keeps its strain curves smooth; 0: off;
        docs/contour_sequences.md).
    incompressible : float
        A solid's wall keeps frame 0's volume with this weight (a soft
        constraint; 0: off). fit.json's `myocardial_volume_change_percent`
        shows the change with or without it.
    loss : {"none", "huber", "cauchy"}
        Robust loss on each point's distance.
    loss_scale : "auto" or float
        The loss's scale in mm; "auto": per frame, from its median distance.
    threads : int
        Threads for the solver, the closest points and, with
        uncertainty=True, the intervals' steps and draws.
    apex, base : (3,) array_like or str, optional
        Together: hints for the long axis in mm; without, from landmarks,
        parallel slices or the point cloud.
    solver : {"direct", "damped", "integrator"}
        Direct least squares, damped steps, or the paper's explicit
        Lagrangian dynamics.
    linear_solver : str
        Ceres' linear solver of the global solve.
    time_step, rest_tolerance, max_steps, damping, damping_scale
        The damped and integrator solvers' settings, as the CLI's flags.
    jacobian : {"analytic", "autodiff", "numeric"}
        How the data term's Jacobian is computed.
    local : bool
        Fit the local displacement field after the global functions.
    local_grid : (int, int)
        The local field's (rings, sectors).
    local_stiffness : float
        The local field's thin-plate weight.
    local_transmural : bool
        A solid's local field varies through the wall (the endocardium's
        apart from the epicardium's): regional defects through the wall
        show.
    tag_depths : str
        A solid's tags through the wall keep frame 0's depth in every frame,
        as they keep its material point ("held", the default), or are ranked
        across the wall in each ("ranked"; with ``local_transmural`` among
        their neighbours); beside both walls' contours their
        depths are measured across the walls the contours place and held,
        either way.
    uncertainty : bool
        Each knot value's standard deviation, from the frame's covariance
        (``Fit.function_sds``; ``write`` puts it in parameters.csv's sd
        column), and every derived number's interval (``Fit.intervals``).

    Returns
    -------
    Fit
        Per frame a FitFrame (``fit[t]``, slices, ``len(fit)``); fit.json as
        dicts (``to_dict``), a long-form table (``to_dataframe``), and
        ``write(out)`` for the CLI's files.

    Raises
    ------
    InputError
        Bad data or options, with the CLI's one-line message naming the file
        and line or the frame.
    TypeError
        An unknown keyword, or a value of the wrong type.
    """
    arguments = dict(locals())
    for name in _INTS:
        arguments[name] = _number(name, arguments[name], int)
    for name in _FLOATS:
        arguments[name] = _number(name, arguments[name], float)
    arguments["contours"] = _names("contours", contours)
    arguments["local"] = _on_off("local", local)
    arguments["local_transmural"] = _on_off("local_transmural",
                                            local_transmural)
    arguments["uncertainty"] = _on_off("uncertainty", uncertainty)
    arguments["local_grid"] = _grid(local_grid)
    if isinstance(damping_scale, dict):
        arguments["damping_scale"] = ",".join(
            f"{group}={scale}" for group, scale in damping_scale.items())
    del arguments["points"]
    if segmentation is not None:
        arguments["segmentation"] = str(segmentation)
    try:
        return _pfdm._fit(points, **arguments)
    except _pfdm.InputError as error:
        raise _pfdm.InputError(_without_dashes(str(error), arguments)) from None
