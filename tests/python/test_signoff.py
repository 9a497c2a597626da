"""rd.signoff: the sheet of `rollerdyn signoff` as a dict, from the same run, modal analysis and
summary; a coupling rated far below its torque FAILs and the sheet is not signed off."""

import rollerdyn as rd
from conftest import model


def test_signoff_returns_the_sheet_with_a_failing_coupling(tmp_path):
    scene = rd.Scene.load(model("balanced-4cart.yaml")).with_(
        {"simulation.t_end": 3, "sizing.coupling_rated_torque": 100})
    sheet = rd.signoff(scene, out_dir=tmp_path)
    assert sheet["counts"]["FAIL"] >= 1
    assert sheet["overall"].startswith("NOT SIGNED OFF")
    coupling = next(c for c in sheet["checks"] if c["check"] == "coupling")
    assert coupling["verdict"] == "FAIL" and coupling["limit"] == 1.0 and coupling["method"]
    assert sheet["overrides"] == ["simulation.t_end=3", "sizing.coupling_rated_torque=100"]
    assert sheet["tool_version"].startswith(f"rollerdyn {rd.__version__}")
    assert (tmp_path / "signoff.json").exists() and (tmp_path / "signoff.html").exists()
