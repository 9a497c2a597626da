"""Studies over many runs: sweep (a table of runs) and optimize (NLopt, with Python objectives
and constraints)."""

import html

import pandas as pd

from . import _core
from ._tables import study_frame
from .runs import RunInterrupted
from .scene import as_scene


def sweep(scene, params=None, *, designs=None, model="multibody", minimize=None, threads=2):
    """One run per point, as ``rollerdyn sweep``; returns sweep.csv as a DataFrame.

    ``params``: {"key.path": values}, a grid over all of them (the last varies fastest); values
    are a list (numbers, or words such as "rigid") or the command line's spec "a:b:step" or
    "v1,v2". ``designs``: instead of a grid, a DataFrame (or list of dicts) with one column per
    key and one row per design. The runs share ``threads`` worker threads; the GIL is released.

    Columns: the parameters, then delta, H, k_p, ... status, cpu_seconds and the drive-sizing
    metrics (see docs/outputs.md); units in ``df.attrs["units"]``. With ``minimize`` (a metric),
    ``df.attrs["optimum"]`` is sweep.json's optimum. Ctrl-C raises RunInterrupted with the table
    of the points done (the others say "not run (interrupted)").
    """
    s = as_scene(scene)
    keys, rows, grid = [], [], []
    if designs is not None:
        d = pd.DataFrame(designs)
        keys = [str(c) for c in d.columns]
        rows = [list(r) for r in d.itertuples(index=False)]
    elif params:
        grid = list(params.items())
    else:
        raise ValueError("sweep: give params ({key: values}) or designs")
    table, optimum, execution, interrupted = _core.sweep(s._s, grid, keys, rows, model, minimize or "", threads)
    df = study_frame(table)
    df.attrs.update({"scene": s.name, "model": model, "optimum": optimum, "execution": execution})
    if interrupted:
        raise RunInterrupted(df)
    return df


class OptimizeResult:
    """What ``rollerdyn optimize`` writes: ``history`` (history.csv: every evaluation),
    ``summary`` (optimize.json), ``found`` and ``optimum`` (the best feasible design)."""

    def __init__(self, history, summary):
        self.history = history
        self.summary = summary

    @property
    def found(self):
        return self.summary["found"]

    @property
    def optimum(self):
        """optimize.json's optimum: parameters, objective, metrics, constraints; None if none found."""
        return self.summary["optimum"]

    def __repr__(self):
        if not self.found:
            return f"<rollerdyn.OptimizeResult: no feasible design in {self.summary['evaluations']} evaluations>"
        # The run at exactly these values: the parameters as applied (shortest exact repr), the
        # objective with 9 significant digits, as `rollerdyn optimize` prints them.
        params = self.optimum["parameters"]
        at = ", ".join(f"{k}={v!r}" for k, v in params.items())
        minimize = self.summary["minimize"]
        value = repr(params[minimize]) if minimize in params else f"{self.optimum['objective']:.9g}"
        return (f"<rollerdyn.OptimizeResult {minimize} = {value} at {at} "
                f"({self.summary['method']}, {self.summary['evaluations']} evaluations; "
                f"{self.summary.get('scope', '')})>")

    def _repr_html_(self):
        return f"<p>{html.escape(repr(self))}</p>" + self.history.to_html(max_rows=20)


def optimize(scene, params, minimize, constraints=(), *, model="multibody", method="auto", max_evals=100,
             threads=2):
    """The design within ``params`` ({"key.path": (lower, upper)}) that minimises ``minimize``
    subject to ``constraints``, with NLopt, as ``rollerdyn optimize``.

    ``minimize``: a metric of the sweep table (e.g. "delta"), one of the parameter keys, or a
    function of the run's row. ``constraints``: "METRIC<=VALUE", "METRIC>=VALUE" or functions of
    the row that are <= 0 where the constraint holds. A row is a dict: every parameter by key,
    every metric of the sweep table, motion, status, steady_state_reached, complete, cpu_seconds.
    The functions see usable runs only (complete, steady, turning). An exception in one stops the
    search and is raised. Ctrl-C raises RunInterrupted with the OptimizeResult so far.

    ``method``: as ``rollerdyn optimize --method``: "auto" (the local method from the middle of
    the ranges, then a grid over the whole ranges, then the local method again from the grid's
    best: a global search; ``summary["scope"]`` says so), "bobyqa" or "cobyla" alone (local: the
    minimum nearest to the start), "direct-l", "crs2", "multistart".
    """
    s = as_scene(scene)
    ranges = [(k, float(lo), float(hi)) for k, (lo, hi) in params.items()]
    history, summary, interrupted = _core.optimize(s._s, ranges, minimize, list(constraints), model, method,
                                                   int(max_evals), int(threads))
    result = OptimizeResult(study_frame(history), summary)
    if interrupted:
        raise RunInterrupted(result)
    return result


class IdentifyResult:
    """What ``rollerdyn identify`` writes and prints: ``summary`` (identify.json: keys with value,
    std and bounds, correlation, signals, warnings, convergence), ``estimates`` (the keys as a
    DataFrame), ``fit`` (t, and per signal the measured values and the model at the estimate),
    ``converged``, ``warnings`` and the console's table as ``text``."""

    def __init__(self, summary, t, curves, text):
        self.summary = summary
        self.text = text
        columns = {"t": t}
        for name, (measured, model) in curves.items():
            columns[f"{name}_measured"] = measured
            if len(model):
                columns[f"{name}_model"] = model
        self.fit = pd.DataFrame(columns) if len(t) else pd.DataFrame()
        self.estimates = pd.DataFrame(summary["keys"]).set_index("key")

    @property
    def converged(self):
        return self.summary["convergence"]["converged"]

    @property
    def warnings(self):
        """The warnings in words (correlated keys, undetermined keys, estimates on a bound)."""
        return [w["text"] for w in self.summary["warnings"]]

    def __getitem__(self, key):
        """(value, std) of a free key, in its scene unit."""
        row = self.estimates.loc[key]
        return row["value"], row["std"]

    def __repr__(self):
        keys = ", ".join(f"{k['key']}={k['value']:.6g}±{k['std']:.2g}" if k["std"] is not None
                         else f"{k['key']}={k['value']:.6g}" for k in self.summary["keys"])
        state = "converged" if self.converged else "NOT converged"
        return f"<rollerdyn.IdentifyResult {keys} ({state}; {len(self.warnings)} warnings)>"

    def _repr_html_(self):
        return f"<pre>{html.escape(self.text)}</pre>"


def _measured_csv(data):
    """A DataFrame of measurements as the CSV text the command line reads: t and output columns,
    headers with their units (name[unit]), added here where the DataFrame's names are bare."""
    d = pd.DataFrame(data)
    header = []
    for c in d.columns:
        c = str(c)
        unit = _core.column_unit(c) if "[" not in c else ""
        header.append(f"{c}[{unit}]" if unit else c)
    return d.to_csv(index=False, header=header, float_format="%.17g", lineterminator="\n")


def identify(scene, data, free, bounds=None, noise=None, *, signals=None, model="multibody", holdout=0.3,
             global_search=False, max_iterations=30, threads=2):
    """The values of the ``free`` scene keys that reproduce measured signals, with their standard
    uncertainties, as ``rollerdyn identify`` (docs/identify.md).

    ``data``: a CSV file (t[s] and output columns with units, e.g. omega_crank[rad/s]) or a
    DataFrame with a column t and output columns (bare names get rollerdyn's units). ``bounds``:
    {key: (lower, upper)} where the schema has no finite range. ``noise``: {column: σ} in the
    column's unit; others are estimated from the residuals. ``signals``: the columns to fit
    (default: every measured column). ``holdout``: the fraction of the span
    at its end that is predicted, not fitted. Ctrl-C raises RunInterrupted with the result so far.
    """
    s = as_scene(scene)
    if isinstance(data, (str, bytes)) or hasattr(data, "__fspath__"):
        path, text = str(data), ""
    else:
        path, text = "data", _measured_csv(data)
    if isinstance(free, str):
        free = [k for k in free.split(",") if k]
    ranges = [(k, float(lo), float(hi)) for k, (lo, hi) in (bounds or {}).items()]
    sigma = {k: float(v) for k, v in (noise or {}).items()}
    summary, t, curves, description, interrupted = _core.identify(
        s._s, path, text, list(signals or []), list(free), ranges, sigma, model, float(holdout), bool(global_search), int(max_iterations),
        int(threads))
    result = IdentifyResult(summary, t, curves, description)
    if interrupted:
        raise RunInterrupted(result)
    return result
