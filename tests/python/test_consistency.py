"""The consistency harness's invariants bite: each is handed a consistent machine's outputs (it
must pass) and the same outputs with one planted contradiction, written by hand after the
findings of the trial that asked for the harness (it must fail). No rollerdyn run is needed:
the invariants are pure functions of the outputs (scripts/consistency_lib/invariants.py)."""

import copy
import pathlib
import sys

import pytest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "scripts"))

from consistency_lib import generator, invariants, parse  # noqa: E402


# --- a consistent machine, written by hand ----------------------------------------------------

def checks(heating=("pass", 0.512, "steady window"), breakdown=("pass", 0.431, "steady window"),
           coupling=("pass", 0.7, "whole run")):
    out = []
    for name, (verdict, value, window) in (("motor_heating", heating), ("motor_breakdown", breakdown),
                                            ("coupling", coupling)):
        out.append({"check": name, "what": f"{name} ratio, ≤ 1", "value": value, "verdict": verdict,
                    "window": window, "reason": "r"})
    return out


def summary(**kw):
    s = {"scene": "m", "model": "reduced", "motion": "turning", "status": "completed", "complete": True,
         "simulated_time": 10.0, "cpu_seconds": 0.1,
         "steady_state": {"reached": True, "relative_tolerance": 1e-3, "t_begin": 7.0, "t_end": 10.0},
         "omega_crank": {"mean": 10.1234, "min": 10.0, "max": 10.2}, "delta": 0.019757,
         "energy": {"motor_work": 1.0e5, "damping_dissipation": 1.0e3, "friction_dissipation": 0.0,
                    "load_work": 9.0e4, "kinetic_change": 9.0e3, "potential_change": 0.0, "residual": 0.01},
         "energy_residual_rel": 1.0e-7,
         "sizing": {"checks": checks(), "motor": {"slip": {"min": 0.02, "max": 0.03},
                                                 "torque_shaft": {"rms": 100.0, "peak": 150.0}},
                    "coupling": {"peak": 1000.0, "peak_whole_run": 2500.0, "t_peak_whole_run": 0.4445},
                    "joints": {"rod_end": {"worst": {"cart": 1, "L10_hours": None, "L10_revolutions": None},
                                           "per_cart": [{"cart": 1, "L10_hours": None, "L10_revolutions": None}]}}},
         "start_up": {"from_rest": True, "starts": True, "still_starting": False, "t_on": 0.0,
                      "run_up_time": 0.487, "start_end": 2.0, "verdict": "the drive starts",
                      "starting_torque_crank": 2000.0, "load_torque_start": 1000.0,
                      "steady": {"t_begin": 7.0}, "motor_torque": {"peak": 4000.0},
                      "coupling_torque": {"peak": 2559.9}, "rotor_energy_loss": 5.0e4},
         "warnings": []}
    s.update(kw)
    return s


def g4(x, f=".4g"):
    return "n/a" if x is None else format(x, f)


def console(s):
    """The console lines the invariants read, printed from a summary as `simulate` prints them."""
    lines = [f"scene        {s['scene']}  (model reduced, integrator cvode)",
             f"motion       {s['motion']}",
             f"status       {s['status']}",
             f"crank speed  mean {s['omega_crank']['mean']:.4g} rad/s, min {s['omega_crank']['min']:.4g}, "
             f"max {s['omega_crank']['max']:.4g}",
             f"             δ (unevenness) {g4(s['delta'])}, H (dynamics) 0.1, k_p (generalised) 0.1",
             "steady state " + ("reached" if s["steady_state"]["reached"] else "NOT reached"),
             f"energy       residual {s['energy']['residual']:.3g} J (relative {s['energy_residual_rel']:.2e})",
             "  checks (the window named decided each):"]
    for k in s["sizing"]["checks"]:
        lines.append(f"    {k['check']:<15} {g4(k['value'], '.3f'):>8}  {k['verdict'] or 'n/a':<14} decided by the "
                     f"{k['window']}")
        lines.append("      what; reason")
    return "\n".join(lines) + "\n"


def ctx(**kw):
    s = kw.pop("s", None) or summary()
    c = {"scene": {"simulation": {"accuracy": 1e-6, "output_step": 0.005}, "motor": {}}, "model": "reduced",
         "base": {"exit": 0, "stdout": console(s), "stderr": "", "summary": s}}
    c.update(kw)
    return c


# --- (a) ----------------------------------------------------------------------------------------

def test_a_passes_when_console_python_and_report_render_the_summary():
    s = summary()
    html = ("<style>.ok{background:#e3f4e3}.bad{background:#fde2e2}</style><h3>Checks</h3><table><tr><th>check</th></tr>"
            + "".join(f"<tr><td>{k['what']}</td><td class=\"n\">{k['value']:.3f}</td><td class=\"ok\">pass</td>"
                      f"<td>{k['window']}</td><td>r</td></tr>" for k in s["sizing"]["checks"]) + "</table>")
    py = {"summary": dict(copy.deepcopy(s), cpu_seconds=0.2), "text": console(s)}
    assert invariants.same_facts(ctx(s=s, python=py, report={"html": html, "summary": s})) == []


def test_a_fails_when_the_console_prints_another_verdict():
    c = ctx()
    c["base"]["stdout"] = c["base"]["stdout"].replace("0.512  pass", "0.512  FAIL")
    v = invariants.same_facts(c)
    assert any("motor_heating verdict 'FAIL'" in m for m in v), v


def test_a_fails_when_a_printed_number_is_not_the_summarys():
    c = ctx()
    c["base"]["stdout"] = c["base"]["stdout"].replace("δ (unevenness) 0.01976", "δ (unevenness) 0.01967")
    assert any("delta" in m for m in invariants.same_facts(c))


def test_a_fails_when_python_computes_another_number():
    s = summary()
    other = copy.deepcopy(s)
    other["delta"] = 0.0198
    v = invariants.same_facts(ctx(s=s, python={"summary": other, "text": None}))
    assert any("Python summary differs" in m and "delta" in m for m in v), v


def test_a_fails_when_the_report_shows_na_for_a_life_in_revolutions():
    # Finding 6: console and summary.json give the rod end's L10 in revolutions, the report n/a.
    s = summary()
    s["sizing"]["joints"]["rod_end"]["per_cart"][0]["L10_revolutions"] = 2.34e7
    html = ("<h3>Joints and bearings</h3><table><tr><th>joint</th></tr><tr><td>rod end (cart hinge)</td>"
            "<td class=\"n\">1</td><td>1</td><td>1</td><td>1</td><td>1</td><td>50.0</td><td class=\"n\">n/a</td>"
            "<td>none</td></tr></table>")
    v = invariants.same_facts(ctx(s=s, report={"html": html, "summary": s}))
    assert any("rod end" in m and "2.34e+07" in m.replace("23400000.0", "2.34e+07") for m in v), v


def test_a_fails_when_even_rows_hide_the_verdict_colours():
    # Finding 8: tr:nth-child(even) td (0,1,2) outranks .bad (0,1,0).
    css = "tr:nth-child(even) td{background:#fafafa}\n.ok{background:#e3f4e3}.bad{background:#fde2e2}"
    s = summary()
    v = invariants.same_facts(ctx(s=s, report={"html": f"<style>{css}</style>", "summary": s}))
    assert any("outranks the verdict colour" in m for m in v), v
    fixed = "tr:nth-child(even) td{background:#fafafa}\ntr td.ok{background:#e3f4e3}tr td.bad{background:#fde2e2}"
    v = invariants.same_facts(ctx(s=s, report={"html": f"<style>{fixed}</style>", "summary": s}))
    assert not any("outranks" in m for m in v), v


# --- (b) ----------------------------------------------------------------------------------------

def test_b_passes_when_the_longer_run_repeats_the_steady_answers():
    s2 = summary(simulated_time=20.0)
    s2["omega_crank"]["mean"] *= 1.0004  # within 2τ = 2e-3
    assert invariants.longer_run_same_verdicts(ctx(double={"exit": 0, "summary": s2})) == []


def test_b_fails_when_a_verdict_flips_with_run_length():
    # Finding 1: heating 2.644 FAIL at one run length, a pass at another.
    s2 = summary(simulated_time=20.0)
    s2["sizing"]["checks"] = checks(heating=("FAIL", 2.644, "steady window"))
    v = invariants.longer_run_same_verdicts(ctx(double={"exit": 0, "summary": s2}))
    assert any("motor_heating" in m and "FAIL" in m for m in v), v


def test_b_fails_when_delta_moves_beyond_the_steady_tolerance():
    s2 = summary(simulated_time=20.0, delta=0.0260)
    assert any("δ" in m for m in invariants.longer_run_same_verdicts(ctx(double={"exit": 0, "summary": s2})))


def test_b_judges_the_extremes_against_the_mean_speed():
    # A crank that nearly stops once per revolution: ω_min ≈ 0 moves by 4e-3 rad/s between the two
    # runs, 20 % of itself but 4e-4 of the mean speed: within what the steady criterion lets
    # through (2τ·|ω̄|, τ of the mean); 0.05 rad/s (5e-3 of ω̄) is not.
    s1, s2 = summary(), summary(simulated_time=20.0)
    s1["omega_crank"].update(mean=10.0, min=-0.020)
    s2["omega_crank"].update(mean=10.0, min=-0.016)
    assert invariants.longer_run_same_verdicts(ctx(s=s1, double={"exit": 0, "summary": s2})) == []
    s2["omega_crank"]["min"] = 0.03
    v = invariants.longer_run_same_verdicts(ctx(s=s1, double={"exit": 0, "summary": s2}))
    assert any("omega_crank.min" in m for m in v), v


def test_b_does_not_apply_without_a_steady_state():
    s = summary()
    s["steady_state"]["reached"] = False
    assert invariants.longer_run_same_verdicts(ctx(s=s, double={"exit": 0, "summary": summary()})) is None


# --- (c) ----------------------------------------------------------------------------------------

def test_c_passes_a_turning_steady_run():
    assert invariants.verdicts_within_preconditions(ctx()) == []


def test_c_fails_a_steady_window_verdict_without_a_steady_state():
    # Finding 1: "steady state NOT reached", yet motor_heating FAIL and motor_breakdown FAIL.
    s = summary()
    s["steady_state"]["reached"] = False
    s["sizing"]["checks"] = checks(heating=("FAIL", 2.644, "steady window"), breakdown=("FAIL", 1.0, "steady window"))
    v = invariants.verdicts_within_preconditions(ctx(s=s))
    assert any(m.startswith("motor_heating FAIL") for m in v) and any(m.startswith("motor_breakdown FAIL") for m in v)
    s["sizing"]["checks"] = checks(heating=("not applicable", None, "steady window"),
                                   breakdown=(None, None, "steady window"))
    assert invariants.verdicts_within_preconditions(ctx(s=s)) == []


def test_c_keeps_a_coupling_fail_of_a_drive_still_starting_but_no_other_verdict():
    # A peak over the whole run already above the rating stays above it however long the run.
    s = summary(motion="starting", delta=None)
    s["steady_state"]["reached"] = False
    s["sizing"]["checks"] = checks(heating=("not applicable", None, "run's last part (no steady state)"),
                                   breakdown=("not applicable", None, "run's last part (no steady state)"),
                                   coupling=("FAIL", 1.3, "whole run"))
    assert invariants.verdicts_within_preconditions(ctx(s=s)) == []
    s["sizing"]["checks"][2]["verdict"] = "pass"
    s["sizing"]["checks"][2]["value"] = 0.7
    assert any("coupling pass" in m for m in invariants.verdicts_within_preconditions(ctx(s=s)))


def test_c_fails_a_duty_heating_pass_for_a_drive_that_cannot_start():
    # Finding 3: at speed, 10 starts per hour, 1032 N·m of starting torque against 1393 N·m.
    s = summary()
    s["start_up"].update({"from_rest": False, "starts": False, "run_up_time": None, "rotor_energy_loss": None,
                          "motor_torque": {"peak": None}, "coupling_torque": {"peak": None},
                          "starting_torque_crank": 1032.0, "load_torque_start": 1393.0})
    c = ctx(s=s)
    c["scene"]["sizing"] = {"starts_per_hour": 10}
    v = invariants.verdicts_within_preconditions(c)
    assert any("cannot start from rest" in m for m in v), v
    s["start_up"]["starting_torque_crank"] = 2000.0  # it could start: still no start heat in the run
    assert any("holds no start" in m for m in invariants.verdicts_within_preconditions(c))


def test_c_passes_duty_heating_of_a_ramped_start_that_ran_up():
    # A converter's torque at switch-on (low frequency) is below the start-angle load, yet the
    # run shows the drive starting: its duty heating may pass.
    s = summary()
    s["start_up"].update({"starting_torque_crank": 261.8, "load_torque_start": 1305.0})
    c = ctx(s=s)
    c["scene"].update({"sizing": {"starts_per_hour": 1}, "motor": {"start": {"method": "frequency_converter"}}})
    assert invariants.verdicts_within_preconditions(c) == []


def test_c_fails_lives_and_stability_of_a_stalled_drive():
    # Finding 7: guide roller 1.25e7 h and "the steady motion is stable" for a stalled drive.
    s = summary(motion="stalled", delta=None)
    s["sizing"]["joints"] = {"guide_roller_front": {"per_cart": [{"cart": 1, "L10_hours": 1.25e7}]}}
    s["resonance_modal"] = {"applicable": True, "floquet_verdict": "stable"}
    v = invariants.verdicts_within_preconditions(ctx(s=s))
    assert any("L10_hours" in m for m in v) and any("modal analysis" in m for m in v), v


def test_c_fails_start_answers_of_a_run_that_begins_at_speed():
    s = summary()
    s["start_up"]["from_rest"] = False
    v = invariants.verdicts_within_preconditions(ctx(s=s))
    assert any("run_up_time" in m for m in v), v


# --- (d) ----------------------------------------------------------------------------------------

STATUS_PEAKS = ("the drive stalled: starting torque at the crank 2471 N·m (the motor law's torque at standstill × u·η) "
                "against a load torque of 1393 N·m at the start angle 0 deg; breakdown torque at the crank 4500 N·m "
                "against a load torque of 900 N·m averaged over a revolution: the motor can start and carry the mean "
                "load, so the stall comes from the load peaks near a dead centre together with the inertia")
START_VERDICT = ("the drive does not start: its starting torque 823.5 N·m at the crank (the motor law's torque at "
                 "standstill under the supply at switch-on, star_delta, × u·η) is below the load torque 1393 N·m at "
                 "the start angle 0 deg")


def stalled(status, verdict, reason):
    s = summary(motion="stalled", status=status, delta=None)
    s["start_up"].update({"starts": False, "run_up_time": None, "verdict": verdict})
    s["sizing"]["checks"][1]["reason"] = reason
    return s


def test_d_fails_when_status_and_start_up_block_name_different_causes():
    # Finding 2: the status blames the dead-centre peaks with 2471 N·m, the start-up block 823.5 N·m.
    s = stalled(STATUS_PEAKS, START_VERDICT, "the drive does not turn (stalled): the motor's starting torque 823.5 N·m "
                "at the crank is below the load 1393 N·m at the start angle")
    v = invariants.one_stall_cause(ctx(s=s))
    assert any("stall causes differ" in m for m in v) and any("starting torques" in m for m in v), v


def test_d_passes_when_every_place_names_the_same_cause():
    status = ("the drive stalled: starting torque at the crank 823.5 N·m (...) against a load torque of 1393 N·m at "
              "the start angle 0 deg; ...: the starting torque is below the load at the start angle, so the motor "
              "cannot turn the crank forwards from there")
    s = stalled(status, START_VERDICT, "the drive does not turn (stalled): the motor's starting torque 823.5 N·m at "
                "the crank is below the load 1393 N·m at the start angle")
    assert invariants.one_stall_cause(ctx(s=s)) == []


# --- (e) ----------------------------------------------------------------------------------------

def sweep(vertex_delta):
    return {"param": "crank.offset_deg", "metric": "delta",
            "stdout": "minimum of delta = 0.0008 at crank.offset_deg=60; parabola through the neighbours: "
                      "crank.offset_deg = 61.1079, delta = 0.00076513",
            "json": {"optimum": {"parabola": {"parameter": 61.1079, "value": 0.00076513}}},
            "vertex_run": summary(delta=vertex_delta)}


def test_e_fails_an_interpolated_optimum_that_a_run_does_not_reproduce():
    # Finding 5: delta = 0.00076513 printed, 0.01696 when run (22x).
    v = invariants.estimates_reproduce(ctx(sweep=sweep(0.01696)))
    assert v and "22.2x" in v[0], v


def test_e_passes_an_optimum_that_reproduces():
    assert invariants.estimates_reproduce(ctx(sweep=sweep(0.000770))) == []


def test_e_fails_a_flywheel_proposal_that_misses_its_target():
    fw = {"proposed": 1103.0, "target": 0.05, "summary": summary(delta=0.075), "stdout": "a flywheel of 1103 kg·m²"}
    assert invariants.estimates_reproduce(ctx(flywheel=fw))
    fw["summary"] = summary(delta=0.052)
    assert invariants.estimates_reproduce(ctx(flywheel=fw)) == []


# --- (f) ----------------------------------------------------------------------------------------

def test_f_passes_a_closed_audit_and_fails_an_open_one():
    assert invariants.energy_closes(ctx()) == []
    s = summary()
    s["energy"]["residual"] = 500.0  # 5e-3 of the motor work, above 1000·1e-6
    assert invariants.energy_closes(ctx(s=s))


def test_f_judges_a_drive_that_hardly_moves_against_a_kilojoule():
    # A stall: terms of 1.7 J, residual 1.7e-3 J (1e-3 of the terms, 1.7e-6 of 1 kJ).
    s = summary(motion="stalled", delta=None)
    s["energy"] = {"motor_work": 1.687, "load_work": 1.5, "kinetic_change": 0.19, "residual": -0.0017}
    assert invariants.energy_closes(ctx(s=s)) == []
    s["energy"]["residual"] = -1.5
    assert invariants.energy_closes(ctx(s=s))


def baranov_ctx(residual, residual_half):
    c = ctx()
    c["scene"]["reduced"] = {"integrator": "baranov", "baranov_step_deg": 1.0}
    c["base"]["summary"]["energy"] = {"motor_work": 3630.0, "kinetic_change": 2372.0, "residual": residual}
    half = summary()
    half["energy"] = {"motor_work": 3630.0, "kinetic_change": 2372.0, "residual": residual_half}
    c["half_step"] = {"exit": 0, "summary": half}
    return c


def test_f_holds_baranovs_scheme_to_its_first_order_error():
    # The scheme's residual is O(h): 41 J of 3630 J (1.1e-2) at 1° is within h = 1.75e-2 and halves
    # at 0.5°; a residual that stays when the step halves is a term the audit misses, and 70 J
    # (1.9e-2) is beyond h.
    assert invariants.energy_closes(baranov_ctx(41.0, 20.5)) == []
    assert invariants.energy_closes(baranov_ctx(41.0, 40.0))
    assert invariants.energy_closes(baranov_ctx(70.0, 35.0))


# --- (g) ----------------------------------------------------------------------------------------

def test_g_fails_a_key_that_changes_nothing_silently():
    p = {"key": "initial.twist", "old": "0.0", "new": "0.001", "exit": 0, "stdout": "", "stderr": "",
         "summary": dict(copy.deepcopy(summary()), cpu_seconds=0.3)}
    v = invariants.keys_take_effect(ctx(perturb=p))
    assert v and "initial.twist" in v[0]


def test_g_passes_a_key_that_changes_a_figure_or_is_reported():
    changed = summary(delta=0.0199)
    assert invariants.keys_take_effect(ctx(perturb={"key": "crank.radius", "old": "0.2", "new": "0.22",
                                                    "summary": changed})) == []
    warned = dict(summary(), warnings=["initial.twist has no effect with a rigid coupling"])
    assert invariants.keys_take_effect(ctx(perturb={"key": "initial.twist", "old": "0", "new": "0.001",
                                                    "summary": warned, "stderr": "", "stdout": ""})) == []


# --- (h) ----------------------------------------------------------------------------------------

def test_h_passes_equal_models_and_fails_different_ones():
    same = summary(model="multibody")
    same["omega_crank"]["mean"] *= 1 + 1e-5
    assert invariants.models_agree(ctx(other={"model": "multibody", "exit": 0, "summary": same})) == []
    off = summary(model="multibody")
    off["omega_crank"]["mean"] *= 1.01
    off["sizing"]["checks"] = checks(coupling=("FAIL", 1.3, "whole run"))
    v = invariants.models_agree(ctx(other={"model": "multibody", "exit": 0, "summary": off}))
    assert any("omega_crank.mean" in m for m in v) and any("coupling" in m for m in v), v


def test_h_judges_a_creeping_crank_against_the_synchronous_crank_speed():
    # A stalled crank creeps at 0.0089 rad/s in both models; 2e-3 of that is 2e-6 of ω0/u.
    a, b = summary(motion="stalled", delta=None), summary(motion="stalled", delta=None, model="multibody")
    a["omega_crank"].update({"min": 0.008863758}), b["omega_crank"].update({"min": 0.008882281})
    c = ctx(s=a, other={"model": "multibody", "exit": 0, "summary": b})
    c["scene"].update({"motor": {"omega_sync": 104.72}, "reducer": {"ratio": 9.8}})
    assert invariants.models_agree(c) == []
    b["omega_crank"]["min"] = 0.2  # 1.8e-2 of ω0/u
    assert any("omega_crank.min" in m for m in invariants.models_agree(c))


# --- (i) ----------------------------------------------------------------------------------------

def shifted(run_up, start_end, t_peak):
    s = summary()
    s["start_up"].update({"t_on": 0.5, "run_up_time": run_up, "start_end": start_end,
                          "steady": {"t_begin": 7.25}})
    s["sizing"]["coupling"]["t_peak_whole_run"] = t_peak
    return {"delta": 0.25, "exit": 0, "summary": s, "omega_before_on": 0.0}


def test_i_passes_when_every_start_answer_moves_with_the_switch_on():
    base = summary()
    base["start_up"]["t_on"] = 0.25
    base["start_up"]["steady"]["t_begin"] = 7.0
    assert invariants.switch_on_shift(ctx(s=base, shift=shifted(0.487, 2.25, 0.6945))) == []


def test_i_fails_a_run_up_time_measured_from_t_zero():
    # Finding 11: with t_on = 0.5 s the run-up reads 1.415 s instead of 0.915 s.
    base = summary()
    base["start_up"].update({"t_on": 0.25, "run_up_time": 1.165})
    base["start_up"]["steady"]["t_begin"] = 7.0
    v = invariants.switch_on_shift(ctx(s=base, shift=shifted(1.415, 2.25, 0.6945)))
    assert any("run-up time" in m for m in v), v


def test_i_does_not_apply_when_the_crank_moved_before_the_switch_on():
    sh = shifted(0.487, 2.25, 0.6945)
    sh["omega_before_on"] = 0.3
    assert invariants.switch_on_shift(ctx(shift=sh)) is None


# --- the generator and the readers ------------------------------------------------------------

def test_generator_is_reproducible_and_varies_what_the_issue_lists():
    a, b = generator.generate(7), generator.generate(7)
    assert a.scene == b.scene and a.model == b.model and a.plan == b.plan
    ms = [generator.generate(s) for s in range(200)]
    assert {m.scene["carts"]["count"] for m in ms} == set(range(1, 9))
    assert {m.scene["motor"]["model"] for m in ms} == set(generator.MOTOR_LAWS)
    assert {m.scene["motor"]["start"]["method"] for m in ms} == set(generator.START_METHODS)
    assert {m.scene["coupling"]["type"] for m in ms} == {"elastic", "rigid"}
    assert {m.model for m in ms} == {"multibody", "reduced"}
    assert any(m.scene["initial"]["crank_speed"] > 0 for m in ms) and any(
        m.scene["initial"]["crank_speed"] == 0 for m in ms)
    assert any(isinstance(m.scene["carts"]["mass"], list) for m in ms)
    assert any(m.scene["flywheel"]["inertia"] > 0 for m in ms)
    assert any("stop" in m.scene["motor"] for m in ms)
    assert min(m.scene["simulation"]["t_end"] for m in ms) < 1.0 < 10.0 < max(m.scene["simulation"]["t_end"] for m in ms)


@pytest.mark.parametrize("printed,value,ok", [("0.01976", 0.019757, True), ("0.01976", 0.019745, False),
                                              ("2.34e+07", 2.3449e7, True), ("n/a", None, True), ("n/a", 1.0, False),
                                              ("1.00e-07", 1.004e-7, True)])
def test_printed_numbers_agree_to_half_a_unit_in_their_last_digit(printed, value, ok):
    assert parse.agrees_with_print(printed, value) is ok
