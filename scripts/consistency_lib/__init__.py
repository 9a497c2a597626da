"""The consistency harness behind scripts/consistency: generator.py (machines from seeds),
runner.py (the runs of one machine), invariants.py ((a)-(i)), parse.py (what the product prints),
perturb.py (invariant (g)'s key changes), report.py (the summary table), cli.py (options, jobs,
MPI ranks)."""
