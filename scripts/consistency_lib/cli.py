"""Command line of scripts/consistency: seeds, parallel jobs, MPI ranks, merging, the summary."""

import argparse
import concurrent.futures
import json
import os
import pathlib
import sys
import time

from . import report, runner
from .invariants import INVARIANTS

SOURCE = pathlib.Path(__file__).resolve().parents[2]


def parse_seeds(spec):
    """"0:100" (100 excluded), "3,7,11", or both mixed: "0:10,50,60:62"."""
    seeds = []
    for part in spec.split(","):
        part = part.strip()
        if not part:
            continue
        if ":" in part:
            a, b = part.split(":", 1)
            seeds += list(range(int(a), int(b)))
        else:
            seeds.append(int(part))
    if not seeds:
        raise ValueError(f"--seeds: no seeds in '{spec}'")
    return seeds


def mpi_rank_size():
    """(rank, size) from Open MPI, MPICH/Hydra or Slurm; (0, 1) outside MPI."""
    for r, s in (("OMPI_COMM_WORLD_RANK", "OMPI_COMM_WORLD_SIZE"), ("PMI_RANK", "PMI_SIZE"),
                 ("PMIX_RANK", "PMIX_SIZE"), ("SLURM_PROCID", "SLURM_NTASKS")):
        if os.environ.get(r) is not None and os.environ.get(s) is not None:
            return int(os.environ[r]), int(os.environ[s])
    return 0, 1


def build_parser():
    p = argparse.ArgumentParser(
        prog="scripts/consistency",
        description="Generates valid machines from seeds, runs rollerdyn on each and checks the invariants (a)-(i) "
                    "that its outputs must satisfy (docs/testing.md, section 'Consistency harness'). Exit code 1 when "
                    "any invariant is violated.")
    p.add_argument("--seeds", default="0:20", help="seeds: a:b (b excluded), a list 1,5,9, or both (default 0:20)")
    p.add_argument("--jobs", type=int, default=1, help="machines run at once on this host (default 1)")
    p.add_argument("--out", default="out/consistency", help="output folder (default out/consistency)")
    p.add_argument("--binary", default=str(SOURCE / "build" / "rollerdyn"), help="the rollerdyn command line")
    p.add_argument("--python-dir", default=None, help="folder of the Python module (default: python/ beside --binary)")
    p.add_argument("--invariants", default=None, help="comma-separated letters to check, e.g. a,c,f (default: all)")
    p.add_argument("--report-every", type=int, default=None, help="rollerdyn report on every Nth seed (default 25)")
    p.add_argument("--sweep-every", type=int, default=None, help="a sweep with --minimize on every Nth seed (default 10)")
    p.add_argument("--keep", action="store_true", help="keep every run's files (default: only those of violations)")
    p.add_argument("--merge", action="store_true",
                   help="only merge the rank files results.rank*.jsonl in --out and print the summary")
    p.add_argument("--recheck", action="store_true",
                   help="judge the machines saved in --out (machines/*/context.json, kept for violations) again "
                        "with this harness, without running; rewrites their records in results.jsonl")
    p.add_argument("--quiet", action="store_true", help="no line per machine")
    return p


def main(argv=None):
    args = build_parser().parse_args(argv)
    out = pathlib.Path(args.out)
    if args.merge:
        return _merge(out, sorted(out.glob("results.rank*.jsonl")))
    if args.recheck:
        return _recheck(out, {x.strip() for x in args.invariants.split(",")} if args.invariants else None)
    try:
        seeds = parse_seeds(args.seeds)
    except ValueError as e:
        print(f"consistency: {e}", file=sys.stderr)
        return 2
    which = None
    if args.invariants:
        which = {x.strip() for x in args.invariants.split(",") if x.strip()}
        bad = which - set(INVARIANTS)
        if bad:
            print(f"consistency: --invariants: unknown {sorted(bad)}; expected letters of {sorted(INVARIANTS)}",
                  file=sys.stderr)
            return 2
    binary = pathlib.Path(args.binary).resolve()
    if not binary.exists():
        print(f"consistency: --binary: {binary} does not exist (build it: cmake --build build --target rollerdyn)",
              file=sys.stderr)
        return 2
    python_dir = args.python_dir or str(binary.parent / "python")
    rates = {}
    if args.report_every:
        rates["report_every"] = args.report_every
    if args.sweep_every:
        rates["sweep_every"] = args.sweep_every
    out.mkdir(parents=True, exist_ok=True)
    opts = runner.Options(binary, python_dir, out.resolve(), which, rates, args.keep)
    rank, size = mpi_rank_size()
    mine = seeds[rank::size]
    results_file = out / (f"results.rank{rank}.jsonl" if size > 1 else "results.jsonl")
    marker = out / f"done.rank{rank}"
    marker.unlink(missing_ok=True)
    started = time.time()
    with open(results_file, "w") as f:
        for rec in _run_all(mine, opts, max(1, args.jobs)):
            f.write(json.dumps(rec) + "\n")
            f.flush()
            if not args.quiet:
                bad = [k for k, v in rec["invariants"].items() if v["status"] in ("violation", "error")]
                print(f"[rank {rank}] seed {rec['seed']}: {rec.get('machine')}: {rec['seconds']:.1f} s, "
                      f"{rec.get('motion')}" + (f"; VIOLATED {','.join(bad)}" if bad else ""), flush=True)
    if size == 1:
        return _finish(out, report.read_records([results_file]))
    marker.write_text(json.dumps({"seeds": args.seeds, "size": size, "started": started}))
    if rank != 0:
        return 0
    return _wait_and_merge(out, size, args.seeds, started)


def _run_all(seeds, opts, jobs):
    if jobs == 1:
        for s in seeds:
            yield runner.run_machine(s, opts)
        return
    with concurrent.futures.ProcessPoolExecutor(max_workers=jobs) as ex:
        futures = [ex.submit(runner.run_machine, s, opts) for s in seeds]
        for fut in concurrent.futures.as_completed(futures):
            yield fut.result()


def _wait_and_merge(out, size, spec, started, timeout=7 * 24 * 3600):
    """Rank 0: waits until every rank has written its marker for this run, then merges."""
    t0 = time.time()
    while True:
        ready = 0
        for r in range(size):
            m = out / f"done.rank{r}"
            try:
                d = json.loads(m.read_text())
            except (OSError, json.JSONDecodeError):
                continue
            if d.get("seeds") == spec and d.get("size") == size and d.get("started", 0) >= started - 600:
                ready += 1
        if ready == size:
            break
        if time.time() - t0 > timeout:
            print("consistency: rank 0 gave up waiting for the other ranks; merge later with --merge", file=sys.stderr)
            return 3
        time.sleep(2)
    return _merge(out, [out / f"results.rank{r}.jsonl" for r in range(size)])


def _merge(out, files):
    if not files:
        print(f"consistency: no results.rank*.jsonl in {out}", file=sys.stderr)
        return 2
    recs = report.read_records(files)
    with open(out / "results.jsonl", "w") as f:
        for r in recs:
            f.write(json.dumps(r) + "\n")
    return _finish(out, recs)


def _recheck(out, which):
    recs = report.read_records([out / "results.jsonl"])
    for r in recs:
        folder = pathlib.Path(r["scene"]).parent if r.get("scene") else None
        if folder and (folder / "context.json").exists():
            r["invariants"] = runner.recheck(folder, which)
    with open(out / "results.jsonl", "w") as f:
        for r in recs:
            f.write(json.dumps(r) + "\n")
    return _finish(out, recs)


def _finish(out, recs):
    text = report.table(recs)
    (out / "summary.txt").write_text(text)
    print(text, end="")
    print(f"results: {out / 'results.jsonl'}; scenes: {out / 'machines'}/<seed>/scene.yaml")
    return 1 if report.any_violation(recs) else 0
