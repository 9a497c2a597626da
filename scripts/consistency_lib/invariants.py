"""The invariants (a)-(i) of the consistency harness, each a pure function of one machine's
outputs (plain dicts and strings, no runs), so that a test can hand each one a doctored output
and see it fail.

Every function takes the machine's context `ctx` (runner.py builds it; the keys are described in
CONTEXT below) and returns None when the invariant does not apply to this machine (its input is
missing: no report was made, no steady state was reached, ...), else the list of violations
found, each one line naming the figures that contradict each other (empty: consistent).

CONTEXT
  scene      the scene dict as written to scene.yaml (generator.py)
  model      "multibody" or "reduced"
  base       the run of the machine: {"exit", "stdout", "stderr", "summary"}
  python     rd.simulate of the same scene and model: {"summary", "text"}
  report     `rollerdyn report` of the scene: {"html", "summary"} (the multibody model)
  double     the run with 2·t_end: {"exit", "stdout", "summary"}
  shift      the run with the switch-on (and every later event) shifted by "delta" seconds and
             t_end longer by as much: {"delta", "exit", "summary", "omega_before_on"}
  other      the other model on the same scene: {"model", "exit", "summary"}
  perturb    one given key changed: {"key", "old", "new", "exit", "stdout", "stderr", "summary"}
  sweep      a sweep with --minimize: {"param", "metric", "stdout", "json", "vertex_run"}
  flywheel   the run with the proposed flywheel: {"proposed", "target", "summary", "stdout"}
"""

import math
import re

from . import parse

BREAKDOWN_LIMIT = 0.95 ** 2  # the breakdown check's limit on peak |M| / M_kr (docs/verdicts.md)
LIMITS = {"motor_heating": 1.0, "motor_breakdown": BREAKDOWN_LIMIT, "coupling": 1.0}
NO_VERDICT = (None, "not applicable")

# Keys that differ between two runs of the same scene for reasons other than the physics.
# motor_fit: whether the motor's fitted circuit was fitted now or read from the fit cache, and when.
VOLATILE = {"cpu_seconds", "real_time_factor", "scene_path", "overrides", "scene", "motor_fit"}


def get(d, path, default=None):
    """d["a"]["b"] for "a.b", default when any step is missing or null."""
    for p in path.split("."):
        if not isinstance(d, dict) or d.get(p) is None:
            return default
        d = d[p]
    return d


def checks_of(summary):
    """{check name: check dict} of summary.json's sizing.checks."""
    return {c.get("check"): c for c in (get(summary, "sizing.checks") or [])}


def near_limit(check, value, tol):
    """Whether a check's value lies within tol (relative) of its limit, where a verdict may
    legitimately differ between two computations of the same figure."""
    limit = LIMITS.get(check)
    return limit is not None and value is not None and abs(value - limit) <= tol * limit


def rel_diff(a, b):
    if a is None or b is None:
        return None if a is None and b is None else math.inf
    scale = max(abs(a), abs(b))
    return 0.0 if scale == 0 else abs(a - b) / scale


def summary_diff(a, b, path="", ignore=VOLATILE, out=None, limit=12):
    """Paths where two summaries differ (bitwise: the same code on the same scene)."""
    out = [] if out is None else out
    if len(out) >= limit:
        return out
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) | set(b)):
            if k in ignore and not path:
                continue
            if k not in a or k not in b:
                out.append(f"{path}{k} (only in {'the first' if k in a else 'the second'})")
            else:
                summary_diff(a[k], b[k], f"{path}{k}.", ignore, out, limit)
    elif isinstance(a, list) and isinstance(b, list) and len(a) == len(b):
        for i, (x, y) in enumerate(zip(a, b)):
            summary_diff(x, y, f"{path}{i}.", ignore, out, limit)
    elif a != b:
        out.append(f"{path.rstrip('.')}: {str(a)[:60]} vs {str(b)[:60]}")
    return out


def motion(summary):
    return summary.get("motion") if isinstance(summary, dict) else None


# ----------------------------------------------------------------------------------------------

def same_facts(ctx):
    """(a) The console, summary.json, the report and Python state the same numbers and verdicts.

    Every fact is computed once into summary.json and the other three only render it: the console
    of `simulate` prints the motion, the status, δ, the mean speed, the energy residual and each
    sizing check's value, verdict and window from it, so each printed figure must be the JSON's,
    rounded as printed; `rd.simulate` runs the same code on the same scene, so its summary must be
    the command line's bit for bit (timings aside) and its text the console's; the report renders
    its own run's summary.json, so each check's verdict, the joints' lives and the verdict colours
    must be the JSON's. A difference means one of them computes instead of rendering."""
    base = ctx.get("base")
    if not base or not isinstance(base.get("summary"), dict):
        return None
    v = []
    s, c = base["summary"], parse.console(base.get("stdout", ""))
    v += _console_against_summary(c, s, "console")
    py = ctx.get("python")
    if py and isinstance(py.get("summary"), dict):
        d = summary_diff(s, py["summary"])
        if d:
            v.append(f"Python summary differs from summary.json at {len(d)} place(s): {'; '.join(d[:3])}")
        if py.get("text") is not None:
            v += _console_against_summary(parse.console(py["text"]), s, "Python text")
    rep = ctx.get("report")
    if rep and rep.get("html") is not None and isinstance(rep.get("summary"), dict):
        v += _report_against_summary(parse.report(rep["html"]), rep["summary"])
    return v


def _console_against_summary(c, s, where):
    v = []
    if "motion" in c and c["motion"] != s.get("motion"):
        v.append(f"{where} motion '{c['motion']}' vs summary.json '{s.get('motion')}'")
    if "status" in c and c["status"] != s.get("status"):
        v.append(f"{where} status differs from summary.json's: '{c['status'][:80]}' vs '{str(s.get('status'))[:80]}'")
    if "steady_reached" in c and c["steady_reached"] != bool(get(s, "steady_state.reached", False)):
        v.append(f"{where} says steady state {'reached' if c['steady_reached'] else 'NOT reached'}, "
                 f"summary.json steady_state.reached = {get(s, 'steady_state.reached')}")
    for key, path in (("delta", "delta"), ("omega_mean", "omega_crank.mean"), ("energy_residual_rel", "energy_residual_rel")):
        if key in c and not parse.agrees_with_print(c[key], get(s, path)):
            v.append(f"{where} {key} {c[key]} vs summary.json {path} = {get(s, path)}")
    checks = checks_of(s)
    for name, k in c.get("checks", {}).items():
        if name not in checks:
            v.append(f"{where} prints check {name}, summary.json has none")
            continue
        j = checks[name]
        jv = j.get("verdict")
        if (k["verdict"] if k["verdict"] != "n/a" else None) != jv:
            v.append(f"{where} {name} verdict '{k['verdict']}' vs summary.json '{jv}'")
        if not parse.agrees_with_print(k["value"], j.get("value")):
            v.append(f"{where} {name} value {k['value']} vs summary.json {j.get('value')}")
        if k["window"] != j.get("window"):
            v.append(f"{where} {name} decided by '{k['window']}' vs summary.json '{j.get('window')}'")
    if c.get("checks") is not None and c.get("checks") != {} or where == "console":
        for name in checks:
            if name not in c.get("checks", {}):
                v.append(f"{where} does not print check {name} of summary.json")
    if "run_up_time" in c and not parse.agrees_with_print(c["run_up_time"], get(s, "start_up.run_up_time")):
        v.append(f"{where} run-up time {c['run_up_time']} s vs summary.json start_up.run_up_time "
                 f"{get(s, 'start_up.run_up_time')}")
    for words, j in c.get("joints", {}).items():
        kind = parse.JOINT_WORDS[words]
        worst = get(s, f"sizing.joints.{kind}.worst") or {}
        life = j["life"]
        hours, revs = worst.get("L10_hours"), worst.get("L10_revolutions")
        if life == "n/a":
            if hours is not None or revs is not None:
                v.append(f"{where} {words} life n/a, summary.json L10_hours {hours}, L10_revolutions {revs}")
        elif life.endswith(" rev"):
            if not parse.agrees_with_print(life[:-4], revs):
                v.append(f"{where} {words} life {life}, summary.json L10_revolutions {revs}")
        elif not parse.agrees_with_print(life, hours):
            v.append(f"{where} {words} life {life} (hours), summary.json L10_hours {hours}")
    return v


def _report_against_summary(r, s):
    v = []
    checks = list(checks_of(s).values())
    for row in r["checks"]:
        match = [k for k in checks if k.get("what") == row["what"]]
        if not match:
            v.append(f"report check row '{row['what'][:50]}' has no check in summary.json")
            continue
        k = match[0]
        jv = k.get("verdict")
        rv = None if row["verdict"] == "n/a" else row["verdict"]
        if rv != jv:
            v.append(f"report {k.get('check')} verdict '{row['verdict']}' vs summary.json '{jv}'")
        if not parse.agrees_with_print(row["value"], k.get("value")):
            v.append(f"report {k.get('check')} value {row['value']} vs summary.json {k.get('value')}")
        colour = {"pass": "ok", "FAIL": "bad"}.get(rv)
        if colour and colour not in row["class"].split():
            v.append(f"report {k.get('check')} verdict {rv} drawn with class '{row['class']}'")
    if len(r["checks"]) != len(checks):
        v.append(f"report shows {len(r['checks'])} checks, summary.json has {len(checks)}")
    names = {"guide roller, front": "guide_roller_front", "guide roller, rear": "guide_roller_rear",
             "rod end (cart hinge)": "rod_end", "crank pin (rod big end)": "crank_pin", "main bearing": "main_bearing"}
    for row in r["joints"]:
        kind = names.get(row["joint"])
        per = get(s, f"sizing.joints.{kind}.per_cart") or []
        mine = [x for x in per if str(x.get("cart")) == row["cart"] or (x.get("cart") is None and row["cart"] == "-")]
        if not mine:
            continue
        x = mine[0]
        if row["life"] == "n/a" and (x.get("L10_hours") is not None or x.get("L10_revolutions") is not None):
            v.append(f"report {row['joint']} cart {row['cart']} life n/a, summary.json L10_hours {x.get('L10_hours')}, "
                     f"L10_revolutions {x.get('L10_revolutions')}")
        elif row["life"] != "n/a" and not parse.agrees_with_print(row["life"], x.get("L10_hours")):
            v.append(f"report {row['joint']} cart {row['cart']} life {row['life']} h, summary.json L10_hours {x.get('L10_hours')}")
    v += _verdict_colours_visible(r["css"])
    return v


def _verdict_colours_visible(css):
    """A verdict cell's colour (classes ok / bad) must not be overridden by a rule that colours
    table cells with a higher specificity, or the same one later in the sheet (the zebra rule of
    even rows): a FAIL in such a row would not be red."""
    rules = parse.css_rules(css)
    verdict_rules = [(i, parse.specificity(sel)) for i, (sel, body) in enumerate(rules)
                     if re.search(r"\.(ok|bad)\b", sel) and "background" in body]
    if not verdict_rules:
        return []
    v = []
    for i, (sel, body) in enumerate(rules):
        if "background" not in body or re.search(r"\.(ok|bad)\b", sel) or not re.search(r"\btd\b", sel):
            continue
        if "!important" in body:
            continue
        sp = parse.specificity(sel)
        for j, vsp in verdict_rules:
            if sp > vsp or (sp == vsp and i > j):
                v.append(f"report CSS rule '{sel}' {sp} outranks the verdict colour rule {vsp}: "
                         f"a verdict cell it matches loses its colour")
                break
    return v


# ----------------------------------------------------------------------------------------------

def speed_tolerance(summary):
    """τ: the steady-state criterion's relative tolerance (each revolution's mean speed within τ
    of the final revolution's; summary.json steady_state.relative_tolerance, 1e-3)."""
    return get(summary, "steady_state.relative_tolerance", 1e-3)


def longer_run_same_verdicts(ctx):
    """(b) Once a steady state is reached, doubling t_end changes no verdict and no steady metric
    beyond the tolerance.

    Tolerance: a run is steady when the mean, lowest and highest speed of each of the last
    revolutions are within τ·|ω̄| (steady_state.relative_tolerance τ = 1e-3 of the mean speed) of
    the final one's; the integration error (accuracy 1e-6) is a thousand times smaller. So two
    steady windows of the same machine may differ by what the criterion lets through: mean, min
    and max crank speed by 2τ·|ω̄| (a minimum near zero is no reason for a tighter bound); δ, the
    difference of the extremes over the mean, by 4τ + 2τ·δ; a torque, which on the motor's
    running branch is proportional to the slip s, by 2τ/s relative (a speed change Δω moves the
    slip by Δω/ω0); the verdicts not at all, unless the value lies within that tolerance of the
    check's limit. The run must not be switched off (a switch-off makes the end of the run
    different) and the crank must turn."""
    base, dbl = ctx.get("base"), ctx.get("double")
    if not base or not dbl or not isinstance(base.get("summary"), dict) or not isinstance(dbl.get("summary"), dict):
        return None
    a, b = base["summary"], dbl["summary"]
    if not get(a, "steady_state.reached", False) or motion(a) != "turning":
        return None
    if get(ctx.get("scene", {}), "motor.stop") or get(a, "start_up.stop"):
        return None
    tau = speed_tolerance(a)
    slip = max(abs(get(a, "sizing.motor.slip.min", 0.0) or 0.0), abs(get(a, "sizing.motor.slip.max", 0.0) or 0.0), 1e-3)
    tol_torque = 2 * tau / slip + 1e-3
    v = []
    t1, t2 = get(a, "simulated_time"), get(b, "simulated_time")
    what = f"t_end {t1:g} s vs {t2:g} s" if t1 and t2 else "t_end doubled"
    if motion(b) != "turning" or not get(b, "steady_state.reached", False):
        v.append(f"{what}: steady state reached and turning at the shorter run, motion '{motion(b)}', "
                 f"steady reached {get(b, 'steady_state.reached')} at the longer")
        return v
    if base.get("exit") != dbl.get("exit"):
        v.append(f"{what}: exit code {base.get('exit')} vs {dbl.get('exit')}")
    w_mean = max(abs(get(a, "omega_crank.mean", 0.0) or 0.0), abs(get(b, "omega_crank.mean", 0.0) or 0.0))
    for path in ("omega_crank.mean", "omega_crank.min", "omega_crank.max"):
        x, y = get(a, path), get(b, path)
        if x is not None and y is not None and abs(x - y) > 2 * tau * w_mean:
            v.append(f"{what}: {path} {x:.6g} vs {y:.6g} (tolerance 2τ·|ω̄| = {2 * tau * w_mean:.2g} rad/s)")
    da, db = get(a, "delta"), get(b, "delta")
    if da is not None and db is not None and abs(da - db) > 4 * tau + 2 * tau * max(da, db):
        v.append(f"{what}: δ {da:.5g} vs {db:.5g} (tolerance {4 * tau + 2 * tau * max(da, db):.2g})")
    for path in ("sizing.motor.torque_shaft.rms", "sizing.motor.torque_shaft.peak", "sizing.coupling.peak"):
        x, y = get(a, path), get(b, path)
        r = rel_diff(x, y)
        if r is not None and r > tol_torque and max(abs(x or 0), abs(y or 0)) > 0:
            v.append(f"{what}: {path} {x} vs {y} (tolerance {tol_torque:.2g} relative, 2τ/s)")
    ca, cb = checks_of(a), checks_of(b)
    for name in sorted(set(ca) | set(cb)):
        x, y = ca.get(name, {}), cb.get(name, {})
        if x.get("verdict") == y.get("verdict"):
            continue
        if near_limit(name, x.get("value"), tol_torque) or near_limit(name, y.get("value"), tol_torque):
            continue
        v.append(f"{what}: {name} {x.get('value')} {x.get('verdict')} vs {y.get('value')} {y.get('verdict')}")
    return v


# ----------------------------------------------------------------------------------------------

def verdicts_within_preconditions(ctx):
    """(c) No check passes or fails outside its preconditions.

    A steady-window check (heating on continuous running, breakdown margin) needs a steady state
    that was reached: over a run too short for one, its window is the end of a start, and a pass
    or FAIL there describes the start, not the running. Start answers (run-up time, a start's
    peaks and rotor heat) need a start from rest. A duty of starts per hour needs a drive that can
    start, and a start whose heat is known. Bearing lives and the modal stability verdict need a
    crank that turns (a joint that does not move has no life in hours, a stalled drive no steady
    motion whose stability could be judged). δ and the per-revolution figures need a crank that
    turns."""
    base = ctx.get("base")
    if not base or not isinstance(base.get("summary"), dict):
        return None
    s = base["summary"]
    v = []
    mo = motion(s)
    reached = bool(get(s, "steady_state.reached", False))
    checks = checks_of(s)
    if mo == "turning" and not reached:
        for name, k in checks.items():
            steady_window = "steady" in str(k.get("window", "")) or name in ("motor_breakdown",)
            if steady_window and k.get("verdict") not in NO_VERDICT and not _robust_fail(name, k, s):
                v.append(f"{name} {k.get('verdict')} ({k.get('value')}) decided by the {k.get('window')}, but the steady "
                         f"state was not reached (t_end {get(s, 'simulated_time')} s)")
    if mo == "starting":
        for name, k in checks.items():
            if k.get("verdict") in NO_VERDICT or _robust_fail(name, k, s):
                continue
            # The start check of a run that begins turning judges the torques at standstill, which
            # do not depend on how this run ends.
            if name == "start" and "torques at standstill" in str(k.get("window", "")):
                continue
            v.append(f"{name} {k.get('verdict')} ({k.get('value')}) while the drive is still starting")
    su = s.get("start_up")
    if isinstance(su, dict):
        if not su.get("from_rest", True):
            for key in ("run_up_time", "rotor_energy_loss", "motor_torque.peak", "coupling_torque.peak"):
                if get(su, key) is not None:
                    v.append(f"start_up.{key} = {get(su, key)} for a run that begins at speed (no start in the run)")
            if su.get("starts"):
                v.append("start_up.starts true for a run that begins at speed")
            if get(s, "sizing.motor.whole_run.start_heat") is not None:
                v.append(f"sizing start heat {get(s, 'sizing.motor.whole_run.start_heat')} J from a run that holds no start")
        if su.get("run_up_time") is not None and not su.get("starts"):
            v.append(f"run-up time {su.get('run_up_time')} s given for a drive that does not start")
    sph = get(ctx.get("scene", {}), "sizing.starts_per_hour", 0) or 0
    heat = checks.get("motor_heating", {})
    if sph > 0 and heat.get("verdict") == "pass" and isinstance(su, dict):
        # From rest the run tells whether the drive starts; at speed, a start direct on line
        # cannot happen when the torque at standstill is below the load at the start angle (with
        # a ramp the torque at switch-on is not the torque that decides).
        dol = (get(ctx.get("scene", {}), "motor.start.method", "direct_on_line") or "direct_on_line") == "direct_on_line"
        cannot = (not su.get("from_rest", True) and dol and su.get("starting_torque_crank") is not None
                  and su.get("load_torque_start") is not None
                  and su["starting_torque_crank"] <= su["load_torque_start"])
        if su.get("from_rest") and su.get("starts") is False and not su.get("still_starting"):
            v.append(f"motor_heating pass ({heat.get('value')}) for {sph:g} starts per hour, but the drive does not start")
        elif cannot:
            v.append(f"motor_heating pass ({heat.get('value')}) for {sph:g} starts per hour, but the starting torque "
                     f"{su['starting_torque_crank']:.4g} N·m is below the load {su['load_torque_start']:.4g} N·m at the "
                     f"start angle: the drive cannot start from rest")
        elif not su.get("from_rest", True) and get(s, "sizing.motor.whole_run.start_heat") is None:
            v.append(f"motor_heating pass ({heat.get('value')}) for {sph:g} starts per hour from a run that holds no "
                     f"start (its start heat is not known)")
    # (at_rest: the motor was switched off, and the run before it may have turned: its lives and
    # its steady motion stand.)
    if mo in ("stalled", "rocking"):
        for kind, j in (get(s, "sizing.joints") or {}).items():
            for x in (j or {}).get("per_cart", []):
                for key in ("L10_hours", "L10_revolutions"):
                    if x.get(key) is not None:
                        v.append(f"{kind} cart {x.get('cart')}: {key} {x.get(key):.3g} for a drive that does not "
                                 f"turn ({mo})")
                        break
        rm = s.get("resonance_modal")
        if isinstance(rm, dict) and rm.get("applicable"):
            v.append(f"the modal analysis judges a steady motion ({str(rm.get('floquet_verdict'))[:40]}) of a drive that "
                     f"does not turn ({mo})")
        rep = ctx.get("report")
        if rep and rep.get("html") and parse.report(rep["html"])["says_stable"] and motion(rep.get("summary")) == mo:
            v.append(f"the report says 'the steady motion is stable' of a drive that does not turn ({mo})")
    if mo != "turning" and s.get("delta") is not None:
        v.append(f"δ = {s.get('delta')} for a crank that does not turn ({mo})")
    return v


def _robust_fail(name, k, s):
    """A FAIL that no longer run can undo: the coupling's peak over the whole run already above
    its rating (a longer run can only raise a peak), whichever window the check names."""
    ratio = get(s, "sizing.coupling.peak_over_rating_whole_run")
    return (name == "coupling" and k.get("verdict") == "FAIL" and
            (k.get("window") == "whole run" or (ratio is not None and ratio > 1)))


# ----------------------------------------------------------------------------------------------

def one_stall_cause(ctx):
    """(d) The status line, the start-up block and the sizing name the same stall cause.

    Why a drive does not start or run is one fact (the motor's torque at standstill under the
    supply at switch-on against the load at the start angle; its largest torque against the mean
    load; a star-delta changeover never reached; else the load peaks near a dead centre with the
    inertia), so every place that names it must name the same cause and the same starting torque.
    Applies to a run from rest whose drive does not start, and to a stalled or rocking drive."""
    base = ctx.get("base")
    if not base or not isinstance(base.get("summary"), dict):
        return None
    s = base["summary"]
    su = s.get("start_up") if isinstance(s.get("start_up"), dict) else {}
    stalled = motion(s) in ("stalled", "rocking")
    no_start = su.get("from_rest") and su.get("starts") is False and not su.get("still_starting")
    if not stalled and not no_start:
        return None
    places = {"status": s.get("status", ""),
              "start-up": su.get("verdict", "") if su else "",
              "sizing": checks_of(s).get("motor_breakdown", {}).get("reason", "")}
    if isinstance(s.get("stall"), dict):
        places["stall"] = s["stall"].get("explanation", "")
    causes = {k: parse.stall_cause(t) for k, t in places.items()}
    named = {k: c for k, c in causes.items() if c}
    v = []
    if len(set(named.values())) > 1:
        v.append("stall causes differ: " + ", ".join(f"{k} '{c}'" for k, c in named.items()))
    if stalled and su and su.get("starts"):
        v.append(f"the status says the drive {motion(s)}, the start-up block that it starts")
    torques = {k: parse.starting_torque_named(t) for k, t in places.items()}
    torques = {k: x for k, x in torques.items() if x is not None}
    if torques and max(torques.values()) > min(torques.values()) * 1.001 + 1e-9:
        v.append("starting torques at the crank differ: " + ", ".join(f"{k} {x:.4g} N·m" for k, x in torques.items()))
    return v


# ----------------------------------------------------------------------------------------------

ESTIMATE_WORDS = re.compile(r"\bestimate", re.I)


def estimates_reproduce(ctx):
    """(e) Every printed optimum or estimate reproduces when run, or is labelled an estimate with
    the run's value beside it.

    The sweep's parabola vertex is printed as "key = x, metric = y": a run at x must give y within
    5 % (a parabola through three points of a smooth curve is accurate to its third derivative;
    5 % is far above the integration error and far below the 22x of a V-shaped minimum). The
    flywheel proposal says that the flywheel proposed gives δ = 0.86 ... 1.16 δ*: a run with it
    must give δ ≤ 1.16 δ* (with the run's 2τ speed tolerance), or the output must give the run's δ
    beside it (in the text, or as the first of the flywheel's runs in summary.json)."""
    sw, fw = ctx.get("sweep"), ctx.get("flywheel")
    if not sw and not fw:
        return None
    v = []
    if sw:
        par = get(sw.get("json") or {}, "optimum.parabola")
        run = sw.get("vertex_run")
        if par and isinstance(run, dict):
            y = par.get("value")
            y_run = get(run, sw["metric"]) if sw["metric"] != "delta" else run.get("delta")
            if y is not None and y_run is not None and rel_diff(y, y_run) > 0.05:
                labelled = ESTIMATE_WORDS.search(sw.get("stdout", "")) and f"{y_run:.4g}" in sw.get("stdout", "")
                if not labelled:
                    v.append(f"sweep prints {sw['param']} = {par.get('parameter'):.6g}, {sw['metric']} = {y:.6g}; a run "
                             f"there gives {y_run:.6g} ({y_run / y if y else math.inf:.3g}x), not labelled an estimate")
    if fw and isinstance(fw.get("summary"), dict):
        d, target = fw["summary"].get("delta"), fw.get("target")
        tau = speed_tolerance(fw["summary"])
        if d is not None and target and d > 1.16 * target * (1 + 2 * tau) + 2 * tau:
            out = fw.get("stdout", "")
            # The run's δ beside the estimate: in the text, or among the flywheel's runs in the
            # summary (sizing.flywheel.by_runs: the estimate is its first run).
            base = (ctx.get("base") or {}).get("summary") or {}
            runs = get(base, "sizing.flywheel.by_runs.runs") or []
            beside = any(isinstance(r, dict) and r.get("delta") is not None and r.get("inertia") and
                         abs(r["inertia"] - fw["proposed"]) <= 1e-3 * fw["proposed"] and
                         abs(r["delta"] - d) <= (2 * tau + 1e-3) * d for r in runs)
            if not beside and not (ESTIMATE_WORDS.search(out) and f"{d:.3g}" in out):
                v.append(f"flywheel proposal {fw['proposed']:.4g} kg·m² on the crankshaft for δ* = {target:g} gives "
                         f"δ = {d:.4g} = {d / target:.3g} δ* in a run (printed: 0.86 ... 1.16 δ*)")
    return v


# ----------------------------------------------------------------------------------------------

def energy_tolerance(scene, model):
    """Tolerance of the energy audit, relative to the largest energy term.

    The audit's integrals (motor work, dissipations, load work) are states of the same integrator
    as the motion, under the relative tolerance a = simulation.accuracy (CVODE at a/100 in the
    minimal formulation, at a in the reduced model). Each step commits a local error ≤ a relative
    to the states; over a run the errors add up to at most a few hundred a for the runs here
    (≲ 10⁴ steps, errors of both signs), and the residual is a sum of six such integrals and the
    kinetic and potential energies: 1000·a of the largest term. Baranov's fixed-step scheme has
    no error control and its energy error is of first order in the crank-angle step h [rad]:
    eq. (4) of Loveikin and Pochka (2007) linearises the energy theorem eq. (2), missing
    ½·J·Δω² per step, and the works are summed by the scheme's left-point rule, off by
    ½·h·ΔM per step; both add up to O(h) over a run (measured on one machine: 2.09e-2, 1.06e-2,
    5.35e-3, 2.68e-3, 1.34e-3 of the largest term at h = 2°, 1°, 0.5°, 0.25°, 0.125°: exactly
    halving). The tolerance is h itself (1.75e-2 at 1°), and baranov_converges checks that the
    residual is this discretisation error: halving h halves it. A drive that hardly moves (a
    stall) has terms of a few joules, where the relative error means nothing: the floor is the
    same 1000·a of 1 kJ, below the kinetic energy of any generated drive at running speed."""
    if model == "reduced" and get(scene, "reduced.integrator") == "baranov":
        return math.radians(get(scene, "reduced.baranov_step_deg", 1.0) or 1.0)
    return 1000 * (get(scene, "simulation.accuracy", 1e-6) or 1e-6)


def residual_rel(summary):
    """|energy residual| over the largest energy term (at least ENERGY_FLOOR); None without an audit."""
    e = summary.get("energy") if isinstance(summary, dict) else None
    if not isinstance(e, dict) or e.get("residual") is None:
        return None
    terms = [abs(x) for k, x in e.items() if k != "residual" and isinstance(x, (int, float))]
    if not terms or max(terms) == 0:
        return None
    return abs(e["residual"]) / max(max(terms), ENERGY_FLOOR)


def baranov_converges(ctx):
    """Baranov's scheme: the same run at half the crank-angle step must halve the energy residual
    (first order, see energy_tolerance) within ±20 % (the O(h²) remainder at h = 1°), unless both
    residuals lie below the integrators' floor 1000·a. A residual that does not shrink with h is
    no discretisation error but a term missing from the audit."""
    half, base = ctx.get("half_step"), ctx.get("base")
    if not half or not isinstance(half.get("summary"), dict) or motion(half["summary"]) != motion(base["summary"]):
        return []
    r, r_half = residual_rel(base["summary"]), residual_rel(half["summary"])
    if r is None or r_half is None:
        return []
    floor = 1000 * (get(ctx.get("scene", {}), "simulation.accuracy", 1e-6) or 1e-6)
    if r <= floor and r_half <= floor:
        return []
    if not (0.4 * r <= r_half <= 0.6 * r):
        return [f"energy residual {r:.3e} at the scheme's step, {r_half:.3e} at half the step: not the scheme's "
                f"first-order error (expected half)"]
    return []


ENERGY_FLOOR = 1000.0  # J, see energy_tolerance


def energy_closes(ctx):
    """(f) The energy audit closes: motor work = dissipations + load work + ΔT + ΔV up to the
    integration tolerance (energy_tolerance)."""
    base = ctx.get("base")
    if not base or not isinstance(base.get("summary"), dict):
        return None
    e = base["summary"].get("energy")
    if not isinstance(e, dict) or e.get("residual") is None:
        return None
    terms = [abs(x) for k, x in e.items() if k != "residual" and isinstance(x, (int, float))]
    scale = max(terms) if terms else 0.0
    if scale == 0:
        return None
    scale = max(scale, ENERGY_FLOOR)
    tol = energy_tolerance(ctx.get("scene", {}), ctx.get("model"))
    r = abs(e["residual"]) / scale
    if r > tol:
        return [f"energy residual {e['residual']:.4g} J = {r:.2e} of the largest term (at least 1 kJ) {scale:.4g} J "
                f"(tolerance {tol:.2e}; summary's energy_residual_rel {base['summary'].get('energy_residual_rel')})"]
    return baranov_converges(ctx)


# ----------------------------------------------------------------------------------------------

NO_EFFECT_WORDS = re.compile(r"no effect|without effect|not used|unused|ignored|has no|does not (use|apply|change)|"
                             r"changes nothing", re.I)


def keys_take_effect(ctx):
    """(g) Every given key changes the result or is reported as without effect.

    A key the scene gives is changed (a number by 10 %, a choice to another valid one): either
    some figure of summary.json changes, or the run says that the key has no effect (a warning or
    a note naming the key). A key that is silently ignored lets a user believe a design change was
    simulated."""
    p, base = ctx.get("perturb"), ctx.get("base")
    if not p or not base or not isinstance(p.get("summary"), dict) or not isinstance(base.get("summary"), dict):
        return None
    if summary_diff(base["summary"], p["summary"], limit=1):
        return []
    key = p["key"]
    leaf = key.split(".")[-1]
    # Where a run says a key does nothing: a warning on stderr or in summary.json naming the key
    # (or its last part) with words to that effect. Not stdout: it echoes the --set options.
    lines = p.get("stderr", "").splitlines() + [str(w) for w in p["summary"].get("warnings", [])]
    for line in lines:
        if (key in line or re.search(rf"\b{re.escape(leaf)}\b", line)) and NO_EFFECT_WORDS.search(line):
            return []
    return [f"{key} changed from {p['old']} to {p['new']}: no figure of summary.json changes and no warning says "
            f"the key has no effect"]


# ----------------------------------------------------------------------------------------------

def model_tolerance(scene):
    """Relative tolerance between the two models where they integrate the same equations: each
    has a global error of at most a few hundred times a = simulation.accuracy in the crank speed
    (the docs measure ≤ 1e-8 at a = 1e-10), so the two differ by ≤ 1000·a; torques, which follow
    the slip, by 1000·a/s."""
    return 1000 * (get(scene, "simulation.accuracy", 1e-6) or 1e-6)


def models_agree(ctx):
    """(h) The two models agree where their physics is the same.

    With split or massless rods, no guide friction, exact kinematics and CVODE in the reduced
    model (generator.same_physics, docs/models.md) the multibody and the reduced model integrate
    the same equations: the motion, the steady figures and every verdict drawn from them must
    agree to the integration tolerance (model_tolerance), and the start-up answers too."""
    o, base = ctx.get("other"), ctx.get("base")
    if not o or not base or not isinstance(o.get("summary"), dict) or not isinstance(base.get("summary"), dict):
        return None
    a, b = base["summary"], o["summary"]
    ma, mb = ctx.get("model"), o.get("model")
    tol = model_tolerance(ctx.get("scene", {}))
    v = []
    if motion(a) != motion(b):
        v.append(f"motion {ma} '{motion(a)}' vs {mb} '{motion(b)}'")
        return v
    if base.get("exit") != o.get("exit"):
        v.append(f"exit code {ma} {base.get('exit')} vs {mb} {o.get('exit')}")
    ra, rb = get(a, "steady_state.reached", False), get(b, "steady_state.reached", False)
    if ra != rb:
        v.append(f"steady state reached: {ma} {ra} vs {mb} {rb}")
        return v
    # Speeds against the larger of themselves and the synchronous crank speed ω0/u: a stalled or
    # rocking crank creeps at mm/s, where a relative difference means nothing.
    sc = ctx.get("scene", {})
    w_sync = (get(sc, "motor.omega_sync", 0.0) or 0.0) / (get(sc, "reducer.ratio", 1.0) or 1.0)
    for path in ("omega_crank.mean", "omega_crank.min", "omega_crank.max"):
        x, y = get(a, path), get(b, path)
        if x is None or y is None:
            if (x is None) != (y is None):
                v.append(f"{path} {ma} {x} vs {mb} {y}")
            continue
        r = abs(x - y) / max(abs(x), abs(y), w_sync, 1e-300)
        if r > tol:
            v.append(f"{path} {ma} {x:.7g} vs {mb} {y:.7g} (difference {r:.1e} of max(|ω|, ω0/u) > {tol:.0e})")
    slip = max(abs(get(a, "sizing.motor.slip.max", 0.0) or 0.0), 1e-3)
    for path in ("sizing.motor.torque_shaft.rms", "sizing.coupling.peak"):
        x, y = get(a, path), get(b, path)
        r = rel_diff(x, y)
        if r is not None and r > tol / slip + 1e-6:
            v.append(f"{path} {ma} {x} vs {mb} {y} (rel {r:.1e})")
    ca, cb = checks_of(a), checks_of(b)
    for name in sorted(set(ca) | set(cb)):
        x, y = ca.get(name, {}), cb.get(name, {})
        if x.get("verdict") != y.get("verdict") and not (near_limit(name, x.get("value"), 1e-3) or
                                                          near_limit(name, y.get("value"), 1e-3)):
            v.append(f"{name}: {ma} {x.get('value')} {x.get('verdict')} vs {mb} {y.get('value')} {y.get('verdict')}")
    sa, sb = a.get("start_up") or {}, b.get("start_up") or {}
    if sa.get("starts") != sb.get("starts"):
        v.append(f"start_up.starts {ma} {sa.get('starts')} vs {mb} {sb.get('starts')}")
    step = get(ctx.get("scene", {}), "simulation.output_step", 0.005)
    x, y = sa.get("run_up_time"), sb.get("run_up_time")
    if x is not None and y is not None and abs(x - y) > step * 1.001:
        v.append(f"run-up time {ma} {x:.4g} s vs {mb} {y:.4g} s (more than one output step apart)")
    return v


# ----------------------------------------------------------------------------------------------

def switch_on_shift(ctx):
    """(i) Shifting the switch-on time (motor.start.t_on, with every later event and t_end)
    shifts every start answer by the same time.

    A machine at rest before its switch-on starts the same way whenever it is switched on, so
    durations (run-up time) are unchanged, instants (the end of the start, the steady window, the
    whole run's coupling peak) move by the shift, and peaks and energies are unchanged, up to one
    output step for what is read off the output rows (the shift is a whole number of steps) and
    1e-3 relative for the integration (≲ 10³ steps at a local tolerance of 1e-6). Applies when
    the crank stayed at rest until the switch-on (rods' gravity can turn an unbraked crank)."""
    sh, base = ctx.get("shift"), ctx.get("base")
    if not sh or not base or not isinstance(sh.get("summary"), dict) or not isinstance(base.get("summary"), dict):
        return None
    a, b, dt = base["summary"], sh["summary"], sh["delta"]
    sa, sb = a.get("start_up"), b.get("start_up")
    if not isinstance(sa, dict) or not isinstance(sb, dict) or not sa.get("from_rest"):
        return None
    if sh.get("omega_before_on") is None or sh["omega_before_on"] > 1e-6:
        return None
    step = get(ctx.get("scene", {}), "simulation.output_step", 0.005)
    v = []
    what = f"switch-on {sa.get('t_on'):g} s vs {sb.get('t_on'):g} s"
    for key in ("starts", "still_starting"):
        if sa.get(key) != sb.get(key):
            v.append(f"{what}: start_up.{key} {sa.get(key)} vs {sb.get(key)}")
    if motion(a) != motion(b):
        v.append(f"{what}: motion '{motion(a)}' vs '{motion(b)}'")
    x, y = sa.get("run_up_time"), sb.get("run_up_time")
    if (x is None) != (y is None) or (x is not None and abs(x - y) > step * 1.001):
        v.append(f"{what}: run-up time {x} s vs {y} s (should be equal, measured from the switch-on)")
    if not (sa.get("starts") and sb.get("starts")):
        # A drive that did not start has its answers over "the run's last part", a share of the
        # whole run (rest before the switch-on included), and a stalled drive's peaks come from a
        # creep against the smoothed loads: only the verdicts above are shift-invariant there.
        return v
    for path in ("start_end", "steady.t_begin"):
        x, y = get(sa, path), get(sb, path)
        if x is not None and y is not None and abs((y - x) - dt) > step * 1.001:
            v.append(f"{what}: start_up.{path} {x:.4g} s vs {y:.4g} s (shifted by {y - x:.4g}, not {dt:g})")
    for path in ("motor_torque.peak", "coupling_torque.peak", "rotor_energy_loss", "stator_current.peak"):
        x, y = get(sa, path), get(sb, path)
        r = rel_diff(x, y)
        if r is not None and r > 1e-3:
            v.append(f"{what}: start_up.{path} {x} vs {y} (rel {r:.1e})")
    ta, tb = get(a, "sizing.coupling.t_peak_whole_run"), get(b, "sizing.coupling.t_peak_whole_run")
    pa, pb = get(a, "sizing.coupling.peak_whole_run"), get(b, "sizing.coupling.peak_whole_run")
    in_start = ta is not None and (sa.get("t_on") or 0) <= ta <= (sa.get("start_end") or -1)
    if in_start and tb is not None and rel_diff(pa, pb) is not None and rel_diff(pa, pb) <= 1e-3 \
            and abs((tb - ta) - dt) > step * 1.001:
        v.append(f"{what}: whole-run coupling peak at t = {ta:.4g} s vs {tb:.4g} s (shifted by {tb - ta:.4g}, not {dt:g})")
    return v


INVARIANTS = {
    "a": same_facts,
    "b": longer_run_same_verdicts,
    "c": verdicts_within_preconditions,
    "d": one_stall_cause,
    "e": estimates_reproduce,
    "f": energy_closes,
    "g": keys_take_effect,
    "h": models_agree,
    "i": switch_on_shift,
}

TITLES = {
    "a": "console, summary.json, report and Python agree",
    "b": "doubling t_end changes no steady verdict",
    "c": "no verdict outside its preconditions",
    "d": "one stall cause",
    "e": "optima and estimates reproduce",
    "f": "energy audit closes",
    "g": "every given key has an effect",
    "h": "the two models agree",
    "i": "switch-on shift shifts the start",
}


def check_all(ctx, which=None):
    """{letter: {"status": "ok" | "violation" | "n/a" | "error", "messages": [...]}}."""
    out = {}
    for letter, fn in INVARIANTS.items():
        if which and letter not in which:
            continue
        try:
            r = fn(ctx)
        except Exception as e:  # a harness bug must not hide the other invariants
            out[letter] = {"status": "error", "messages": [f"{type(e).__name__}: {e}"]}
            continue
        if r is None:
            out[letter] = {"status": "n/a", "messages": []}
        else:
            out[letter] = {"status": "violation" if r else "ok", "messages": r}
    return out
