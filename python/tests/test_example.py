"""examples/python_phantom.py runs, with or without matplotlib."""
import importlib.util
import os
import subprocess
import sys

from conftest import SOURCE_DIR, scratch


def test_the_python_example_fits_and_writes_the_outputs():
    out = scratch("example")
    done = subprocess.run(
        [sys.executable, str(SOURCE_DIR / "examples" / "python_phantom.py"),
         "--frames", "3", "--tags", "500", "--out", str(out)],
        capture_output=True, text=True, env=dict(os.environ), check=False)
    assert done.returncode == 0, done.stderr
    assert (out / "fit" / "fit.json").exists()
    assert "frame 2: rms" in done.stdout
    assert "midwall volume fraction 0." in done.stdout
    plotted = importlib.util.find_spec("matplotlib") is not None
    for name in ("functions.png", "strain.png", "surface.png"):
        assert (out / name).exists() == plotted, name
