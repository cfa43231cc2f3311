"""Fit's Python side: slicing and a long-form table of every number."""
import math

_compiled_getitem = None


def _getitem(self, index):
    """fit[t] (negative counts from the end) or fit[a:b:c], a list."""
    if isinstance(index, slice):
        return [_compiled_getitem(self, t)
                for t in range(*index.indices(len(self)))]
    if not isinstance(index, int):
        index = getattr(index, "__index__", lambda: index)()
    if isinstance(index, int) and index < 0:
        index += len(self)
    if isinstance(index, int) and not 0 <= index < len(self):
        raise IndexError(f"frame {index} of a fit of {len(self)} frames")
    return _compiled_getitem(self, index)


def _iter(self):
    return (_compiled_getitem(self, t) for t in range(len(self)))


def _interval(container, key, index=None):
    """The (low, high) fit.json gives beside `key` (--uncertainty on)."""
    interval = container.get(key + "_ci95")
    if interval is not None and index is not None:
        interval = interval[index]
    return tuple(interval) if interval else (None, None)


def _layer_rows(region, times):
    """A solid's per-layer numbers of one region (fit.json's
    ``regions[i]["layers"]``), each row with its layer's name."""
    for layer, numbers in (region.get("layers") or {}).items():
        for key, values in numbers.items():
            for t, value in enumerate(values):
                yield (t, times[t], key, region["name"], layer, value, None,
                       None)


def _rows(document):
    """(frame, time_ms, quantity, segment, layer, value, low, high) of every
    number fit.json holds per frame: its scalar clinical numbers, RMS and
    volumes, each segment's numbers, and a solid's per segment and layer
    ("endocardium", "midwall", "epicardium"; None for the rest), with their
    95 % interval where computed.  Lists per knot are left out (see
    Fit.functions)."""
    frames = document["frames"]
    times = [frame.get("time_ms", math.nan) for frame in frames]
    for t, frame in enumerate(frames):
        for key, value in frame.items():
            if key in ("rms_mm", "n_points") or key.endswith("_volume_ml"):
                yield (t, times[t], key, None, None, value) + _interval(
                    frame, key)
        clinical = frame.get("clinical", {})
        for key, value in clinical.items():
            if not isinstance(value, (list, dict)):
                yield (t, times[t], key, None, None, value) + _interval(
                    clinical, key)
    for region in document.get("regions") or []:
        for key, values in region.items():
            if (key.endswith("_ci95") or not isinstance(values, list) or
                    len(values) != len(frames)):
                continue
            for t, value in enumerate(values):
                yield ((t, times[t], key, region["name"], None, value) +
                       _interval(region, key, t))
        yield from _layer_rows(region, times)


def _number(value):
    return math.nan if value is None else float(value)


def _to_dataframe(self):
    """Every per-frame number in long form, for pandas.

    Returns
    -------
    pandas.DataFrame
        Columns frame, time_ms (NaN where the data carry no times),
        quantity (fit.json's name, e.g. ``net_twist_deg``, ``ecc_percent``),
        segment (the AHA segment's name, None for global numbers), layer
        (a solid's "endocardium", "midwall" or "epicardium" for its strain
        per layer: ``ecc_percent``, ``ell_percent`` and the third's
        ``thickening_percent``; None for every other number, and for every
        row of a fit without a wall), value (NaN where fit.json has null:
        not measured), and ci95_low and ci95_high (the 95 % interval with
        ``uncertainty=True``, else NaN).  One row per frame, quantity,
        segment and layer.
    """
    import pandas  # Only where wanted: Debian's python3-pandas.

    rows = [(t, time, quantity, segment, layer, _number(value), _number(low),
             _number(high))
            for t, time, quantity, segment, layer, value, low, high
            in _rows(self.to_dict())]
    return pandas.DataFrame(rows, columns=[
        "frame", "time_ms", "quantity", "segment", "layer", "value",
        "ci95_low", "ci95_high"])


def extend_fit_class(fit_class):
    global _compiled_getitem
    _compiled_getitem = fit_class.__getitem__
    fit_class.__getitem__ = _getitem
    fit_class.__iter__ = _iter
    fit_class.to_dataframe = _to_dataframe
