"""rollerdyn from Python: drive dynamics of roller forming installations.

The same libraries as the ``rollerdyn`` command line, with its concepts: a scene (a scene file
and overrides), a run of the multibody or the reduced model, its time series, joint reactions,
summary and drive-sizing answers, the comparison of the two models, sweeps and optimizations.
Numbers are the command line's numbers, to the last bit.

    import rollerdyn as rd
    scene = rd.Scene.load("model/balanced-4cart.yaml")
    r = rd.simulate(scene.with_({"crank.offset_deg": 60}))
    r.timeseries.plot(x="t", y="omega_crank")      # pandas; units in r.units
    r.summary["delta"], r.sizing["motor"]["rms_over_nominal"]

Documentation: docs/python.md in the repository.
"""

import sys

try:
    import numpy  # noqa: F401
    import pandas  # noqa: F401
    from . import _core
except ImportError as error:  # another interpreter than the one the module was built for
    raise ImportError(
        f"rollerdyn runs with Debian's Python, /usr/bin/python3, which sees the numpy and pandas "
        f"that scripts/setup.sh installs; this is {sys.executable} ({error}). Run your script with "
        f"PYTHONPATH=build/python /usr/bin/python3") from error

from ._core import SceneError
from .analysis import Modes, MotorFit, fit_motor, modes
from .runs import Comparison, ResonanceWarning, Result, RunInterrupted, RunWarning, compare, signoff, simulate
from .scene import Scene, scene_keys
from .studies import IdentifyResult, OptimizeResult, identify, optimize, sweep

__version__ = _core.version
__all__ = [
    "Comparison",
    "IdentifyResult",
    "Modes",
    "MotorFit",
    "OptimizeResult",
    "ResonanceWarning",
    "Result",
    "RunInterrupted",
    "RunWarning",
    "Scene",
    "SceneError",
    "compare",
    "fit_motor",
    "identify",
    "modes",
    "optimize",
    "scene_keys",
    "signoff",
    "simulate",
    "sweep",
]
