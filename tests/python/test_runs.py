"""Results of one run: tables with units, the summary's sizing answers, HTML for Jupyter, and
the reactions left out when the scene says so."""

import json

import pytest

import rollerdyn as rd
from conftest import model


def short(scene_file, **changes):
    return rd.Scene.load(model(scene_file)).with_({"simulation.t_end": 2, **changes})


def test_tables_summary_and_units():
    r = rd.simulate(short("balanced-4cart.yaml"))
    ts, rx = r.timeseries, r.reactions
    assert list(ts.columns[:5]) == ["t", "phi_motor", "phi_crank", "omega_motor", "omega_crank"]
    assert ts["t"].iloc[-1] == 2.0 and len(ts) == 401
    assert ts.attrs["units"]["omega_crank"] == "rad/s" and r.units["F_rod_1"] == "N"
    assert rx is not None and "N_front_4" in rx.columns
    assert r.summary["complete"] is True and r.summary["model"] == "multibody"
    assert set(r.sizing) >= {"motor", "flywheel", "coupling", "joints"}
    assert r.sizing["motor"]["torque_shaft"]["rms"] > 0
    text = str(r)
    assert "drive sizing over the " in text and "crank speed" in text


def test_html_has_the_report_tables():
    r = rd.simulate(short("recuperative-2cart.yaml"), model="reduced")
    h = r._repr_html_()
    for part in ("Summary metrics", "<table>", "Joint reactions over the steady window", "recuperative-2cart"):
        assert part in h
    assert "<table>" in rd.Scene.load(model("recuperative-2cart.yaml"))._repr_html_()


def test_no_reactions_when_the_scene_leaves_them_out():
    r = rd.simulate(short("balanced-4cart.yaml", **{"simulation.reactions": False}))
    assert r.reactions is None
    assert r.summary["reactions"] == {}


def test_compare_runs_both_models():
    c = rd.compare(short("recuperative-2cart.yaml"))
    assert c.multibody.model == "multibody" and c.reduced.model == "reduced"
    assert "omega_crank_multibody" in c.table.columns
    d = c.differences()
    assert d.loc["omega_crank", "max_rel_diff"] < 1e-2
    assert "max_rel_diff" in str(c) or "omega_crank" in str(c)


def test_write_refuses_a_file_as_folder(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    r = rd.simulate(short("recuperative-2cart.yaml"), model="reduced")
    try:
        r.write(blocker / "out")
    except RuntimeError as e:
        assert "out_dir" in str(e)
    else:
        raise AssertionError("write into a path below a file must fail")


def test_start_up_answers_and_friction_warnings_as_the_summary_has_them():
    # The default scene starts from rest: the start-up answers, their console block and the
    # report's section; the sizing's start heat is their rotor energy loss.
    r = rd.simulate(short("balanced-4cart.yaml"), model="reduced")
    su = r.start_up
    assert su is not None and su == r.summary["start_up"]
    assert su["rotor_energy_loss"] > 0
    assert r.sizing["motor"]["whole_run"]["start_heat"] == su["rotor_energy_loss"]
    assert "start-up" in str(r).lower() and su["verdict"] in str(r)
    assert "Start-up" in r._repr_html_()
    # Guide friction f = 0.3, motor off, from 10.42 rad/s: the self-locking warning reaches
    # warnings as it reaches summary.json, and friction brings the machine to rest.
    f = rd.simulate(short("balanced-4cart.yaml", **{"loads.guide_friction.coefficient": 0.3, "motor.enabled": False,
                                                    "initial.crank_speed": 10.42}), model="reduced")
    assert f.start_up is None
    assert f.guide_friction == f.summary["guide_friction"] and f.guide_friction["self_locking_index"] > 0.1
    assert any("self-locking" in w for w in f.warnings)
    assert all(w in f.summary["warnings"] for w in f.warnings)
    assert f.summary["motion"] == "at_rest" and not f.complete


def test_a_summary_key_that_does_not_exist_says_where_the_value_is():
    # The notebook trial looked for summary["steady_state_reached"] and got a bare KeyError.
    r = rd.simulate(short("balanced-4cart.yaml"), model="reduced")
    assert isinstance(r.summary["steady_state"]["reached"], bool)
    with pytest.raises(KeyError) as e:
        r.summary["steady_state_reached"]
    assert 'summary["steady_state"]["reached"]' in str(e.value)
    with pytest.raises(KeyError) as e:
        r.summary["sizing"]["motor"]["rms_over_nominl"]  # misspelt, one level down
    assert 'summary["sizing"]["motor"]["rms_over_nominal"]' in str(e.value)
    # Still the summary.json dict: equal to it, serialisable, .get works as for a dict.
    assert r.summary.get("no_such_key") is None
    assert json.loads(json.dumps(r.summary)) == r.summary


def test_fatigue_and_coupling_selection_reach_python_as_the_summary_has_them():
    """The damage per start and the DIN 740-2 checks are the summary's, rendered in text and HTML."""
    r = rd.simulate(short("balanced-4cart.yaml", **{
        "sizing.fatigue.coupling_torque.endurance_amplitude": 1000, "sizing.fatigue.coupling_torque.knee_cycles": 2e6,
        "sizing.fatigue.coupling_torque.slope": 6, "sizing.fatigue.required_starts": 1e5,
        "sizing.coupling.max_torque": 1.0, "simulation.t_end": 10}), model="reduced")  # the start settles
    g = r.sizing["fatigue"]["signals"]["coupling_torque"]
    assert g["per_start"]["applies"] and g["damage_per_start"] > 0
    assert g["starts_to_failure"] == pytest.approx(1 / g["damage_per_start"])
    checks = {c["check"]: c for c in r.sizing["checks"]}
    assert checks["fatigue_starts_coupling_torque"]["verdict"] in ("pass", "FAIL")
    # a 1 N·m T_Kmax is exceeded by any start
    assert checks["coupling_max_torque"]["verdict"] == "FAIL"
    assert "per start" in str(r) and "Coupling selection after DIN 740-2" in r._repr_html_()


def test_gear_spectrum_and_motor_duty_reach_python_as_the_summary_has_them():
    """K_A after ISO 6336-6 and the starts after IEC 60034-1 are the summary's, rendered in text and HTML."""
    r = rd.simulate(short("balanced-4cart.yaml", **{
        "sizing.reducer.application_factor": 1.25, "sizing.reducer.max_torque": 1.0, "sizing.starts_per_hour": 30,
        "sizing.motor.locked_rotor_time": 12, "sizing.motor.no_load_starts": 500, "simulation.t_end": 10}),
        model="reduced")
    g, m = r.sizing["gear"], r.sizing["motor_duty"]
    assert g["duty"]["applies"] and g["application_factor"] == pytest.approx(
        g["duty"]["equivalent_torque"] / g["nominal_torque"])
    assert m["duty_type"] == "S4" and m["start_heat"] == r.summary["start_up"]["rotor_energy_loss"]
    checks = {c["check"]: c for c in r.sizing["checks"]}
    assert checks["gear_max_torque"]["verdict"] == "FAIL"  # a 1 N·m T_2max is exceeded by any start
    assert checks["gear_rated_torque"]["verdict"] == "not applicable"
    assert "sizing.reducer.rated_torque" in checks["gear_rated_torque"]["reason"]
    assert checks["motor_starts_per_hour"]["verdict"] in ("pass", "FAIL")
    assert "reducer load spectrum" in str(r) and "Motor duty after IEC 60034-1" in r._repr_html_()
