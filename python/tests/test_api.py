"""The module documents itself, and its options are the CLI's flags."""
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


def cli_defaults():
    """Flag name -> default text from `pfdm --help`."""
    _, out, err = run_cli("--help")
    defaults = {}
    for match in re.finditer(
            r"^\s+-(\w+) \(.*?\)\s+type: \w+\s+default: (\S*)", out + err,
            re.S | re.M):
        defaults[match.group(1)] = match.group(2).strip('"')
    return defaults


def python_defaults(function):
    """Keyword -> default from pybind11's signature line."""
    signature = function.__doc__.splitlines()[0]
    return {name: value.strip("'") for name, value in
            re.findall(r"(\w+): [\w.]+ = ('[^']*'|[^,)]+)", signature)}


def test_fit_takes_the_clis_flags_with_their_defaults():
    cli = cli_defaults()
    ours = python_defaults(pfdm.fit)
    assert len(ours) == 28
    for name, value in ours.items():
        assert name in cli, name
        if name in ("apex", "base", "rv_insertion"):
            assert value == "None" and cli[name] == ""
        elif re.fullmatch(r"[-+.\deE]+", value):
            assert float(value) == float(cli[name]), name
        else:
            assert value == cli[name], name


def test_simulate_and_read_mesh_points_take_the_clis_flags():
    cli = cli_defaults()
    for function in (pfdm.simulate, pfdm.read_mesh_points):
        ours = python_defaults(function)
        assert ours
        for name, value in ours.items():
            cli_value = cli[name]
            if re.fullmatch(r"[-+.\deE]+", value):
                assert float(value) == float(cli_value), name
            else:
                assert value == cli_value, name
