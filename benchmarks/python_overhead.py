"""What the Python layer costs on one run of the default scene.

Alternates, pair by pair (A B A B ...):
  A  in this process: rd.simulate(scene), its tables as DataFrames, summary, and Result.write(dir)
     (the files `rollerdyn simulate` writes);
  B  `rollerdyn simulate SCENE --out DIR` in a child process (the same run and files);
and prints the CPU seconds of each (A: this process's CPU time, which counts the worker thread
the run executes on; B: the child's user + system time) with the median of the per-pair ratios
A/B. B also pays for its own process start and scene parsing, so a ratio near 1 means the Python
layer adds nothing measurable. Machines shared with other work are noisy: quote the median ratio.

Usage (from the repository root, after bash scripts/setup.sh):
  PYTHONPATH=build/python /usr/bin/python3 benchmarks/python_overhead.py [PAIRS] [SCENE]
"""

import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

import rollerdyn as rd


def child_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def main():
    pairs = int(sys.argv[1]) if len(sys.argv) > 1 else 10
    scene_path = sys.argv[2] if len(sys.argv) > 2 else "model/balanced-4cart.yaml"
    binary = os.environ.get("ROLLERDYN_BINARY", "build/rollerdyn")
    scene = rd.Scene.load(scene_path)
    out = tempfile.mkdtemp(prefix="rollerdyn-python-overhead-")
    rows = []
    for i in range(pairs + 1):  # the first pair warms caches and is not counted
        c0, w0 = time.process_time(), time.perf_counter()
        r = rd.simulate(scene)
        c1 = time.process_time()
        r.timeseries, r.reactions, r.summary  # the tables as pandas DataFrames, the summary as a dict
        convert = time.process_time() - c1
        r.write(os.path.join(out, "python"))
        a_cpu, a_wall = time.process_time() - c0, time.perf_counter() - w0
        c0, w0 = child_cpu(), time.perf_counter()
        subprocess.run([binary, "simulate", scene_path, "--out", os.path.join(out, "cli")], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        b_cpu, b_wall = child_cpu() - c0, time.perf_counter() - w0
        if i:
            rows.append((a_cpu, b_cpu, a_wall, b_wall, convert))
    med = statistics.median
    print(f"{scene_path}: {pairs} pairs (after one warm-up pair)")
    print(f"  CPU  python {med(r[0] for r in rows):.4f} s, command line {med(r[1] for r in rows):.4f} s (medians)")
    ratios = sorted(r[0] / r[1] for r in rows)
    print(f"  CPU  ratio python / command line: median {med(ratios):.3f}, min {ratios[0]:.3f}, max {ratios[-1]:.3f}")
    print(f"  of python's CPU: tables to DataFrames and summary to a dict {1e3 * med(r[4] for r in rows):.2f} ms")
    wall = sorted(r[2] / r[3] for r in rows)
    print(f"  wall ratio python / command line: median {med(wall):.3f}, min {wall[0]:.3f}, max {wall[-1]:.3f}")


if __name__ == "__main__":
    main()
