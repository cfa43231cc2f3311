"""Builds pfdm._pfdm with the project's CMake for `pip install .`
(pyproject.toml holds the metadata)."""
import os
import pathlib
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


class CMakeBuild(build_ext):
    """Configures the project without tests or benchmarks, builds the module
    target only, and puts the built module where setuptools wants it."""

    def build_extension(self, ext):
        build = pathlib.Path(self.build_temp).resolve() / "cmake"
        subprocess.run(
            ["cmake", "-S", str(ROOT), "-B", str(build),
             "-DCMAKE_BUILD_TYPE=Release", "-DPFDM_BUILD_TESTS=OFF",
             "-DPFDM_BUILD_BENCHMARKS=OFF", "-DPFDM_BUILD_PYTHON=ON",
             f"-DPython_EXECUTABLE={sys.executable}"], check=True)
        jobs = str(os.cpu_count() or 1)
        subprocess.run(["cmake", "--build", str(build), "--target",
                        "pfdm_python", "-j", jobs], check=True)
        built = next((build / "python" / "pfdm").glob("_pfdm*.so"))
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


setup(ext_modules=[Extension("pfdm._pfdm", sources=[])],
      cmdclass={"build_ext": CMakeBuild},
      # Not build/: that is the CMake build of README's set-up.
      options={"build": {"build_base": ".pip-build"}})
