#!/usr/bin/python3
"""Mutation audit: does every physics law, force element, output column and summary metric have
a test that fails when it is wrong?

Each plant of scripts/mutation-plants.txt (a small, realistic error: file, exact code snippet,
replacement) is applied in turn to a scratch copy of the repository (a git worktree at the
commit under audit), the scratch build is rebuilt incrementally (ccache), the whole ctest suite
runs (`rollerdyn validate` included, as the test validate.claims), and the plant is reverted. A
plant is *caught* when at least one test fails, and *caught by its law's test* when one of the
failing tests matches the plant's `expect:` patterns (a test written for that law, not a
cross-model comparison that happened to notice).

Usage (from the repository root; long: one whole-suite run per plant):
  nice -n 19 /usr/bin/python3 scripts/mutation-audit.py                  # every plant
  /usr/bin/python3 scripts/mutation-audit.py --check                     # only verify the plants apply
  nice -n 19 /usr/bin/python3 scripts/mutation-audit.py --only P12,P03   # some plants, in this order
  /usr/bin/python3 scripts/mutation-audit.py --law-tests                 # quick: each plant against its
                                                                         # law's tests only (minutes)
  options: --scratch DIR (default /tmp/rollerdyn-mutation; kept between runs, so its build stays
  warm), --commit REV (default HEAD), --out DIR (default validation/mutation), --jobs N (default 2),
  --test-timeout S (default 600: a plant that makes a test hang is caught by the timeout),
  --fresh-baseline (run the unplanted suite again even when it passed at this commit in the scratch
  build before; by default that earlier pass is reused, so a re-run of one plant costs one suite run)
Cost: a plant costs one incremental build (seconds with a warm ccache, minutes for a header many
files include) plus one whole-suite run, which is 90-98 % of it.
Writes OUT/audit.md (the table, the command and the duration) and OUT/audit.json, updated after
every plant. Exit status 0 when every plant is caught by its law's test, 1 otherwise.

--law-tests answers only the last question, for every plant at one commit: each plant is built
and then only the tests its `expect:` patterns name are run (after checking that the unplanted
code passes them). A whole audit takes hours; this takes minutes, so it can follow every change
of the code or the tests. It cannot tell which other tests would fail too: that needs the whole
suite. Writes OUT/law-tests.md and OUT/law-tests.json.
"""
import argparse
import contextlib
import datetime
import json
import os
import re
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PLANTS = os.path.join(ROOT, "scripts", "mutation-plants.txt")


class PlantError(Exception):
    pass


def parse_plants(path):
    """[{id, name, law, expect: [regex], edits: [(file, find, replace)]}]"""
    plants, cur, mode, buf, file_ = [], None, None, [], None
    pending_find = None

    def close_block():
        nonlocal mode, buf, pending_find
        text = "\n".join(buf) + "\n" if buf else ""
        if mode == "find":
            pending_find = text
        elif mode == "replace":
            if pending_find is None or file_ is None:
                raise PlantError(f"{cur['id']}: '+++ replace' without 'file:' and '--- find' before it")
            cur["edits"].append((file_, pending_find, text))
            pending_find = None
        mode, buf = None, []

    with open(path, encoding="utf-8") as f:
        for raw in f:
            line = raw.rstrip("\n")
            if line.startswith("=== "):
                if cur:
                    close_block()
                    plants.append(cur)
                parts = line[4:].split(None, 1)
                cur = {"id": parts[0], "name": parts[1] if len(parts) > 1 else "", "law": "", "expect": [], "edits": []}
                file_, pending_find = None, None
                continue
            if cur is None:
                continue
            if line == "--- find":
                close_block()
                mode = "find"
                continue
            if line == "+++ replace":
                close_block()
                mode = "replace"
                continue
            if mode in ("find", "replace"):
                if line.startswith(("law:", "expect:", "file:")) or (line == "" and mode == "replace"):
                    close_block()
                else:
                    buf.append(line)
                    continue
            if line.startswith("law:"):
                cur["law"] = line[4:].strip()
            elif line.startswith("expect:"):
                cur["expect"] = line[7:].split()
            elif line.startswith("file:"):
                file_ = line[5:].strip()
    if cur:
        close_block()
        plants.append(cur)
    for p in plants:
        if not p["edits"]:
            raise PlantError(f"{p['id']}: no edit")
        if not p["expect"]:
            raise PlantError(f"{p['id']}: no expect: patterns (the tests written for its law)")
    ids = [p["id"] for p in plants]
    if len(ids) != len(set(ids)):
        raise PlantError("duplicate plant ids")
    return plants


def check_plant(root, plant):
    """Raises PlantError unless every find text occurs exactly once in its file under root."""
    for file_, find, _ in plant["edits"]:
        path = os.path.join(root, file_)
        if not os.path.exists(path):
            raise PlantError(f"{plant['id']}: {file_} does not exist")
        text = open(path, encoding="utf-8").read()
        n = text.count(find)
        if n != 1:
            raise PlantError(f"{plant['id']} ({plant['name']}): the snippet occurs {n} times in {file_} "
                             f"(expected once); update the plant:\n{find}")


def apply_plant(root, plant):
    for file_, find, replace in plant["edits"]:
        path = os.path.join(root, file_)
        text = open(path, encoding="utf-8").read()
        with open(path, "w", encoding="utf-8") as f:
            f.write(text.replace(find, replace, 1))


@contextlib.contextmanager
def planted(scratch, plant, jobs, log):
    """The scratch copy with the plant in and rebuilt; yields the build's process (returncode 0
    when it compiled) and takes the plant out again, whatever happens inside."""
    try:
        apply_plant(scratch, plant)
        yield build(scratch, jobs, log)
    finally:
        for file_, _, _ in plant["edits"]:
            run(["git", "checkout", "--", file_], scratch, log)


def compile_error(built):
    return built.stdout.strip().splitlines()[-1][:200]


def run(cmd, cwd, log=None, env=None, check=True):
    proc = subprocess.run(cmd, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if log:
        with open(log, "a") as f:
            f.write(f"[{datetime.datetime.now():%H:%M:%S}] $ {' '.join(cmd)}\n{proc.stdout}\n")
    if check and proc.returncode != 0:
        raise RuntimeError(f"command failed ({proc.returncode}): {' '.join(cmd)}\n{proc.stdout[-3000:]}")
    return proc


def scratch_env(scratch):
    env = dict(os.environ)
    env["CCACHE_BASEDIR"] = scratch  # paths relative to the scratch root: hits across scratch copies
    return env


def prepare_scratch(scratch, commit, jobs, log):
    if not os.path.exists(os.path.join(scratch, ".git")):
        run(["git", "worktree", "add", "--detach", scratch, commit], ROOT, log)
    else:
        run(["git", "checkout", "--detach", "--force", commit], scratch, log)
        run(["git", "reset", "--hard"], scratch, log)
    env = scratch_env(scratch)
    run(["cmake", "-S", ".", "-B", "build", "-DCMAKE_BUILD_TYPE=Release",
         "-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"], scratch, log, env)
    build(scratch, jobs, log, check=True)


BASELINE = os.path.join("build", "mutation-audit-baseline.json")


def baseline_passed(scratch, commit):
    """The number of tests when the unplanted code at this commit passed the whole suite in this
    scratch build before (recorded by record_baseline), else None."""
    path = os.path.join(scratch, BASELINE)
    if not os.path.exists(path):
        return None
    rec = json.load(open(path))
    return rec["tests"] if rec.get("commit") == commit else None


def record_baseline(scratch, commit, tests):
    with open(os.path.join(scratch, BASELINE), "w") as f:
        json.dump({"commit": commit, "tests": tests}, f)


FAILED_LINE = re.compile(r"^\s*\d+\s+-\s+(\S+)\s+\(([^)]*)\)")


def run_tests(scratch, jobs, timeout, log, numbers=None):
    """(failed tests, number of tests run, ctest's exit status); `numbers`: only these ctest test numbers."""
    only = ["-I", "0,0,0," + ",".join(map(str, numbers))] if numbers else []
    proc = run(["ctest", "--test-dir", "build", f"-j{jobs}", "--timeout", str(timeout)] + only,
               scratch, log, scratch_env(scratch), check=False)
    failed, in_list = [], False
    for line in proc.stdout.splitlines():
        if line.startswith("The following tests FAILED"):
            in_list = True
            continue
        if in_list:
            m = FAILED_LINE.match(line)
            if m:
                failed.append(f"{m.group(1)} ({m.group(2)})" if m.group(2) != "Failed" else m.group(1))
    total = re.search(r"tests passed, (\d+) tests failed out of (\d+)", proc.stdout)
    return failed, int(total.group(2)) if total else None, proc.returncode


def matches(expect, failed):
    names = [f.split(" (")[0] for f in failed]
    return [n for n in names if any(re.search(p, n) for p in expect)]


def merged(out_dir, results, plants):
    """With --only: the earlier audit's results for the plants not run now, in plant order."""
    path = os.path.join(out_dir, "audit.json")
    earlier = json.load(open(path))["results"] if os.path.exists(path) else []
    now = {r["id"]: r for r in results}
    keep = {r["id"]: r for r in earlier}
    keep.update(now)
    return [keep[p["id"]] for p in plants if p["id"] in keep]


def cell(text):
    return str(text).replace("|", "\\|")


def build(scratch, jobs, log, check=False):
    """Every target: the suite runs rollerdyn, the test executables, the Python module (python.*,
    notebook.*, docs.*) and the benchmark executables the docs pages' examples call (docs.*)."""
    cmd = ["cmake", "--build", "build", f"-j{jobs}"]
    return run(cmd, scratch, log, scratch_env(scratch), check=check)


def minutes(r):
    if "test_minutes" in r:
        return f"{r['minutes']:.1f} ({r['build_minutes']:.1f} + {r['test_minutes']:.1f})"
    return f"{r['minutes']:.1f}"


def write_outputs(out_dir, meta, results, plants):
    os.makedirs(out_dir, exist_ok=True)
    with open(os.path.join(out_dir, "audit.json"), "w") as f:
        json.dump({"meta": meta, "results": results}, f, indent=2)
    by_id = {p["id"]: p for p in plants}
    done = [r for r in results if r.get("status") == "done"]
    commits = sorted({r.get("commit", meta["commit"])[:10] for r in done})
    caught = sum(1 for r in done if r["failed"])
    own = sum(1 for r in done if r["by_law_test"])
    lines = [
        "# Mutation audit",
        "",
        f"Made by `{meta['command']}` at commit {meta['commit'][:10]} on {meta['started']}, in "
        f"{meta.get('minutes', 0):.0f} minutes ({len(done)} of {len(plants)} plants; "
        f"{meta.get('tests', '?')} ctest tests per plant in this run, `rollerdyn validate` included as validate.claims)."
        + (f" Rows from earlier runs are kept where this run did not repeat them (commits {', '.join(commits)})."
           if len(commits) > 1 else ""),
        "",
        "Each plant is a small, realistic error put into a scratch copy of the code, which is rebuilt and "
        "tested with the whole suite, then taken out again. Plants and their code snippets: "
        "`scripts/mutation-plants.txt`; what each plant breaks is in the column \"law\". \"By its law's test\" "
        "names the failing tests written for that law (the plant's expected tests); \"all failing tests\" "
        "lists every test that failed.",
        "",
        f"**{caught} of {len(done)} plants run caught, {own} by a test written for their law.**",
        "",
    ]
    not_run = [p["id"] for p in plants if p["id"] not in {r["id"] for r in results}]
    if not_run:
        lines += [
            f"**Partial audit: {len(plants) - len(not_run)} of {len(plants)} plants run.** Not run yet (no verdict, "
            f"caught or not): {', '.join(not_run)}.",
            "",
        ]
    lines += [
        "| plant | law | caught | by its law's test | all failing tests | minutes (build + tests) | commit |",
        "|---|---|---|---|---|---|---|",
    ]
    for r in results:
        p = by_id[r["id"]]
        if r.get("status") != "done":
            lines.append(f"| {r['id']} {p['name']} | {cell(p['law'])} | {r.get('status')} | | {cell(r.get('error', ''))} | | |")
            continue
        failed = r["failed"]
        shown = ", ".join(failed[:12]) + (f", … ({len(failed)} in all)" if len(failed) > 12 else "")
        lines.append(f"| {r['id']} {p['name']} | {cell(p['law'])} | {'yes' if failed else '**SURVIVED**'} | "
                     f"{', '.join(r['by_law_test']) if r['by_law_test'] else '**none**'} | {shown} | {minutes(r)} | "
                     f"{r.get('commit', meta['commit'])[:10]} |")
    notes = [r for r in results if r.get("note")]
    if notes:
        lines += ["", "Notes (written by hand into audit.json beside the row; a re-run of the plant replaces the row):", ""]
        lines += [f"- {r['id']}: {r['note']}" for r in notes]
    with open(os.path.join(out_dir, "audit.md"), "w") as f:
        f.write("\n".join(lines) + "\n")


def ctest_listing(scratch):
    """[(ctest's test number, test name)] of the scratch build."""
    listing = run(["ctest", "--test-dir", "build", "-N"], scratch, env=scratch_env(scratch)).stdout
    return [(int(n), name) for n, name in re.findall(r"Test\s+#(\d+): (\S+)", listing)]


def law_test_numbers(tests, patterns):
    """The numbers of the tests whose names match any of the patterns, matched as `matches` does
    (Python's re.search; ctest's own -R engine allows too few parentheses for a union)."""
    return [n for n, name in tests if any(re.search(p, name) for p in patterns)]


def run_law_tests(scratch, plants, args, commit, log, t0):
    """The quick mode (--law-tests): every plant against its own law's tests only."""
    tests = ctest_listing(scratch)
    union = law_test_numbers(tests, [e for p in plants for e in p["expect"]])
    if not union:
        sys.exit("mutation-audit: no test matches the plants' expect: patterns")
    failed, total, rc = run_tests(scratch, args.jobs, args.test_timeout, log, union)
    if failed or rc != 0 or not total:
        sys.exit(f"mutation-audit: the unplanted code fails its law tests ({', '.join(failed) or 'ctest exit ' + str(rc)})")
    print(f"baseline: the {total} law tests of the {len(plants)} plants pass unplanted", flush=True)
    results = []
    for p in plants:
        t1 = time.time()
        r = {"id": p["id"], "name": p["name"]}
        numbers = law_test_numbers(tests, p["expect"])
        with planted(scratch, p, args.jobs, log) as built:
            if built.returncode != 0:
                r.update(status="does not compile", error=compile_error(built))
            elif not numbers:
                r.update(status="no test matches its expect: patterns", error="")
            else:
                failed, ran, _ = run_tests(scratch, args.jobs, args.test_timeout, log, numbers)
                r.update(status="done", ran=ran or 0, by_law_test=matches(p["expect"], failed))
        r["minutes"] = (time.time() - t1) / 60
        results.append(r)
        print(f"{p['id']} {p['name']}: " + ("caught by " + ", ".join(r["by_law_test"]) if r.get("by_law_test") else
                                          r["status"] if r["status"] != "done" else "SURVIVED its law's tests")
              + f" ({r['minutes']:.1f} min)", flush=True)
    build(scratch, args.jobs, log)
    minutes_all = (time.time() - t0) / 60
    caught = sum(1 for r in results if r.get("by_law_test"))
    meta = {"command": "/usr/bin/python3 scripts/mutation-audit.py --law-tests" + (f" --only {args.only}" if args.only else ""),
            "commit": commit, "started": datetime.datetime.fromtimestamp(t0).strftime("%Y-%m-%d %H:%M"),
            "minutes": minutes_all, "law_tests_unplanted": total}
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "law-tests.json"), "w") as f:
        json.dump({"meta": meta, "results": results}, f, indent=2)
    lines = [
        "# Mutation audit, law tests only",
        "",
        f"Made by `{meta['command']}` at commit {commit[:10]} on {meta['started']}, in {minutes_all:.0f} minutes. "
        "Each plant is built into a scratch copy of the code and only the tests written for its law (its "
        "`expect:` patterns in `scripts/mutation-plants.txt`) are run; the unplanted code passes all "
        f"{total} of them. The whole suite's table, with every other test a plant fails, is `audit.md`.",
        "",
        f"**{caught} of {len(results)} plants caught by a test written for their law.**",
        "",
        "| plant | law | law's tests run | caught by |",
        "|---|---|---|---|",
    ]
    for r in results:
        p = next(q for q in plants if q["id"] == r["id"])
        verdict = (", ".join(r["by_law_test"]) if r.get("by_law_test") else
                   "**SURVIVED**" if r["status"] == "done" else r["status"] + ": " + r.get("error", ""))
        lines.append(f"| {r['id']} {p['name']} | {cell(p['law'])} | {r.get('ran', '')} | {cell(verdict)} |")
    with open(os.path.join(args.out, "law-tests.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"{caught} of {len(results)} plants caught by their law's test; {minutes_all:.0f} minutes", flush=True)
    sys.exit(0 if caught == len(results) else 1)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--check", action="store_true", help="only check that every plant applies to the working tree")
    ap.add_argument("--only", default="", help="comma-separated plant ids")
    ap.add_argument("--scratch", default="/tmp/rollerdyn-mutation")
    ap.add_argument("--commit", default="HEAD")
    ap.add_argument("--out", default=os.path.join(ROOT, "validation", "mutation"))
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--test-timeout", type=int, default=600)
    ap.add_argument("--law-tests", action="store_true",
                    help="quick: run only each plant's law tests (its expect: patterns), every plant at one commit")
    ap.add_argument("--fresh-baseline", action="store_true",
                    help="run the unplanted suite even when it passed at this commit in the scratch build before")
    args = ap.parse_args()

    plants = all_plants = parse_plants(PLANTS)
    if args.only:
        wanted = set(args.only.split(","))
        unknown = wanted - {p["id"] for p in plants}
        if unknown:
            sys.exit(f"mutation-audit: no such plant: {', '.join(sorted(unknown))}")
        by_id = {p["id"]: p for p in plants}
        plants = [by_id[i] for i in dict.fromkeys(args.only.split(","))]  # in the order given
    if args.check:
        bad = []
        for p in plants:
            try:
                check_plant(ROOT, p)
            except PlantError as e:
                bad.append(str(e))
        print(f"{len(plants)} plants, {len(plants) - len(bad)} apply to the working tree")
        for b in bad:
            print("  " + b)
        sys.exit(1 if bad else 0)

    scratch = os.path.abspath(args.scratch)
    commit = subprocess.run(["git", "rev-parse", args.commit], cwd=ROOT, capture_output=True, text=True,
                            check=True).stdout.strip()
    log = os.path.join(args.out, "law-tests.log" if args.law_tests else "audit.log")
    os.makedirs(args.out, exist_ok=True)
    open(log, "w").close()
    t0 = time.time()
    meta = {"command": "nice -n 19 /usr/bin/python3 scripts/mutation-audit.py" + (f" --only {args.only}" if args.only else ""),
            "commit": commit, "started": datetime.datetime.now().strftime("%Y-%m-%d %H:%M"), "plants": len(plants)}
    print(f"scratch copy {scratch} at {commit[:10]}: building", flush=True)
    prepare_scratch(scratch, commit, args.jobs, log)
    for p in plants:  # every snippet must be where the plant says before anything runs
        check_plant(scratch, p)
    if args.law_tests:
        run_law_tests(scratch, plants, args, commit, log, t0)
    total = None if args.fresh_baseline else baseline_passed(scratch, commit)
    if total is not None:
        print(f"baseline: the unplanted code at {commit[:10]} passed all {total} tests in this scratch build "
              "before (--fresh-baseline runs it again)", flush=True)
    else:
        failed, total, rc = run_tests(scratch, args.jobs, args.test_timeout, log)
        if failed or rc != 0:
            sys.exit(f"mutation-audit: the unplanted code fails tests ({', '.join(failed) or 'ctest exit ' + str(rc)}); "
                     "an audit needs a passing suite")
        record_baseline(scratch, commit, total)
        print(f"baseline: {total} tests pass ({(time.time() - t0) / 60:.1f} min)", flush=True)
    meta["tests"] = total
    results = []
    for p in plants:
        t1 = time.time()
        r = {"id": p["id"], "name": p["name"], "commit": commit}
        with planted(scratch, p, args.jobs, log) as built:
            r["build_minutes"] = (time.time() - t1) / 60
            if built.returncode != 0:
                r.update(status="does not compile", error=compile_error(built))
            else:
                t2 = time.time()
                failed, _, _ = run_tests(scratch, args.jobs, args.test_timeout, log)
                r["test_minutes"] = (time.time() - t2) / 60
                r.update(status="done", failed=failed, by_law_test=matches(p["expect"], failed))
        r["minutes"] = (time.time() - t1) / 60
        results.append(r)
        meta["minutes"] = (time.time() - t0) / 60
        write_outputs(args.out, meta, merged(args.out, results, all_plants) if args.only else results, all_plants)
        verdict = ("caught by " + ", ".join(r["by_law_test"]) if r.get("by_law_test") else
                   "caught only by " + ", ".join(r["failed"][:4]) if r.get("failed") else
                   r.get("status") if r.get("status") != "done" else "SURVIVED")
        print(f"{p['id']} {p['name']}: {verdict} ({r['minutes']:.1f} min)", flush=True)
    # leave the scratch build as the unplanted code
    build(scratch, args.jobs, log)
    meta["minutes"] = (time.time() - t0) / 60
    write_outputs(args.out, meta, merged(args.out, results, all_plants) if args.only else results, all_plants)
    ok = all(r.get("status") == "done" and r["by_law_test"] for r in results)
    print(f"{sum(1 for r in results if r.get('by_law_test'))} of {len(results)} plants caught by their law's test; "
          f"{meta['minutes']:.0f} minutes", flush=True)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
