"""Readers of what rollerdyn prints: the console of `simulate`, the report's HTML, the stall
causes in words. Each reader returns plain data (dicts, lists) and never raises on text it does
not recognise: a line it cannot read is simply absent, and the invariants say "not checked" for
it. Every pattern for the product's wording lives here, in one place, so a change of wording is
one edit."""

import html as htmllib
import math
import re

NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"


def number(text):
    """float of a printed number; None for n/a, nan or nothing."""
    if text is None:
        return None
    t = text.strip()
    if t in ("n/a", "", "-", "nan", "null"):
        return None
    try:
        return float(t)
    except ValueError:
        return None


def printed_tolerance(text):
    """Half a unit in the last printed digit of a number as printed (%.4g, %.3f, %.2e ...): the
    largest difference between the printed text and the value it was printed from."""
    t = text.strip().lower()
    mant, _, exp = t.partition("e")
    e = int(exp) if exp else 0
    if "." in mant:
        decimals = len(mant.split(".")[1])
    else:
        decimals = 0
    return 0.5 * 10.0 ** (e - decimals)


def agrees_with_print(printed, value):
    """Whether a printed number is the value, rounded as printed (with a hair for the binary
    representation of the value)."""
    p = number(printed)
    if p is None or value is None:
        return (p is None) == (value is None)
    if isinstance(value, float) and not math.isfinite(value):
        return False
    return abs(p - value) <= printed_tolerance(printed) * (1 + 1e-9) + 1e-12 * abs(value)


# --- the console of `rollerdyn simulate` ------------------------------------------------------

CHECK_LINE = re.compile(r"^    (?P<check>[a-z_]+)\s+(?P<value>\S+)\s+(?P<verdict>pass|FAIL|not applicable|n/a)\s+"
                        r"decided by the (?P<window>.*)$")


def console(text):
    """The facts `simulate` prints: motion, status, steady state, δ, mean speed, energy residual,
    the sizing checks (value, verdict, window), the start-up verdict and run-up time, the joints'
    L10 column. Values stay strings as printed (their precision is the tolerance)."""
    out = {"checks": {}, "joints": {}}
    lines = text.splitlines()
    for i, line in enumerate(lines):
        if line.startswith("motion       "):
            out["motion"] = line[13:].split()[0] if line[13:].split() else ""
        elif line.startswith("status       "):
            out["status"] = line[13:]
        elif line.startswith("crank speed  mean "):
            m = re.match(rf"crank speed  mean (\S+) rad/s, min (\S+), max (\S+)", line)
            if m:
                out["omega_mean"], out["omega_min"], out["omega_max"] = m.groups()
        elif "δ (unevenness) " in line:
            m = re.search(r"δ \(unevenness\) (\S+), H \(dynamics\) (\S+), k_p \(generalised\) (\S+)", line)
            if m:
                out["delta"], out["H"], out["k_p"] = m.groups()
        elif line.startswith("steady state "):
            out["steady_reached"] = not line.startswith("steady state NOT")
        elif line.startswith("energy       residual "):
            m = re.match(rf"energy       residual (\S+) J \(relative (\S+)\)", line)
            if m:
                out["energy_residual"], out["energy_residual_rel"] = m.groups()
        elif line.startswith("start-up     "):
            out["start_method_line"] = line[13:]
            if i + 1 < len(lines):
                out["start_verdict"] = lines[i + 1].strip()
        elif line.startswith("  run-up time"):
            m = re.match(rf"  run-up time \(to 95 % of (\S+) rad/s\)\s+(\S+) s", line)
            out["run_up_time"] = m.group(2) if m else None
        elif line.startswith("  starting torque at the crank"):
            m = re.match(rf"  starting torque at the crank\s+(\S+) N·m", line)
            if m:
                out["starting_torque_crank"] = m.group(1)
        else:
            m = CHECK_LINE.match(line)
            if m:
                out["checks"][m.group("check")] = {"value": m.group("value"), "verdict": m.group("verdict"),
                                                    "window": m.group("window")}
                continue
            m = re.match(r"^  (guide roller, front|guide roller, rear|rod end|crank pin|main bearing)\s{2,}"
                         r"(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s+(.+?)\s*$", line)
            if m:
                out["joints"][m.group(1)] = {"cart": m.group(2), "mean": m.group(3), "amplitude": m.group(4),
                                             "peak": m.group(5), "equivalent_load": m.group(6),
                                             "rating": m.group(7), "life": m.group(8)}
    return out


JOINT_WORDS = {"guide roller, front": "guide_roller_front", "guide roller, rear": "guide_roller_rear",
               "rod end": "rod_end", "crank pin": "crank_pin", "main bearing": "main_bearing"}


# --- the report (report.html) ------------------------------------------------------------------

def _cells(row_html):
    cells = re.findall(r"<td([^>]*)>(.*?)</td>", row_html, flags=re.S)
    return [(attrs, htmllib.unescape(re.sub(r"<[^>]+>", "", body)).strip()) for attrs, body in cells]


def report(html_text):
    """From report.html: the sizing checks (what, value, verdict, colour class), the joint rows
    (name, cart, L10 column), whether the page calls the steady motion stable, and the CSS."""
    out = {"checks": [], "joints": [], "says_stable": "the steady motion is stable" in html_text}
    m = re.search(r"<h3>Checks</h3>(.*?)</table>", html_text, flags=re.S)
    if m:
        for row in re.findall(r"<tr>(.*?)</tr>", m.group(1), flags=re.S):
            c = _cells(row)
            if len(c) >= 4:
                cls = re.search(r'class="([^"]*)"', c[2][0])
                out["checks"].append({"what": c[0][1], "value": c[1][1], "verdict": c[2][1],
                                      "class": cls.group(1) if cls else ""})
    m = re.search(r"<h3>Joints and bearings</h3>(.*?)</table>", html_text, flags=re.S)
    if m:
        for row in re.findall(r"<tr>(.*?)</tr>", m.group(1), flags=re.S):
            c = _cells(row)
            if len(c) >= 8:
                out["joints"].append({"joint": c[0][1], "cart": c[1][1], "life": c[7][1]})
    m = re.search(r"<style>(.*?)</style>", html_text, flags=re.S)
    out["css"] = m.group(1) if m else ""
    return out


def css_rules(css):
    """[(selector, declarations)] of a flat style sheet (no @media nesting needed here)."""
    rules = []
    for sel, body in re.findall(r"([^{}]+)\{([^{}]*)\}", css):
        for s in sel.split(","):
            rules.append((s.strip(), body))
    return rules


def specificity(selector):
    """CSS specificity (ids, classes/attributes/pseudo-classes, elements) of a simple selector."""
    s = re.sub(r"\([^)]*\)", "", selector)
    ids = len(re.findall(r"#[\w-]+", s))
    classes = len(re.findall(r"\.[\w-]+", s)) + len(re.findall(r"\[[^\]]*\]", s)) + len(re.findall(r":(?!:)[\w-]+", s))
    elements = len(re.findall(r"(?:^|[\s>+~])([a-zA-Z][\w-]*)", s))
    return (ids, classes, elements)


# --- stall causes in words ---------------------------------------------------------------------

# The cause of a drive that does not start or run, as one of four words, from any of the three
# places that name it (the status line, the start-up verdict, the breakdown check's reason).
CAUSES = [
    ("start", [r"starting torque is below the load at the start angle", r"does not start: its starting torque",
               r"starting torque \S+ N·m at the crank is below the load"]),
    ("mean", [r"exceeds even the breakdown torque", r"largest torque \S+ N·m at the crank is below the load averaged",
              r"exceeds the motor's breakdown torque"]),
    ("changeover", [r"changeover speed \S+ rad/s was never reached"]),
    ("peaks", [r"load peaks near a dead centre"]),
]


def stall_cause(text):
    """'start', 'mean', 'changeover', 'peaks' or None (no cause named)."""
    if not text:
        return None
    for cause, patterns in CAUSES:
        if any(re.search(p, text) for p in patterns):
            return cause
    return None


def starting_torque_named(text):
    """The starting torque at the crank a cause text names [N·m], or None."""
    if not text:
        return None
    for p in (rf"starting torque at the crank ({NUM}) N·m", rf"starting torque ({NUM}) N·m",
              rf"starting torque ({NUM}) N·m at the crank"):
        m = re.search(p, text)
        if m:
            return float(m.group(1))
    return None
