"""Seeded generator of valid machines for the consistency harness.

A machine is a scene (a dict with the keys of a scene file, docs/scene-reference.md), the model
that runs it and a plan: which of the costlier invariants (extra runs) this machine gets. The
same (seed, attempt) always gives the same machine, on any host and under any number of ranks,
so a violation is re-run by hand from its seed or from the scene file written beside it.

The machines start from the shipped scenes (model/*.yaml: their rods, cart geometry, motors with
catalogue data, reducer and coupling) and vary what the issue lists: 1-8 carts, sides and crank
offsets, per-cart masses and loads, every motor law and starting method, elastic or rigid
coupling, flywheels, a start from rest or at speed, a switch-off, the sizing inputs, run lengths
from shorter than the start to many revolutions, and both models. Loads are scaled to the motor
(a mean load torque of 5 % ... 140 % of the motor's nominal torque at the crank), so most drives
run and some stall, as designs do.
"""

import math
import random

# The two catalogue motors of the shipped scenes (model/balanced-4cart.yaml: 4A200M6U3;
# model/energy-balanced-3cart.yaml: 4A160M6U3), with Kloss data consistent with the catalogue.
MOTORS = [
    {"name": "4A200M6U3", "omega_sync": 104.72, "omega_nominal": 102.1, "overload_ratio": 2.4,
     "breakdown_torque": 517.14, "rotor_inertia": 0.4,
     "catalogue": {"power": 22000.0, "omega_nominal": 102.1, "current": 41.27, "power_factor": 0.90,
                   "efficiency": 0.90, "starting_torque_ratio": 1.3, "breakdown_torque_ratio": 2.4,
                   "starting_current_ratio": 6.5}},
    {"name": "4A160M6U3", "omega_sync": 104.72, "omega_nominal": 102.1, "overload_ratio": 2.0,
     "breakdown_torque": 293.8, "rotor_inertia": 0.183,
     "catalogue": {"power": 15000.0, "omega_nominal": 102.1, "current": 29.94, "power_factor": 0.87,
                   "efficiency": 0.875, "starting_torque_ratio": 1.2, "breakdown_torque_ratio": 2.0,
                   "starting_current_ratio": 6.0}},
]

MOTOR_LAWS = ["kloss", "kloss_dynamic", "circuit", "park"]
START_METHODS = ["direct_on_line", "star_delta", "soft_starter", "frequency_converter"]


class Machine:
    """One generated machine: seed, attempt (sub-seed), scene dict, model and plan."""

    def __init__(self, seed, attempt, scene, model, plan, notes):
        self.seed, self.attempt, self.scene, self.model, self.plan, self.notes = seed, attempt, scene, model, plan, notes

    @property
    def name(self):
        return f"seed{self.seed:06d}" + (f"-{self.attempt}" if self.attempt else "")

    def describe(self):
        """One line: what kind of machine this is (for the summary table)."""
        s = self.scene
        m = s["motor"]
        start = m.get("start", {})
        return (f"{s['carts']['count']} carts, {m.get('model', 'kloss')}, {start.get('method', 'direct_on_line')}, "
                f"{s['coupling']['type']}, {'from rest' if s['initial']['crank_speed'] == 0 else 'at speed'}, "
                f"t_end {s['simulation']['t_end']:g} s, {self.model}")


def _r(rng, lo, hi, digits=4):
    """A uniform draw rounded to `digits` significant figures (scene files read cleanly)."""
    v = rng.uniform(lo, hi)
    return float(f"{v:.{digits}g}")


def _log(rng, lo, hi, digits=3):
    return float(f"{math.exp(rng.uniform(math.log(lo), math.log(hi))):.{digits}g}")


def _pick(rng, weighted):
    """weighted: list of (value, weight)."""
    total = sum(w for _, w in weighted)
    x = rng.uniform(0, total)
    for v, w in weighted:
        x -= w
        if x <= 0:
            return v
    return weighted[-1][0]


def generate(seed, attempt=0, plan_rates=None):
    """The machine of (seed, attempt): a valid scene dict, the model and the plan of extra runs."""
    rng = random.Random(f"rollerdyn-consistency/{seed}/{attempt}")
    notes = []
    n = rng.randint(1, 8)
    motor = dict(rng.choice(MOTORS))
    law = _pick(rng, [("kloss", 3), ("kloss_dynamic", 2), ("circuit", 2.5), ("park", 2.5)])
    method = _pick(rng, [("direct_on_line", 4), ("star_delta", 2), ("soft_starter", 2), ("frequency_converter", 2)])
    model = _pick(rng, [("reduced", 55), ("multibody", 45)])

    # Geometry (model/balanced-4cart.yaml's, varied), l/r >= 3 keeps the rods off their dead centre.
    r = _r(rng, 0.15, 0.25, 3)
    l = float(f"{r * rng.uniform(3.0, 5.0):.3g}")
    rods_model = _pick(rng, [("distributed", 4), ("split", 4), ("massless", 2)])
    rods = {"model": rods_model, "length": l}
    if rods_model != "massless":
        rods["mass"] = _r(rng, 30, 80, 3)

    sides = _pick(rng, [("same", 5), ("opposite", 1), ("alternate", 2), ("list", 2)])
    if sides == "list":
        sides = [rng.choice(["same", "opposite"]) for _ in range(n)]
    crank = {"radius": r, "inertia_per_crank": _pick(rng, [(0.0, 3), (_r(rng, 0.5, 5, 2), 1)]),
             "shaft_inertia": _pick(rng, [(0.0, 3), (_r(rng, 0.5, 10, 2), 1)])}
    layout = _pick(rng, [("even", 4), ("random_offset", 3), ("angles", 2)])
    if layout == "even":
        crank["offset_deg"] = float(f"{(360.0 / n) % 360:.6g}") if n > 1 else 0.0
    elif layout == "random_offset":
        crank["offset_deg"] = float(rng.randrange(0, 360, 5))
    else:
        crank["angles_deg"] = [0.0] + [float(rng.randrange(0, 360, 5)) for _ in range(n - 1)]
    if rng.random() < 0.15:
        crank["angle_error_deg"] = [_r(rng, -2, 2, 2) for _ in range(n)] if rng.random() < 0.5 else _r(rng, -2, 2, 2)

    masses = [_r(rng, 400, 1500, 3) for _ in range(n)]
    carts = {"count": n, "sides": sides, "mass": masses if rng.random() < 0.4 else masses[0],
             "geometry": {"a": 0.27, "b": 0.37, "p": 0.52, "e": 0.21, "D": 0.22, "d": 0.046, "com_height": 0.0}}

    # Reducer: the crank runs at omega_n/u = 6 ... 15 rad/s.
    u = float(f"{motor['omega_nominal'] / rng.uniform(6.5, 14.0):.3g}")
    eta = _r(rng, 0.85, 0.97, 3)
    reducer = {"ratio": u, "efficiency": eta, "inertia": _pick(rng, [(0.036, 1), (0.046, 1)]), "delta": 1.0}

    # Loads scaled to the motor: the mean load torque at the crank over a revolution is about
    # L·M_n·u·η for forces opposing the velocity (a force F against v does F·4r/(2π) per revolution).
    M_n = motor["breakdown_torque"] / motor["overload_ratio"]
    L = _pick(rng, [(_r(rng, 0.05, 0.6, 3), 4), (_r(rng, 0.6, 1.0, 3), 4), (_r(rng, 1.0, 1.4, 3), 2)])
    direction = _pick(rng, [("opposes_velocity", 3), ("as_printed", 1)])
    weights = [rng.uniform(0.3, 1.0) if rng.random() < 0.85 else 0.0 for _ in range(n)]
    if sum(weights) == 0:
        weights[0] = 1.0
    total_force = L * M_n * u * eta * math.pi / (2 * r)
    mu = _pick(rng, [(0.0, 3), (_r(rng, 0.02, 0.12, 2), 1)])
    f_front, f_rear, r_front, r_rear = [], [], [], []
    for w in weights:
        F = total_force * w / sum(weights)
        share = rng.uniform(0.3, 0.7)
        R = _r(rng, 0, 12000, 3) if rng.random() < 0.6 else 0.0
        if mu > 0:  # the rolling resistance takes a part of the force
            F = max(0.0, F - mu * 2 * R)
        f_front.append(float(f"{F * share:.4g}"))
        f_rear.append(float(f"{F * (1 - share):.4g}"))
        r_front.append(R)
        r_rear.append(R)
    per_cart = rng.random() < 0.5 or len(set(f_front)) > 1 and rng.random() < 0.5
    loads = {"roller_force_direction": direction, "gravity": _pick(rng, [(9.81, 9), (0.0, 1)])}
    for key, vals in (("roller_force_front", f_front), ("roller_force_rear", f_rear),
                      ("roller_normal_front", r_front), ("roller_normal_rear", r_rear)):
        loads[key] = vals if per_cart else vals[0]
    if mu > 0:
        loads["rolling_resistance"] = mu
    friction = _pick(rng, [(0.0, 3), (_r(rng, 0.004, 0.02, 2), 2)])
    loads["guide_friction"] = {"coefficient": friction}

    coupling_type = _pick(rng, [("elastic", 6), ("rigid", 4)])
    coupling = {"type": coupling_type, "inertia": 0.32}
    if coupling_type == "elastic":
        coupling["stiffness"] = _log(rng, 5e4, 5e5)
        coupling["damping"] = _pick(rng, [(0.0, 1), (_log(rng, 500, 8000), 4)])

    flywheel = {"inertia": 0.0, "location": "crankshaft"}
    fw = rng.random()
    if fw < 0.3:
        flywheel = {"inertia": _log(rng, 5, 300), "location": "crankshaft"}
    elif fw < 0.45:
        flywheel = {"inertia": _log(rng, 0.05, 2), "location": "motor_shaft"}

    # Motor.
    m = {"omega_sync": motor["omega_sync"], "omega_nominal": motor["omega_nominal"],
         "overload_ratio": motor["overload_ratio"], "breakdown_torque": motor["breakdown_torque"],
         "rotor_inertia": motor["rotor_inertia"], "model": law, "voltage": 380.0, "frequency": 50.0,
         "connection": "delta" if method == "star_delta" or rng.random() < 0.8 else "star"}
    if law != "kloss" or rng.random() < 0.5:
        m["catalogue"] = dict(motor["catalogue"])
    if law == "kloss_dynamic" and rng.random() < 0.3:
        m["torque_time_constant"] = _r(rng, 0.005, 0.05, 2)
    from_rest = rng.random() < 0.6
    omega_run = motor["omega_nominal"] / u
    initial = {"crank_angle_deg": float(rng.randrange(0, 360, 5)),
               "crank_speed": 0.0 if from_rest else float(f"{omega_run * rng.uniform(0.95, 1.01):.4g}"),
               "twist": 0.0}
    start = {"method": method}
    t_on = 0.0 if rng.random() < 0.7 else _r(rng, 0.1, 0.8, 2)
    if t_on > 0:
        start["t_on"] = t_on
    has_current = law in ("circuit", "park")
    if method == "star_delta":
        if rng.random() < 0.6:
            start["changeover_speed"] = _r(rng, 0.8, 0.97, 3) * motor["omega_sync"]
            start["changeover_speed"] = float(f"{start['changeover_speed']:.4g}")
        else:
            start["changeover_time"] = float(f"{t_on + rng.uniform(0.3, 2.5):.3g}")
        if rng.random() < 0.4:
            start["changeover_gap"] = _r(rng, 0.02, 0.06, 2)
    elif method == "soft_starter":
        start["initial_voltage"] = _r(rng, 0.3, 0.8, 2)
        start["ramp_time"] = _r(rng, 0.5, 3.0, 2)
        if has_current and rng.random() < 0.6:
            I_n = motor["catalogue"]["current"]
            start["current_limit"] = float(f"{I_n * rng.uniform(2.0, 5.0):.3g}")
    elif method == "frequency_converter":
        start["initial_frequency"] = _r(rng, 1.0, 10.0, 2)
        start["ramp_time"] = _r(rng, 0.5, 3.0, 2)
        if rng.random() < 0.5:
            start["boost"] = _r(rng, 0.02, 0.1, 2)
    m["start"] = start

    # Run length: shorter than the start, a few revolutions, many revolutions.
    kind = _pick(rng, [("short", 2), ("medium", 5), ("long", 3)])
    t_end = {"short": _r(rng, 0.2, 1.5, 2), "medium": _r(rng, 2.0, 6.0, 2), "long": _r(rng, 7.0, 16.0, 2)}[kind]
    t_end = float(f"{t_end + t_on:.3g}")
    if rng.random() < 0.15 and t_end > t_on + 1.0:
        stop = {"t_off": float(f"{t_on + (t_end - t_on) * rng.uniform(0.4, 0.8):.3g}")}
        if rng.random() < 0.5:
            stop["brake_torque"] = _r(rng, 50, 300, 2)
            if rng.random() < 0.5:
                stop["brake_delay"] = _r(rng, 0.05, 0.3, 2)
        if "changeover_time" in start and stop["t_off"] <= start["changeover_time"]:
            stop["t_off"] = float(f"{start['changeover_time'] + 0.2:.3g}")
        if rng.random() < 0.3 and stop["t_off"] + 0.3 < t_end:
            stop["t_restart"] = float(f"{stop['t_off'] + 0.3:.3g}")
            stop.pop("brake_torque", None)
            stop.pop("brake_delay", None)
        m["stop"] = stop
    if not from_rest and t_on > 0 and rng.random() < 0.5:
        notes.append("begins at speed with the motor switched on later")

    simulation = {"t_end": t_end, "output_step": 0.005, "accuracy": 1e-6,
                  "steady_window_revolutions": _pick(rng, [(5, 3), (3, 1), (2, 1)])}
    if rng.random() < 0.15:
        simulation["reactions"] = False

    sizing = {}
    if rng.random() < 0.5:
        sizing["starts_per_hour"] = float(rng.choice([1, 2, 5, 10, 20, 30]))
    if rng.random() < 0.5:
        sizing["coupling_rated_torque"] = float(f"{M_n * u * eta * rng.uniform(0.8, 4.0):.3g}")
    if rng.random() < 0.25:
        sizing["motor_nominal_power"] = motor["catalogue"]["power"]
    if rng.random() < 0.3:
        sizing["target_delta"] = _r(rng, 0.01, 0.1, 2)
    if rng.random() < 0.25:
        sizing["motor_efficiency"] = _r(rng, 0.85, 0.93, 2)
    if rng.random() < 0.4:
        sizing["bearing_rating"] = {"guide_roller": _r(rng, 20e3, 100e3, 2), "rod_end": _r(rng, 50e3, 300e3, 2),
                                    "crank_pin": _r(rng, 100e3, 500e3, 2), "main_bearing": _r(rng, 100e3, 500e3, 2)}

    reduced = {"kinematics": _pick(rng, [("exact", 9), ("truncated", 1)]),
               "integrator": _pick(rng, [("cvode", 9), ("baranov", 1)]),
               "guide_normals": _pick(rng, [("kinetostatic", 3), ("quasi_static", 1)])}
    if reduced["integrator"] == "baranov" and not (coupling_type == "rigid" and law == "kloss" and
                                                   method == "direct_on_line" and t_on == 0 and "stop" not in m):
        # Baranov's scheme steps a one-mass model with a torque of the speed alone (the parser
        # refuses it otherwise: seeds 24, 34, 35 of the first runs).
        reduced["integrator"] = "cvode"
    if reduced["integrator"] == "baranov":
        reduced["baranov_step_deg"] = 1.0

    if (rods_model == "massless" and coupling_type == "elastic" and not crank["inertia_per_crank"]
            and not crank["shaft_inertia"] and not (flywheel["location"] == "crankshaft" and flywheel["inertia"] > 0)):
        # The crank side of an elastic coupling needs an inertia of its own (the parser refuses
        # a massless crank side: seed 19 of the first runs).
        crank["inertia_per_crank"] = 1.0
    scene = {"source": f"generated by scripts/consistency, seed {seed}, attempt {attempt}",
             "simulation": simulation, "initial": initial, "crank": crank, "rods": rods, "carts": carts,
             "motor": m, "reducer": reducer, "coupling": coupling, "flywheel": flywheel, "loads": loads,
             "reduced": reduced}
    if sizing:
        scene["sizing"] = sizing
    _maybe_torsional_chain(seed, attempt, scene, model, notes)
    plan = make_plan(rng, scene, model, plan_rates or {})
    return Machine(seed, attempt, scene, model, plan, notes)


def _maybe_torsional_chain(seed, attempt, scene, model, notes):
    """The crankshaft as a torsional chain on some multibody machines (crankshaft.torsional_stiffness,
    docs/models.md): throws 0.3 m apart in a random order along the shaft, a steel shaft's G·I_p
    (a 70 ... 140 mm shaft, 2e5 ... 3e6 N·m²), damped or not, on runs of up to 4 s, under the
    constrained formulation the chain needs (with lagged friction normals). Drawn from a stream of its own, so every other
    machine of a seed is the one it was before the chain was added."""
    crng = random.Random(f"rollerdyn-consistency/{seed}/{attempt}/chain")
    n = scene["carts"]["count"]
    # Short runs only: the shaft's modes (hundreds to thousands of rad/s) cost the multibody model
    # some six times the steps of a rigid crankshaft, and the harness's test run must stay short.
    if model != "multibody" or n < 2 or scene["simulation"]["t_end"] > 4.0 or crng.random() >= 0.12:
        return
    crank = scene["crank"]
    rod_inertia = scene["rods"]["model"] == "distributed" or (scene["rods"]["model"] == "split"
                                                              and scene["rods"].get("mass", 0) > 0)
    if not (rod_inertia or crank.get("inertia_per_crank") or crank.get("shaft_inertia")):
        crank["inertia_per_crank"] = 1.0  # each throw of the chain needs an inertia of its own
    order = list(range(n))
    crng.shuffle(order)
    chain = {"throw_positions": [float(f"{0.2 + 0.3 * k:.3g}") for k in order],
             "torsional_stiffness": float(f"{_log(crng, 2e5, 3e6):.3g}")}
    if crng.random() < 0.5:
        chain["torsional_damping"] = float(f"{_log(crng, 20, 500):.3g}")
    scene["crankshaft"] = chain
    scene["simulation"]["formulation"] = "constrained"
    if scene["loads"].get("guide_friction", {}).get("coefficient", 0.0) > 0:
        scene["loads"]["guide_friction"]["normal_force"] = "lagged"
    notes.append("crankshaft as a torsional chain")


DEFAULT_RATES = {
    "python": 0.25,       # (a) the same scene through rd.simulate
    "report_every": 25,   # (a) rollerdyn report on every Nth seed (~10 s each)
    "double": 0.4,        # (b) the run again with 2·t_end (when a steady state was reached)
    "sweep_every": 10,    # (e) a small sweep with --minimize on every Nth seed (reduced model)
    "flywheel": 0.6,      # (e) the flywheel proposal run (when one is printed)
    "perturb": 0.3,       # (g) one given key changed
    "other_model": 0.7,   # (h) the other model (where the physics is the same)
    "shift": 0.4,         # (i) the switch-on time shifted (a start from rest)
}


def make_plan(rng, scene, model, rates):
    """Which extra runs this machine gets; drawn from the machine's own stream (reproducible)."""
    r = dict(DEFAULT_RATES)
    r.update(rates)
    return {"python": rng.random() < r["python"],
            "double": rng.random() < r["double"],
            "flywheel": rng.random() < r["flywheel"],
            "perturb": rng.random() < r["perturb"],
            "other_model": rng.random() < r["other_model"],
            "shift": rng.random() < r["shift"],
            "perturb_pick": rng.random(),
            "report_every": r["report_every"],
            "sweep_every": r["sweep_every"]}


def same_physics(scene):
    """Whether the two models integrate the same equations (docs/models.md): rods split or
    massless, no guide friction, exact kinematics, CVODE in the reduced model. Then the motion,
    the drive torques and every verdict drawn from them agree to the integration tolerance."""
    # A torsional chain is the multibody model's alone: the reduced model keeps a rigid crankshaft.
    return ("torsional_stiffness" not in scene.get("crankshaft", {})
            and scene["rods"]["model"] in ("split", "massless")
            and scene["loads"].get("guide_friction", {}).get("coefficient", 0.0) == 0.0
            and scene["reduced"].get("kinematics", "exact") == "exact"
            and scene["reduced"].get("integrator", "cvode") == "cvode")


def get_key(scene, path):
    """scene["a"]["b"] for "a.b"; None when absent."""
    d = scene
    for p in path.split("."):
        if not isinstance(d, dict) or p not in d:
            return None
        d = d[p]
    return d


def set_key(scene, path, value):
    d = scene
    parts = path.split(".")
    for p in parts[:-1]:
        d = d.setdefault(p, {})
    d[parts[-1]] = value


def given_keys(scene, prefix=""):
    """Every leaf key path the scene gives (lists are leaves)."""
    out = []
    for k, v in scene.items():
        p = f"{prefix}{k}"
        if isinstance(v, dict):
            out += given_keys(v, p + ".")
        else:
            out.append(p)
    return out
