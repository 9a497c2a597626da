"""The Python interface gives the command line's numbers: the same scene through rd.simulate and
through `rollerdyn simulate` gives identical time series, reactions, crank speed extrema and summary (every key and
value but the CPU-time figures), for both models; Result.write writes the same files byte for
byte."""

import json

import numpy as np
import pytest

import rollerdyn as rd
from conftest import cli, model

# Measured, so they differ between any two runs; motor_fit says whether this process fitted the
# motor's circuit or read it from the fit cache.
TIMING_KEYS = {"cpu_seconds", "real_time_factor", "motor_fit"}


def without_timing(summary):
    return {k: v for k, v in summary.items() if k not in TIMING_KEYS}


def csv_cells(path):
    """Header names (units stripped) and the text of every number of a CSV written by rollerdyn."""
    lines = path.read_text().splitlines()
    header = [h.split("[")[0] for h in lines[0].split(",")]
    return header, [line.split(",") for line in lines[1:]]


@pytest.mark.parametrize("scene_file, model_name", [
    ("balanced-4cart.yaml", "multibody"),       # the default scene, as the README runs it
    ("recuperative-2cart.yaml", "reduced"),
])
def test_python_and_cli_give_identical_numbers(tmp_path, scene_file, model_name):
    cli_dir = tmp_path / "cli"
    cli("simulate", model(scene_file), "--model", model_name, "--out", cli_dir)
    r = rd.simulate(rd.Scene.load(model(scene_file)), model=model_name)
    assert r.complete

    # Every number in memory, printed as the CSV writer prints it (%.12g), is the CLI's text.
    for name, df in (("timeseries", r.timeseries), ("reactions", r.reactions),
                     ("crank_speed_extrema", r.crank_speed_extrema)):
        header, rows = csv_cells(cli_dir / f"{name}.csv")
        assert list(df.columns) == header
        assert len(df) == len(rows)
        ours = [["%.12g" % v for v in row] for row in df.to_numpy()]
        assert ours == rows, f"{name}: a value differs from the command line's"

    summary = json.loads((cli_dir / "summary.json").read_text())
    assert set(r.summary) == set(summary)
    assert without_timing(r.summary) == without_timing(summary)

    # Written by the same writer: the same files, byte for byte (summary.json but its CPU time).
    py_dir = tmp_path / "py"
    r.write(py_dir)
    for f in ("timeseries.csv", "reactions.csv", "crank_speed_extrema.csv"):
        assert (py_dir / f).read_bytes() == (cli_dir / f).read_bytes(), f
    assert without_timing(json.loads((py_dir / "summary.json").read_text())) == without_timing(summary)


def test_overrides_are_the_cli_set(tmp_path):
    """scene.with_ is --set: the same override gives the same run."""
    cli("simulate", model("recuperative-2cart.yaml"), "--model", "reduced", "--set", "crank.offset_deg=60",
        "--set", "simulation.t_end=4", "--out", tmp_path)
    scene = rd.Scene.load(model("recuperative-2cart.yaml")).with_({"crank.offset_deg": 60, "simulation.t_end": 4})
    assert scene.overrides == ("crank.offset_deg=60", "simulation.t_end=4")
    r = rd.simulate(scene, model="reduced")
    header, rows = csv_cells(tmp_path / "timeseries.csv")
    assert [["%.12g" % v for v in row] for row in r.timeseries.to_numpy()] == rows


def test_scene_from_dict_is_the_scene_file():
    """A scene given as a dict (the file's keys) runs exactly like the file."""
    path_scene = rd.Scene.load(model("recuperative-2cart.yaml")).with_({"simulation.t_end": 3})
    dict_scene = rd.Scene.from_dict(path_scene.to_dict(), name="recuperative")
    assert dict_scene.to_dict() == path_scene.to_dict()
    a = rd.simulate(path_scene, model="reduced")
    b = rd.simulate(dict_scene, model="reduced")
    np.testing.assert_array_equal(a.timeseries.to_numpy(), b.timeseries.to_numpy())
    assert b.summary["scene_path"] is None and a.summary["scene_path"].endswith("model/recuperative-2cart.yaml")
