"""identify from Python: the command line's identify.json, from a file or a DataFrame."""

import json

import numpy as np
import pytest

import rollerdyn as rd
from conftest import cli, model

FREE = ["coupling.stiffness", "coupling.damping"]
BOUNDS = {"coupling.stiffness": (2e4, 2e6), "coupling.damping": (500, 50000)}


@pytest.fixture(scope="module")
def measured(tmp_path_factory):
    """A start of the default scene with a stiffer, less damped coupling (reduced model, 2.5 s): its
    timeseries.csv is the measurement."""
    out = tmp_path_factory.mktemp("measured")
    cli("simulate", model("balanced-4cart.yaml"), "--model", "reduced", "--out", out, "--set", "simulation.t_end=2.5",
        "--set", "coupling.stiffness=150000", "--set", "coupling.damping=6000")
    return out / "timeseries.csv"


def test_identify_is_the_cli_identify(measured, tmp_path):
    cli("identify", model("balanced-4cart.yaml"), "--model", "reduced", "--data", measured, "--signals",
        "omega_crank,omega_motor", "--free", ",".join(FREE), "--bounds", "coupling.stiffness=2e4:2e6", "--bounds",
        "coupling.damping=500:50000", "--out", tmp_path)
    on_cli = json.loads((tmp_path / "identify.json").read_text())
    r = rd.identify(model("balanced-4cart.yaml"), measured, FREE, BOUNDS, signals=["omega_crank", "omega_motor"],
                    model="reduced")
    assert r.converged
    for ours, theirs in zip(r.summary["keys"], on_cli["keys"]):
        assert (ours["key"], ours["value"], ours["std"]) == (theirs["key"], theirs["value"], theirs["std"])
    assert r.summary["correlation"] == on_cli["correlation"]
    # Noise-free data made by the model itself at the scene's accuracy (1e-6): the truth to about that.
    assert r["coupling.stiffness"][0] == pytest.approx(150000, rel=1e-3)
    assert r["coupling.damping"][0] == pytest.approx(6000, rel=1e-3)
    assert list(r.fit.columns) == ["t", "omega_crank_measured", "omega_crank_model", "omega_motor_measured",
                                   "omega_motor_model"]


def test_identify_from_a_dataframe(measured):
    import pandas as pd
    df = pd.read_csv(measured)
    df.columns = [c.split("[")[0] for c in df.columns]  # bare names: identify adds rollerdyn's units
    r = rd.identify(model("balanced-4cart.yaml"), df[["t", "omega_crank", "omega_motor"]], FREE, BOUNDS,
                    model="reduced")
    assert r.converged
    assert r["coupling.stiffness"][0] == pytest.approx(150000, rel=1e-3)
    assert np.isfinite(r.fit["omega_crank_model"]).all()


def test_identify_errors_name_what_is_wrong(measured):
    with pytest.raises(ValueError, match="give bounds with --bounds coupling.stiffness=LOWER:UPPER"):
        rd.identify(model("balanced-4cart.yaml"), measured, ["coupling.stiffness"], model="reduced",
                    signals=["omega_crank"])
    with pytest.raises(ValueError, match="--signals omega_crnk: expected a column of"):
        rd.identify(model("balanced-4cart.yaml"), measured, ["coupling.stiffness"], BOUNDS, model="reduced",
                    signals=["omega_crnk"])
