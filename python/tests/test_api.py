"""The module documents itself, and its options are the CLI's flags."""
import inspect
import re

import pfdm
from conftest import run_cli


def doc_text(obj):
    """A docstring without pybind11's generated signature lines."""
    lines = (obj.__doc__ or "").splitlines()
    name = getattr(obj, "__name__", "")
    if name and lines and lines[0].startswith(name + "("):
        lines = lines[1:]
    return " ".join(lines).strip()


def public(namespace):
    return [(name, getattr(namespace, name)) for name in dir(namespace)
            if not name.startswith("_")]


def test_every_function_class_method_and_property_is_documented():
    undocumented = []
    assert len(doc_text(pfdm)) > 40
    checked = 0
    for name, obj in public(pfdm):
        if isinstance(obj, (str, tuple)):
            continue  # __version__, FUNCTION_NAMES, FUNCTION_UNITS
        checked += 1
        if len(doc_text(obj)) < 20:
            undocumented.append(name)
        if isinstance(obj, type) and not issubclass(obj, Exception):
            for member, value in vars(obj).items():
                if member.startswith("_") and member not in ("__len__", "__getitem__"):
                    continue
                checked += 1
                if len(doc_text(value)) < 10:
                    undocumented.append(f"{name}.{member}")
    if len(doc_text(pfdm.PointSequence.__init__)) < 20:
        undocumented.append("PointSequence.__init__")
    assert undocumented == []
    assert checked > 40  # Every class and its members were looked at.


def cli_defaults(command):
    """Flag name -> default text from `pfdm COMMAND --help`."""
    code, out, err = run_cli(command, "--help")
    assert code == 0, err
    return {name: quoted if quoted or value.startswith('"') else value
            for name, value, quoted in
            re.findall(r'^  --(\w+)=("([^"]*)"|\S+)', out, re.M)}


def python_defaults(function):
    """Keyword -> default from pybind11's signature line."""
    signature = function.__doc__.splitlines()[0]
    return {name: value.strip("'") for name, value in
            re.findall(r"(\w+): [\w.]+ = ('[^']*'|[^,)]+)", signature)}


def as_cli_text(value):
    """A Python default as the CLI writes it: True "on", (13, 24) "13x24"."""
    if value is None:
        return ""
    if isinstance(value, bool):
        return "on" if value else "off"
    if isinstance(value, tuple) and all(isinstance(v, str) for v in value):
        return ",".join(value)
    if isinstance(value, tuple):
        return "x".join(map(str, value))
    return value


def same_default(python_value, cli_value):
    if isinstance(python_value, bool):  # A bool flag, or an on/off string.
        return cli_value in (("true", "on") if python_value else ("false", "off"))
    text = as_cli_text(python_value)
    if isinstance(text, (int, float)):
        return float(text) == float(cli_value)
    return text == cli_value


def test_fit_takes_the_clis_flags_with_their_defaults():
    cli = cli_defaults("fit")
    signature = inspect.signature(pfdm.fit).parameters
    ours = {name: p.default for name, p in signature.items() if name != "points"}
    assert len(ours) == 36
    for name, value in ours.items():
        assert name in cli, name
        assert same_default(value, cli[name]), (name, value, cli[name])
    # Every keyword of the compiled fit is wrapped, none left behind.
    assert set(python_defaults(pfdm._pfdm._fit)) - {"points"} == set(ours)


def test_simulate_and_read_mesh_points_take_the_clis_flags():
    simulate = cli_defaults("simulate")
    ours = {name: p.default
            for name, p in inspect.signature(pfdm.simulate).parameters.items()}
    assert len(ours) == 15
    assert ours.pop("frames") is None  # The phantom's own: 5, or the cycle's.
    for name, value in ours.items():
        assert name in simulate, name
        assert same_default(value, simulate[name]), (name, value)
    mesh = cli_defaults("mesh-points")
    for name, value in python_defaults(pfdm.read_mesh_points).items():
        assert value == mesh[name], name
