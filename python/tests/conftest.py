"""Shared helpers: the pfdm binary, scratch folders and a phantom fitted by the CLI.

CTest sets PYTHONPATH to build/python and PFDM_BINARY to the built CLI; run
by hand as `PYTHONPATH=build/python /usr/bin/python3 -m pytest python/tests`.
"""
import json
import os
import pathlib
import shutil
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(
    os.environ.get("PFDM_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
PFDM_BINARY = os.environ.get("PFDM_BINARY", str(SOURCE_DIR / "build" / "pfdm"))


def scratch(name):
    """A fresh /tmp/pfdm_tests/python/<name>/, kept for a look afterwards."""
    path = pathlib.Path("/tmp/pfdm_tests/python") / name
    shutil.rmtree(path, ignore_errors=True)
    path.mkdir(parents=True)
    return path


def run_cli(*args):
    """Runs the pfdm binary; returns (exit code, stdout, stderr)."""
    done = subprocess.run([PFDM_BINARY, *map(str, args)], capture_output=True,
                          text=True, check=False)
    return done.returncode, done.stdout, done.stderr


def cli_error(*args):
    """The one-line message the CLI prints for bad input, without its prefix."""
    code, _, err = run_cli(*args)
    assert code == 1, err
    line = err.strip()
    assert line.startswith("pfdm: error: ") and "\n" not in line, err
    return line[len("pfdm: error: "):]


@pytest.fixture(scope="session")
def cli_phantom():
    """A small phantom simulated and fitted by the CLI: (folder, csv, fit.json)."""
    folder = scratch("cli_phantom")
    csv = folder / "phantom.csv"
    code, _, err = run_cli("simulate", "--frames", 3, "--tags", 600, "--out", csv)
    assert code == 0, err
    code, _, err = run_cli("fit", "--points", csv, "--out", folder / "cli")
    assert code == 0, err
    with open(folder / "cli" / "fit.json") as f:
        return folder, csv, json.load(f)
