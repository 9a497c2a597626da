"""sweep and optimize from Python: the command line's tables, and Python functions as objective
and constraints."""

import json
import math

import numpy.testing
import pytest

import rollerdyn as rd
from conftest import cli, model


def test_sweep_is_the_cli_sweep_table(tmp_path):
    cli("sweep", model("recuperative-2cart.yaml"), "--param", "crank.offset_deg", "--values", "0:180:45",
        "--model", "reduced", "--minimize", "delta", "--out", tmp_path)
    df = rd.sweep(model("recuperative-2cart.yaml"), {"crank.offset_deg": "0:180:45"}, model="reduced",
                  minimize="delta")
    lines = (tmp_path / "sweep.csv").read_text().splitlines()
    header = [h.split("[")[0] for h in lines[0].split(",")]
    assert list(df.columns) == header
    cpu = header.index("cpu_seconds")
    for row, line in zip(df.itertuples(index=False), lines[1:]):
        cells = line.split(",")
        for k, (ours, theirs) in enumerate(zip(row, cells)):
            if k == cpu:
                continue
            assert (ours if isinstance(ours, str) else "%.12g" % ours) == theirs, header[k]
    # The optimum is a run, the command line's: here the run at the parabola's vertex (92.6°), whose
    # δ is below the grid's best (90°).
    optimum, cli_optimum = df.attrs["optimum"], json.loads((tmp_path / "sweep.json").read_text())["optimum"]
    assert (optimum["at"], optimum["value"], optimum["source"]) == (cli_optimum["at"], cli_optimum["value"],
                                                                    "run at the parabola's vertex")
    assert optimum["value"] == optimum["parabola"]["run"]["value"]
    assert optimum["value"] < df.loc[df["crank.offset_deg"] == 90, "delta"].item()
    assert df.attrs["units"]["crank.offset_deg"] == "deg"


def test_sweep_of_words_and_designs():
    scene = rd.Scene.load(model("recuperative-2cart.yaml")).with_({"simulation.t_end": 4})
    grid = rd.sweep(scene, {"crank.offset_deg": [0, 90], "coupling.type": ["rigid"]}, model="reduced")
    assert list(grid["coupling.type"]) == ["rigid", "rigid"]
    designs = rd.sweep(scene, designs=[{"crank.offset_deg": 0}, {"crank.offset_deg": 90}], model="reduced")
    # The same runs either way (δ is NaN, i.e. not applicable, where a 4 s run reaches no steady state).
    numpy.testing.assert_array_equal(designs["delta"].to_numpy(), grid["delta"].to_numpy())
    with pytest.raises(ValueError, match="did you mean 'crank.offset_deg'"):
        rd.sweep(scene, {"crank.ofset_deg": [0]}, model="reduced")


def test_optimize_with_a_python_constraint_is_the_metric_constraint():
    scene = rd.Scene.load(model("recuperative-2cart.yaml")).with_({"crank.offset_deg": 30})
    params = {"flywheel.inertia": (0, 400)}
    by_text = rd.optimize(scene, params, "flywheel.inertia", ["delta<=0.25"], model="reduced", max_evals=30)

    def delta_at_most_0_25(row):
        return row["delta"] - 0.25

    by_function = rd.optimize(scene, params, "flywheel.inertia", [delta_at_most_0_25], model="reduced", max_evals=30)
    assert by_text.found and by_function.found
    assert by_function.optimum["parameters"] == by_text.optimum["parameters"]
    assert by_function.optimum["metrics"]["delta"] <= 0.25
    assert "delta_at_most_0_25(row)<=0" in by_function.history.columns
    # Printed as the run at exactly those values (it printed the inertia rounded to 6 digits).
    inertia = by_text.optimum["parameters"]["flywheel.inertia"]
    assert f"flywheel.inertia={inertia!r}" in repr(by_text) and f"flywheel.inertia = {inertia!r} at" in repr(by_text)
    # The same designs were evaluated; the order differs where --method auto's grid stage runs on
    # two threads.
    assert sorted(by_text.history["flywheel.inertia"]) == sorted(by_function.history["flywheel.inertia"])


def test_optimize_with_a_python_objective():
    scene = rd.Scene.load(model("recuperative-2cart.yaml"))
    seen = []

    def unevenness_squared(row):
        seen.append(row["crank.offset_deg"])
        return row["delta"] ** 2

    r = rd.optimize(scene, {"crank.offset_deg": (0, 180)}, unevenness_squared, model="reduced", max_evals=20)
    assert r.found and seen
    assert r.summary["minimize"] == "unevenness_squared"
    best = r.optimum
    assert math.isclose(best["objective"], best["metrics"]["delta"] ** 2)
    assert 60 < best["parameters"]["crank.offset_deg"] < 120  # δ is least near 90° (sweep above)


def test_an_exception_in_a_python_function_stops_the_search_and_is_raised():
    calls = []

    def broken(row):
        calls.append(1)
        raise ZeroDivisionError("my sizing rule failed")

    with pytest.raises(ZeroDivisionError, match="my sizing rule failed"):
        rd.optimize(model("recuperative-2cart.yaml"), {"crank.offset_deg": (0, 180)}, broken, model="reduced",
                    max_evals=50)
    assert len(calls) <= 2
