"""The committed type stubs are the ones the built module gives
(scripts/make_python_stubs.py), and they parse."""
import ast
import sys

from conftest import SOURCE_DIR

sys.path.insert(0, str(SOURCE_DIR / "scripts"))
import make_python_stubs  # noqa: E402


def test_committed_stubs_match_the_module():
    committed = (SOURCE_DIR / "python/pfdm/__init__.pyi").read_text()
    assert committed == make_python_stubs.stubs(), (
        "python/pfdm/__init__.pyi is stale: run "
        "PYTHONPATH=build/python /usr/bin/python3 scripts/make_python_stubs.py")
    tree = ast.parse(committed)
    names = {node.name for node in tree.body
             if isinstance(node, (ast.ClassDef, ast.FunctionDef))}
    assert {"Fit", "FitFrame", "Model", "PointSequence", "fit", "simulate",
            "read_points", "read_mesh_points"} <= names
