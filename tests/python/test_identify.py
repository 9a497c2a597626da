"""identify from Python: the command line's identify.json, from a file or a DataFrame."""

import json

import numpy as np
import pandas as pd
import pytest

import rollerdyn as rd
from conftest import cli, model

FREE = ["coupling.stiffness", "coupling.damping"]
BOUNDS = {"coupling.stiffness": (2e4, 2e6), "coupling.damping": (500, 50000)}


@pytest.fixture(scope="module")
def measured(tmp_path_factory):
    """A start of the default scene with a softer, less damped coupling (reduced model, 2.5 s): its
    crank and motor speeds with 0.2 % Gaussian noise (of each signal's RMS value, fixed seed) are
    the measurement, written as the command line's CSV (header cells name[unit])."""
    out = tmp_path_factory.mktemp("measured")
    cli("simulate", model("balanced-4cart.yaml"), "--model", "reduced", "--out", out, "--set", "simulation.t_end=2.5",
        "--set", "coupling.stiffness=150000", "--set", "coupling.damping=6000")
    df = pd.read_csv(out / "timeseries.csv")
    df = df[["t[s]", "omega_crank[rad/s]", "omega_motor[rad/s]"]].copy()
    rng = np.random.default_rng(5)
    for c in df.columns[1:]:
        df[c] += 0.002 * np.sqrt((df[c] ** 2).mean()) * rng.standard_normal(len(df))
    df.to_csv(out / "measured.csv", index=False, float_format="%.12g")
    return out / "measured.csv"


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
    # The truth within 3 standard uncertainties (a Gaussian estimate misses that in 0.3 % of cases).
    for key, truth in (("coupling.stiffness", 150000), ("coupling.damping", 6000)):
        value, std = r[key]
        assert abs(value - truth) < 3 * std, (key, value, std)
    assert list(r.fit.columns) == ["t", "omega_crank_measured", "omega_crank_model", "omega_motor_measured",
                                   "omega_motor_model"]


def test_identify_from_a_dataframe(measured):
    df = pd.read_csv(measured)
    df.columns = [c.split("[")[0] for c in df.columns]  # bare names: identify adds rollerdyn's units
    from_frame = rd.identify(model("balanced-4cart.yaml"), df, FREE, BOUNDS, model="reduced")
    from_file = rd.identify(model("balanced-4cart.yaml"), measured, FREE, BOUNDS, model="reduced")
    assert from_frame.converged
    # The same numbers (the frame's text keeps every digit of the file's 12 significant ones).
    assert from_frame.summary["keys"] == from_file.summary["keys"]
    assert np.isfinite(from_frame.fit["omega_crank_model"]).all()


def test_identify_errors_name_what_is_wrong(measured):
    with pytest.raises(ValueError, match="give bounds with --bounds coupling.stiffness=LOWER:UPPER"):
        rd.identify(model("balanced-4cart.yaml"), measured, ["coupling.stiffness"], model="reduced",
                    signals=["omega_crank"])
    with pytest.raises(ValueError, match="--signals omega_crnk: expected a column of"):
        rd.identify(model("balanced-4cart.yaml"), measured, ["coupling.stiffness"], BOUNDS, model="reduced",
                    signals=["omega_crnk"])
