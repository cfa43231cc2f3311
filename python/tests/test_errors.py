"""Bad input raises pfdm.InputError with the CLI's message; Ctrl-C stops fits."""
import os
import signal
import threading
import time

import numpy as np
import pfdm
import pytest
from conftest import cli_error, scratch


def test_input_error_is_a_value_error():
    assert issubclass(pfdm.InputError, ValueError)


def test_bad_files_raise_the_clis_message():
    folder = scratch("bad_files")
    missing = folder / "missing.csv"
    nan = folder / "nan.csv"
    nan.write_text("frame,id,x,y,z\n0,1,1,2,3\n0,2,nan,2,3\n")
    gap = folder / "gap.csv"
    gap.write_text("frame,id,x,y,z\n0,1,1,2,3\n2,1,1,2,3\n")
    for path in (missing, nan, gap):
        message = cli_error("fit", "--points", path, "--out", folder / "out")
        with pytest.raises(pfdm.InputError) as raised:
            pfdm.fit(path)
        assert str(raised.value) == message
        with pytest.raises(pfdm.InputError) as raised:
            pfdm.read_points(str(path))
        assert str(raised.value) == message
    assert "nan.csv:3" in cli_error("fit", "--points", nan, "--out", folder)


def test_bad_options_raise_the_clis_message(cli_phantom):
    folder, points_csv, _ = cli_phantom
    cases = [
        ({"solver": "newton"}, ["--solver", "newton"]),
        ({"knots": 1}, ["--knots", "1"]),
        ({"model": "cube"}, ["--model", "cube"]),
        ({"apex": (1, 2, 3)}, ["--apex", "1,2,3"]),
        ({"apex": "1,2,3", "base": "1,2"}, ["--apex", "1,2,3", "--base", "1,2"]),
        ({"linear_solver": "MAGIC"}, ["--linear_solver", "MAGIC"]),
        ({"max_steps": 0}, ["--max_steps", "0"]),
        ({"damping_scale": "spin=2"}, ["--damping_scale", "spin=2"]),
        ({"base_plane": "lid"}, ["--base_plane", "lid"]),
        ({"rv_insertion": "1,2"}, ["--rv_insertion", "1,2"]),
        ({"format": "xml"}, ["--format", "xml"]),
        ({"jacobian": "guess"}, ["--jacobian", "guess"]),
        # Issue 29: settings of no use or of no sense, and those checked
        # against the data once read.
        ({"time_step": 1.0}, ["--time_step", "1"]),
        ({"local_stiffness": 0.0}, ["--local_stiffness", "0"]),
        ({"loss": "cauchy", "loss_scale": 1e150},
         ["--loss", "cauchy", "--loss_scale", "1e150"]),
        ({"apex": (9e5, 0, 0), "base": (-9e5, 0, 0)},
         ["--apex", "900000,0,0", "--base=-900000,0,0"]),
    ]
    for kwargs, flags in cases:
        message = cli_error("fit", "--points", points_csv, "--out",
                            folder / "never", *flags)
        with pytest.raises(pfdm.InputError) as raised:
            pfdm.fit(points_csv, **kwargs)
        assert str(raised.value) == message, kwargs
    with pytest.raises(TypeError):
        pfdm.fit(points_csv, no_such_option=1)


def test_bad_arrays_raise_naming_the_frame():
    good = np.zeros((12, 3)) + np.arange(12)[:, None]
    cases = [
        (([good, np.zeros((5, 2))],), "arrays: frame 1: positions must be an (N, 3) array, got shape (5, 2)"),
        (([good, np.zeros((0, 3))],), "arrays: frame 1 has no points"),
        (([np.full((3, 3), np.nan)],), "arrays: frame 0: point 0 is not finite"),
        (([good], [np.zeros(12, dtype=int)]), "arrays: id 0 appears twice in frame 0"),
        (([good], [np.arange(12.0)]), "arrays: frame 0: ids must be an array of integers"),
        (([good], [np.arange(11)]), "arrays: frame 0: ids must have shape (12,), got (11,)"),
        (([good], [np.arange(12), np.arange(12)]), "arrays: 2 id arrays for 1 frames"),
        (([],), "arrays: no points"),
        (([[["a", "b", "c"]]],), "arrays: frame 0: positions must be an (N, 3) array of numbers"),
    ]
    for args, message in cases:
        with pytest.raises(pfdm.InputError) as raised:
            pfdm.PointSequence(*args)
        assert str(raised.value) == message
    # Too few points is the fitter's message, naming the frame.
    with pytest.raises(pfdm.InputError) as raised:
        pfdm.fit([good[:5]])
    assert str(raised.value) == "arrays: frame 0: only 5 points, at least 10 needed"


def test_bad_arguments_to_a_fitted_model_raise():
    points, truth = pfdm.simulate(frames=1, tags=50)
    model = truth[0]
    with pytest.raises(pfdm.InputError, match="finite"):
        model.evaluate(np.nan, 0.0)
    with pytest.raises(pfdm.InputError, match="rings >= 2"):
        model.surface(rings=1)
    with pytest.raises(pfdm.InputError, match="unknown function 'twist'"):
        model.function("twist")
    with pytest.raises(IndexError):
        points.positions(1)
    with pytest.raises(pfdm.InputError) as raised:
        pfdm.simulate(frames=0)
    assert str(raised.value) == cli_error("simulate", "--frames", 0, "--out",
                                          scratch("bad_simulate") / "p.csv")


# The damped solver stops through a Ceres callback, the integrator in its
# own loop.  With this rest tolerance (and the damped solver's small step)
# both take thousands of steps a frame, over 10 s uninterrupted.
@pytest.mark.parametrize("solver, time_step",
                         [("damped", 0.01), ("integrator", 0.0)])
def test_ctrl_c_interrupts_a_long_fit_and_the_module_still_works(
        solver, time_step):
    points, _ = pfdm.simulate(frames=3, tags=2000)
    timer = threading.Timer(0.5, os.kill, (os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            pfdm.fit(points, solver=solver, rest_tolerance=1e-12,
                     time_step=time_step)
    finally:
        timer.cancel()
    assert time.monotonic() - start < 5.0
    fit = pfdm.fit(points)
    assert len(fit) == 3 and fit[0].stats["rms_mm"] < 0.6


def test_fit_releases_the_gil():
    points, _ = pfdm.simulate(frames=2, tags=2000)
    ticks = []
    done = threading.Event()

    def count():
        while not done.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    start = time.monotonic()
    pfdm.fit(points, solver="damped")
    elapsed = time.monotonic() - start
    done.set()
    counter.join()
    # Python ran beside the fit: ticks spread over it, not bunched at its end.
    during = [t for t in ticks if start < t < start + elapsed]
    assert elapsed > 0.05 and len(during) > 10
