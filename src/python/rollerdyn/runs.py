"""Runs of one scene: simulate (one model) and compare (both models)."""

import html
import os
import warnings

import pandas as pd

from . import _core
from ._tables import frame
from .scene import Scene, as_scene


def write_outputs(data, out_dir, figures):
    """Writes the files of a result (``data``, the module's object) into ``out_dir`` as its
    command's --out does, with ``figures`` also its figures, and prints the lines the command
    prints about the figures; returns ``out_dir``."""
    text = data.write(os.fspath(out_dir), figures)
    if text:
        print(text, end="")
    return out_dir


class RunWarning(UserWarning):
    """A warning about a run that the command line prints on stderr: a load that does almost no
    net work, or a scene value that is implausible (a length typed in millimetres)."""


class ResonanceWarning(RuntimeWarning):
    """The drive's torsional mode is near an order of the crank speed that the cart layout
    excites: the two-mass first estimate (Dyomin (two rotors) eq. (10)) or the modal analysis
    of the drive about its steady motion; the command line prints the same warning on stderr.
    When the modal analysis reconciles the first estimate's warning, its verdict (the command
    line's next stderr line, ``result.resonance_verdict``) ends the message."""


class RunInterrupted(KeyboardInterrupt):
    """Ctrl-C (or a notebook's interrupt) stopped a run. The part computed is kept, as the
    command line keeps it: ``.result`` holds it (its summary says complete: false and
    status "interrupted at t = ...")."""

    def __init__(self, result):
        super().__init__(f"interrupted: {getattr(result, 'status', 'partial result in .result')}")
        self.result = result


class Summary(dict):
    """summary.json as a dict (the same keys and values, nested dicts too). A key it does not have
    raises a KeyError that names where the value lives: ``summary["steady_state_reached"]`` points
    to ``summary["steady_state"]["reached"]``."""

    def __init__(self, data, path=""):
        super().__init__((k, Summary(v, f'{path}["{k}"]') if isinstance(v, dict) else v) for k, v in data.items())
        self._path = path

    def _paths(self, prefix=()):
        for k, v in self.items():
            yield prefix + (k,)
            if isinstance(v, Summary):
                yield from v._paths(prefix + (k,))

    def __missing__(self, key):
        import difflib
        paths = list(self._paths())
        flat = {"_".join(p): p for p in paths}
        text = str(key)
        found = [flat[text]] if text in flat else []
        if not found:  # a leaf of the same name deeper down, or a close spelling
            found = [p for p in paths if len(p) > 1 and p[-1] == text]
            found += [flat[m] for m in difflib.get_close_matches(text, list(flat), n=3, cutoff=0.75) if flat[m] not in found]
        where = " or ".join(f"summary{self._path}" + "".join(f'["{k}"]' for k in p) for p in found[:3])
        raise KeyError(f"summary{self._path} has no key {key!r}" + (f"; did you mean {where}?" if where else
                                                                       f"; its keys: {', '.join(self)}"))


class Result:
    """One run, as ``rollerdyn simulate`` writes it.

    - ``timeseries``, ``reactions``: DataFrames with the columns of timeseries.csv and
      reactions.csv (bare names; units in ``df.attrs["units"]`` and ``units``); reactions is None
      when the run computed none (simulation.reactions: false).
    - ``crank_speed_extrema``: DataFrame of crank_speed_extrema.csv (t, omega_crank): every
      local extremum of the crank speed, located inside the integrator's steps; δ and the
      summary's omega_crank min and max take them as well as the rows.
    - ``summary``: summary.json as a dict (the same keys); ``sizing`` its drive-sizing answers,
      ``start_up`` its start-up and stopping answers, ``guide_friction`` the friction's margins;
      ``warnings`` every warning (the friction's self-locking and dead-centre ones included).
    - ``write(dir)``: the files ``simulate --out dir`` writes, byte for byte.
    """

    def __init__(self, data):
        self._d = data
        self._timeseries = None
        self._reactions = None
        self._summary = None

    @property
    def scene(self):
        return Scene(self._d.scene)

    @property
    def model(self):
        """multibody or reduced."""
        return self._d.model

    @property
    def complete(self):
        """Whether the run reached t_end (a stall, a failure or Ctrl-C end it early)."""
        return self._d.complete

    @property
    def status(self):
        return self._d.status

    @property
    def warnings(self):
        """Every warning of the run, as summary["warnings"] and in the order the command line
        prints them: the load's and the scene's (also issued as RunWarning), then the resonance
        warnings (also issued as ResonanceWarning)."""
        return list(self._d.run_warnings) + list(self._d.resonance_warnings)

    @property
    def resonance_verdict(self):
        """Why the modal analysis finds no resonance where the two-mass first estimate warned
        ("resonance verdict: ..."), or "" when there is nothing to reconcile."""
        return self._d.resonance_verdict

    @property
    def modes(self):
        """With ``simulate(..., modes=True)``: summary["modes"], the modal analysis of the drive
        about its steady motion (as modes.json), else None."""
        return self.summary.get("modes")

    @property
    def frozen(self):
        """With modes=True: the frozen-angle modes along the steady motion (frozen.csv)."""
        table = self._d.frozen()
        return None if table is None else frame(table)

    @property
    def campbell(self):
        """With modes=True: the Campbell diagram (campbell.csv); None for a rigid coupling."""
        table = self._d.campbell()
        return None if table is None else frame(table)

    @property
    def spectrum(self):
        """With modes=True: the order spectrum of the torques and reactions over the steady
        window (spectrum.csv)."""
        table = self._d.spectrum()
        return None if table is None else frame(table)

    @property
    def timeseries(self):
        if self._timeseries is None:
            self._timeseries = frame(self._d.timeseries())
        return self._timeseries

    @property
    def crank_speed_extrema(self):
        return frame(self._d.crank_speed_extrema())

    @property
    def reactions(self):
        if self._reactions is None:
            table = self._d.reactions()
            if table is None:
                return None
            self._reactions = frame(table)
        return self._reactions

    @property
    def units(self):
        """Unit of every column of timeseries and reactions, e.g. units["coupling_torque"] == "N*m"."""
        u = dict(self.timeseries.attrs["units"])
        if self.reactions is not None:
            u.update(self.reactions.attrs["units"])
        return u

    @property
    def summary(self):
        """summary.json as a dict: the same keys and values."""
        if self._summary is None:
            self._summary = Summary(self._d.summary())
        return self._summary

    @property
    def sizing(self):
        """The drive-sizing answers (summary["sizing"]): motor, flywheel, coupling, joints."""
        return self.summary["sizing"]

    @property
    def start_up(self):
        """The start-up and stopping answers (summary["start_up"]): whether and how fast the drive
        starts, its peaks, the rotor's energy loss, the stopping time; None without a motor."""
        return self.summary["start_up"]

    @property
    def guide_friction(self):
        """The guide friction's margins (summary["guide_friction"]): the normal forces used, the
        self-locking index, the smallest transmission angle, the friction work."""
        return self.summary["guide_friction"]

    def write(self, out_dir, figures=False):
        """Writes timeseries.csv, reactions.csv and summary.json into ``out_dir`` (created), as
        ``rollerdyn simulate --out out_dir`` does (with modes=True also modes.json, frozen.csv,
        campbell.csv and spectrum.csv, as ``--modes``); with ``figures`` also its --plot figures.
        Returns the folder."""
        return write_outputs(self._d, out_dir, figures)

    def __str__(self):
        """The summary, start-up and drive-sizing tables ``rollerdyn simulate`` prints."""
        return self._d.text()

    def __repr__(self):
        return f"<rollerdyn.Result {self.scene.name}, {self.model} model: {self.status}>"

    def _repr_html_(self):
        return f"<p><b>{html.escape(self.scene.name)}</b>, {self.model} model</p>" + self._d.html()


def _warn(data, stacklevel):
    for w in data.run_warnings:
        warnings.warn(w, RunWarning, stacklevel=stacklevel)
    # The first estimate's warning and the modal analysis' verdict on it belong together: the
    # command line prints the verdict right after the warnings; a notebook sees only the warning,
    # so the verdict rides in its message (also in ``result.resonance_verdict``).
    verdict = data.resonance_verdict
    for w in data.resonance_warnings:
        warnings.warn(f"{w}; {verdict}" if verdict else w, ResonanceWarning, stacklevel=stacklevel)


def _run(data, interrupted):
    result = Result(data)
    _warn(data, 4)
    if interrupted:
        raise RunInterrupted(result)
    return result


def simulate(scene, model="multibody", modes=False):
    """Runs ``model`` ("multibody", the Simbody model, or "reduced", the papers' reduced-mass
    model) on ``scene`` (a Scene or a scene file path) to its t_end, as ``rollerdyn simulate``.
    With ``modes``, also the modal analysis of the drive about its steady motion (torsional
    modes, Floquet stability, Campbell diagram) and the run's order spectrum, as ``simulate
    --modes``: ``result.modes``, ``frozen``, ``campbell``, ``spectrum``; the resonance verdict
    rests on it.

    The GIL is released while it runs. Ctrl-C stops it at the next output row and raises
    RunInterrupted (a KeyboardInterrupt) with the partial Result in ``.result``.
    """
    return _run(*_core.simulate(as_scene(scene)._s, model, bool(modes)))


class Comparison:
    """Both models on one scene, as ``rollerdyn compare`` (comparison.csv and comparison.json)."""

    def __init__(self, data):
        self._d = data
        self.table = frame(data.table())
        self.summary = Summary(data.json())
        self.multibody = Result(data.multibody)
        self.reduced = Result(data.reduced)

    def differences(self):
        """max_abs_diff, rms_diff, max_rel_diff, ... per compared quantity (comparison.json)."""
        return pd.DataFrame.from_dict(self.summary["quantities"], orient="index")

    def __str__(self):
        return self._d.text()

    def _repr_html_(self):
        items = "".join(f"<li>{html.escape(s)}</li>" for s in self.summary.get("differences", []))
        return (
            f"<p><b>multibody vs reduced</b>: {self.multibody.status} / {self.reduced.status}</p>"
            + self.differences().to_html()
            + (f"<p>Modelling differences that apply to this scene:</p><ul>{items}</ul>" if items else "")
        )


def compare(scene):
    """Runs both models on ``scene`` and compares them, as ``rollerdyn compare``. Ctrl-C raises
    RunInterrupted with the partial Comparison."""
    data, interrupted = _core.compare(as_scene(scene)._s)
    result = Comparison(data)
    if interrupted:
        raise RunInterrupted(result)
    return result


def signoff(scene, out_dir=None):
    """The sign-off sheet of ``scene`` (a Scene or a scene file path), as ``rollerdyn signoff``:
    a multibody run with its modal analysis, and every check it makes (drive sizing, coupling
    after DIN 740-2, fatigue, separation margins after API 617/684) with value, limit, method,
    window and verdict. Returns signoff.json as a dict: ``counts`` (pass, FAIL, not_applicable,
    total), ``overall``, ``signable``, ``checks``. With ``out_dir``, also writes the run's files,
    signoff.json, signoff.html and signoff.pdf there (the PDF needs Chromium; without it a
    RunWarning says so and the JSON and HTML are still written).
    """
    sheet, pdf, pdf_missing = _core.signoff(as_scene(scene)._s, "" if out_dir is None else os.fspath(out_dir))
    if out_dir is not None and pdf_missing:
        warnings.warn(f"signoff.pdf not written: {pdf_missing}", RunWarning, stacklevel=2)
    return sheet
