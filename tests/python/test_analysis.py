"""The drive's modes and the motor from Python are the command line's: simulate(modes=True) gives
`simulate --modes`' summary and files, rd.modes gives `rollerdyn modes`' files, rd.fit_motor gives
`rollerdyn motor`'s; the run's warnings are the lines the command line prints on stderr, issued
as RunWarning and ResonanceWarning."""

import json
import warnings

import pytest

import rollerdyn as rd
from conftest import cli, model

# Measured, so they differ between any two runs; motor_fit says whether this process fitted the
# motor's circuit or read it from the fit cache.
TIMING_KEYS = {"cpu_seconds", "real_time_factor", "motor_fit"}


def without_timing(value):
    """`value` with every CPU-time key left out, at any depth."""
    if isinstance(value, dict):
        return {k: without_timing(v) for k, v in value.items() if k not in TIMING_KEYS}
    if isinstance(value, list):
        return [without_timing(v) for v in value]
    return value


def test_simulate_with_modes_is_simulate_dash_dash_modes(tmp_path):
    sets = ["--set", "simulation.t_end=6"]
    cli("simulate", model("balanced-4cart.yaml"), "--model", "reduced", "--modes", *sets, "--out", tmp_path / "cli")
    scene = rd.Scene.load(model("balanced-4cart.yaml")).with_({"simulation.t_end": 6})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = rd.simulate(scene, model="reduced", modes=True)
    summary = json.loads((tmp_path / "cli" / "summary.json").read_text())
    assert "modes" in r.summary and "order_spectrum" in r.summary and "resonance_modal" in r.summary
    assert without_timing(r.summary) == without_timing(summary)
    assert r.modes == r.summary["modes"]
    assert r.frozen is not None and "p_torsional_reduced" in r.frozen.columns
    assert r.spectrum is not None and r.campbell is not None
    r.write(tmp_path / "py")
    for f in ("frozen.csv", "campbell.csv", "spectrum.csv", "timeseries.csv"):
        assert (tmp_path / "py" / f).read_bytes() == (tmp_path / "cli" / f).read_bytes(), f
    modes_json = [json.loads((tmp_path / d / "modes.json").read_text()) for d in ("cli", "py")]
    assert without_timing(modes_json[0]) == without_timing(modes_json[1])


def test_run_warnings_are_the_command_lines_and_are_issued(tmp_path):
    # The shipped four-cart scene reads the roller forces as printed: the load does no net work.
    r_cli = cli("simulate", model("balanced-4cart.yaml"), "--model", "reduced", "--out", tmp_path)
    scene = rd.Scene.load(model("balanced-4cart.yaml"))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        r = rd.simulate(scene, model="reduced")
    printed = [line[len("rollerdyn: warning: "):] for line in r_cli.stderr.splitlines()
               if line.startswith("rollerdyn: warning: ")]
    assert r.warnings == printed == r.summary["warnings"]
    assert any("no net work" in w for w in r.warnings)
    # The scene gives keys this run does not read (the rollers' half spacing with equal normals,
    # the winding connection): named in one more warning, issued like the load's.
    assert any(w.startswith("scene keys without effect") and "carts.geometry.a" in w for w in r.warnings)
    # Its front guide reactions change sign (the rollers lift off): a third warning, issued too.
    assert any(w.startswith("guide reactions change sign") for w in r.warnings)
    assert [str(w.message) for w in caught if issubclass(w.category, rd.RunWarning)] == r.warnings


def test_modes_is_rollerdyn_modes(tmp_path):
    cli("modes", model("balanced-4cart.yaml"), "--no-charts", "--no-multibody", "--speeds", "7",
        "--out", tmp_path / "cli")
    m = rd.modes(model("balanced-4cart.yaml"), charts=False, multibody=False, speeds=7)
    m.write(tmp_path / "py", figures=False)
    for f in ("frozen.csv", "campbell.csv"):
        assert (tmp_path / "py" / f).read_bytes() == (tmp_path / "cli" / f).read_bytes(), f
    assert without_timing(m.summary) == without_timing(json.loads((tmp_path / "cli" / "modes.json").read_text()))
    assert m.summary["steady_motion"]["stable"]
    assert "steady motion" in str(m)
    with pytest.raises(ValueError, match="rigid"):
        rd.modes(model("recuperative-2cart.yaml"), charts=False, multibody=False, stiffness=(1e4, 1e5))


def test_fit_motor_is_rollerdyn_motor(tmp_path):
    r_cli = cli("motor", model("energy-balanced-3cart.yaml"), "--out", tmp_path / "cli")
    fit = rd.fit_motor(model("energy-balanced-3cart.yaml"))
    assert str(fit) in r_cli.stdout  # the same table, printed by the command before its file list
    fit.write(tmp_path / "py")
    for f in ("motor.json", "motor_curves.csv", "motor_catalogue.csv"):
        assert (tmp_path / "py" / f).read_bytes() == (tmp_path / "cli" / f).read_bytes(), f
    # The 4A160M6U3's printed torques are met (docs/motor.md: within 0.75 %).
    cat = fit.catalogue.set_index("symbol")
    for symbol in ("M_n", "M_s", "M_k"):
        assert abs(cat.loc[symbol, "relative_error"]) < 0.0075, symbol
    assert fit.machine["cages"] == 2
    assert fit.curves.attrs["units"]["M_circuit"] == "N*m"
    # Without circuit or catalogue: Kloss only, as the command says.
    kloss = rd.fit_motor(model("recuperative-2cart.yaml"))
    assert kloss.machine is None and kloss.catalogue is None


def test_a_first_estimate_the_modal_analysis_refutes_is_no_warning():
    # Six carts at 60°: the first estimate finds p0 near order 6, the modal analysis refutes it
    # (damping ratio 0.82): one answer, no ResonanceWarning, and the verdict says why at the run's ω.
    scene = rd.Scene.load(model("balanced-4cart.yaml")).with_(
        {"carts.count": 6, "crank.offset_deg": 60, "simulation.t_end": 6})
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        r = rd.simulate(scene, model="reduced")
    resonance = [str(w.message) for w in caught if issubclass(w.category, rd.ResonanceWarning)]
    assert not resonance, resonance
    assert r.resonance_verdict.startswith("resonance verdict: the modal analysis refutes the first estimate")
    assert r.summary["resonance_verdict"]["verdict"] == "no resonance"
    assert r.summary["resonance_verdict"]["omega"] == r.summary["omega_crank"]["mean"]