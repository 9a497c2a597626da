"""The drive and the motor of a scene on their own: modes (``rollerdyn modes``) and fit_motor
(``rollerdyn motor``)."""

import html
import os
import warnings

import pandas as pd

from . import _core
from ._tables import frame
from .runs import ResonanceWarning, write_outputs
from .scene import as_scene


class Modes:
    """What ``rollerdyn modes`` writes: ``summary`` (modes.json: steady motion, Floquet
    multipliers, frozen-angle band of each mode, resonance warnings), ``frozen`` (frozen.csv),
    ``campbell`` (campbell.csv), ``stability`` (stability.csv, every chart in long format);
    ``write(dir)`` writes those files (and the figures)."""

    def __init__(self, data):
        self._d = data
        self.summary = data.json()
        self.frozen = frame(data.frozen())
        self.campbell = frame(data.campbell())
        self.stability = frame(data.stability())

    @property
    def warnings(self):
        """Resonance warnings of the analysis (also issued as ResonanceWarning)."""
        return list(self._d.warnings)

    def write(self, out_dir, figures=True):
        """Writes modes.json, frozen.csv, campbell.csv and stability.csv into ``out_dir``
        (created), as ``rollerdyn modes --out out_dir``; with ``figures`` also its figures."""
        return write_outputs(self._d, out_dir, figures)

    def __str__(self):
        return self._d.text()

    def _repr_html_(self):
        return f"<pre>{html.escape(self._d.text())}</pre>"


def modes(scene, *, dampings=(), mark_dampings=(), grid=(16, 10), speeds=21, stiffness=None, charts=True,
          multibody=True):
    """Torsional natural frequencies, Floquet stability of the steady motion, Campbell diagram
    and stability charts of the drive, as ``rollerdyn modes`` with the same options:
    ``dampings`` (--damping: k [N·m·s/rad] of a stiffness x speed chart each; default the
    scene's), ``mark_dampings`` (--mark-damping), ``grid`` (--grid: (stiffness, speed or damping)
    points of the charts), ``speeds`` (--speeds: of the Campbell diagram), ``stiffness``
    (--stiffness: (lo, hi) in N·m/rad; default 0.05 ... 5 times the scene's c), ``charts=False``
    (--no-charts, the slow part), ``multibody=False`` (--no-multibody). The GIL is released."""
    s = as_scene(scene)
    c, y = grid
    data = _core.modes(s._s, [float(k) for k in dampings], [float(k) for k in mark_dampings], int(c), int(y),
                       int(speeds), None if stiffness is None else (float(stiffness[0]), float(stiffness[1])),
                       bool(charts), bool(multibody))
    result = Modes(data)
    for w in result.warnings:
        warnings.warn(w, ResonanceWarning, stacklevel=2)
    return result


class MotorFit:
    """What ``rollerdyn motor`` writes: ``summary`` (motor.json: Kloss's data, the machine per
    phase of the equivalent star, the fit, the catalogue points), ``machine`` (its circuit, None
    without motor.circuit or motor.catalogue), ``catalogue`` (motor_catalogue.csv: the model
    beside the catalogue and Kloss at every catalogue point; None without a catalogue) and
    ``curves`` (motor_curves.csv: torque and current against slip of every model)."""

    def __init__(self, data):
        self._d = data
        self.summary = data.json()
        self.curves = frame(data.curves())

    @property
    def machine(self):
        return self.summary.get("machine")

    @property
    def catalogue(self):
        points = self.summary.get("catalogue_points")
        return None if points is None else pd.DataFrame(points)

    def write(self, out_dir):
        """Writes motor.json, motor_curves.csv, motor_catalogue.csv and the figures into
        ``out_dir`` (created), as ``rollerdyn motor --out out_dir``."""
        note = self._d.write(os.fspath(out_dir))
        if note:
            print(note)
        return out_dir

    def __str__(self):
        return self._d.text()

    def _repr_html_(self):
        table = self.catalogue
        return f"<pre>{html.escape(self._d.text())}</pre>" + ("" if table is None else table.to_html(index=False))


def fit_motor(scene):
    """The scene's induction motor on its own, as ``rollerdyn motor``: the equivalent circuit
    from motor.circuit, or fitted to motor.catalogue by weighted least squares (Pedra (2008)),
    the model at every catalogue point beside the catalogue value and Kloss's, and the steady
    torque-slip and current-slip curves of every motor model (docs/motor.md)."""
    return MotorFit(_core.fit_motor(as_scene(scene)._s))
