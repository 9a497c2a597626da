"""Invariant (g)'s change of one given key: which keys may be changed and to what, so that the
changed scene is still valid (a refused change is counted, not a violation)."""

from . import generator

# Keys never changed: the citation, the counts that fix list lengths, and keys whose change
# needs other keys with it (a method's own keys, a coupling's stiffness).
SKIP = {"source", "carts.count", "motor.start.method", "coupling.type", "motor.model", "rods.model",
        "carts.geometry.D"}  # D: "informational" in the schema (the report's scene table only)
CHOICES = {
    "loads.roller_force_direction": ["opposes_velocity", "as_printed"],
    "flywheel.location": ["crankshaft", "motor_shaft"],
    "reduced.kinematics": ["exact", "truncated"],
    "reduced.integrator": ["cvode", "baranov"],
    "reduced.guide_normals": ["kinetostatic", "quasi_static"],
    "carts.sides": ["same", "opposite", "alternate"],
    "motor.connection": ["star", "delta"],
}
# What a key given as 0 becomes (a plausible value in its allowed range).
FROM_ZERO = {
    "initial.crank_speed": 1.0, "initial.twist": 0.001, "initial.crank_angle_deg": 10.0,
    "crank.inertia_per_crank": 1.0, "crank.shaft_inertia": 1.0, "flywheel.inertia": 20.0,
    "coupling.damping": 1000.0, "loads.gravity": 9.81, "loads.rolling_resistance": 0.02,
    "loads.guide_friction.coefficient": 0.005, "carts.geometry.com_height": 0.1, "crank.offset_deg": 30.0,
    "loads.roller_normal_front": 5000.0, "loads.roller_normal_rear": 5000.0,
    "loads.roller_force_front": 1000.0, "loads.roller_force_rear": 1000.0, "crank.angle_error_deg": 1.0,
}
ANGLES = {"initial.crank_angle_deg", "crank.offset_deg"}


def candidates(scene):
    """Keys of the scene that this module knows how to change."""
    out = []
    for k in generator.given_keys(scene):
        if k in SKIP:
            continue
        v = generator.get_key(scene, k)
        if k == "motor.connection" and generator.get_key(scene, "motor.start.method") == "star_delta":
            continue  # star-delta needs a delta winding
        if k == "reduced.integrator":
            continue  # Baranov's scheme needs its step key; changing it alone is refused
        if isinstance(v, bool) or isinstance(v, (int, float)) or isinstance(v, list) or k in CHOICES:
            out.append(k)
    return sorted(out)


def change(scene, key):
    """(new value, its --set text) for one key of the scene; None when the key cannot be changed."""
    v = generator.get_key(scene, key)
    if key in CHOICES:
        options = [c for c in CHOICES[key] if c != v]
        new = options[0]
        return new, new
    if isinstance(v, bool):
        return (not v), "false" if v else "true"
    if isinstance(v, list):
        if not v:
            return None
        new = list(v)
        i = len(v) - 1
        if isinstance(v[i], str):
            new[i] = "opposite" if v[i] == "same" else "same"
        elif key == "crank.angles_deg":
            if len(v) < 2:
                return None
            new[i] = (v[i] + 15.0) % 360.0
        elif v[i] == 0:
            new[i] = FROM_ZERO.get(key, 1.0)
        else:
            new[i] = v[i] * 1.1
        return new, "[" + ", ".join(str(x) for x in new) + "]"
    if isinstance(v, (int, float)):
        if key in ANGLES:
            new = (v + 15.0) % 360.0
        elif key == "simulation.steady_window_revolutions":
            new = v + 1
        elif v == 0:
            new = FROM_ZERO.get(key)
            if new is None:
                return None
        elif key in ("reducer.efficiency", "simulation.accuracy") or key.endswith("_ratio") or key.endswith(
                "efficiency") or key.endswith("power_factor") or key.endswith("initial_voltage"):
            new = v * 0.95 if v * 1.05 >= 1 else v * 1.05
        else:
            new = v * 1.1
        if isinstance(v, int) and not isinstance(v, bool):
            new = int(round(new)) if key == "simulation.steady_window_revolutions" else new
        new = float(f"{new:.6g}") if isinstance(new, float) else new
        return new, repr(new)
    return None
