"""The summary table of a harness run, from its JSON lines records."""

import json
import pathlib
import statistics

from .invariants import TITLES


def read_records(paths):
    recs = []
    for p in paths:
        for line in pathlib.Path(p).read_text().splitlines():
            if line.strip():
                recs.append(json.loads(line))
    recs.sort(key=lambda r: r["seed"])
    return recs


def table(records, max_listed=40):
    """The summary as text: machines, refusals, time per machine, violations per invariant with
    the seed and one line each."""
    ran = [r for r in records if r.get("machine")]
    lines = []
    refused = sum(len(r.get("refused", [])) for r in records)
    models = {m: sum(1 for r in ran if r.get("model") == m) for m in ("multibody", "reduced")}
    motions = {}
    for r in ran:
        motions[r.get("motion")] = motions.get(r.get("motion"), 0) + 1
    secs = [r["seconds"] for r in ran]
    cpus = [r.get("cpu", 0.0) for r in ran]
    lines.append(f"machines run: {len(ran)} (multibody {models['multibody']}, reduced {models['reduced']}); "
                 f"refused by the parser and regenerated: {refused}; harness errors: "
                 f"{sum(1 for r in records if r.get('harness_error'))}")
    lines.append("motion: " + ", ".join(f"{k} {v}" for k, v in sorted(motions.items(), key=lambda x: -x[1])) +
                 f"; steady state reached: {sum(1 for r in ran if r.get('steady'))}")
    if secs:
        lines.append(f"time per machine (wall): median {statistics.median(secs):.2f} s, mean {statistics.mean(secs):.2f} s, "
                     f"max {max(secs):.1f} s (seed {max(ran, key=lambda r: r['seconds'])['seed']})")
        lines.append(f"CPU per machine (all its runs): median {statistics.median(cpus):.2f} s, mean "
                     f"{statistics.mean(cpus):.2f} s, total {sum(cpus):.0f} s; runs {sum(r.get('runs', 0) for r in ran)} "
                     f"in all; the machine's own run: median {statistics.median(r.get('base_cpu', 0) for r in ran):.2f} s CPU")
    lines.append("")
    lines.append(f"{'invariant':<52} {'checked':>7} {'violated':>8} {'n/a':>5} {'errors':>6}")
    for letter, title in TITLES.items():
        st = [r["invariants"].get(letter, {}).get("status") for r in ran]
        if not any(st):
            continue
        lines.append(f"({letter}) {title:<48} {st.count('ok') + st.count('violation'):>7} {st.count('violation'):>8} "
                     f"{st.count('n/a'):>5} {st.count('error'):>6}")
    lines.append("")
    listed = 0
    for letter in TITLES:
        hits = [(r, r["invariants"][letter]) for r in ran if r["invariants"].get(letter, {}).get("status") in
                ("violation", "error")]
        if not hits:
            continue
        lines.append(f"({letter}) {TITLES[letter]}: {len(hits)} machine(s)")
        for r, res in hits:
            for msg in res["messages"][:2]:
                if listed >= max_listed:
                    break
                tag = "ERROR " if res["status"] == "error" else ""
                lines.append(f"  seed {r['seed']}: {tag}{msg[:220]}")
                listed += 1
        if listed >= max_listed:
            lines.append("  ... (more in the JSON lines file)")
            break
    notes = [(r["seed"], n) for r in ran for n in r.get("notes", [])]
    if notes:
        lines.append("")
        lines.append(f"notes ({len(notes)}): " + "; ".join(f"seed {s}: {n[:100]}" for s, n in notes[:5]))
    return "\n".join(lines) + "\n"


def any_violation(records):
    return any(res.get("status") == "violation" for r in records for res in r.get("invariants", {}).values())
