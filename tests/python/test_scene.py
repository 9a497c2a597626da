"""Scenes in Python: the CLI's concepts (file, --set), immutable, and the scene file's errors with
the command line's text."""

import pytest

import rollerdyn as rd
from conftest import cli, model


def test_load_and_read_values():
    s = rd.Scene.load(model("balanced-4cart.yaml"))
    assert s.name == "balanced-4cart"
    assert s.path == "model/balanced-4cart.yaml"
    assert s.overrides == ()
    assert s["crank.offset_deg"] == 90.0
    assert s["carts.count"] == 4 and isinstance(s["carts.count"], int)
    assert s["simulation.reactions"] is True          # a default
    assert s["motor.critical_slip"] is None           # given another way (derived)
    assert "Loveikin" in s.source
    assert "kloss_motor" in s.effects
    params = s.parameters()
    assert list(params.columns) == ["key", "value", "unit", "from", "meaning"]
    assert params.set_index("key").loc["coupling.stiffness", "unit"] == "N·m/rad"


def test_with_returns_a_new_scene_and_leaves_the_old_one():
    s = rd.Scene.load(model("balanced-4cart.yaml"))
    t = s.with_({"crank.offset_deg": 60, "coupling": {"type": "rigid"}})
    assert s["crank.offset_deg"] == 90.0 and t["crank.offset_deg"] == 60.0
    assert t["coupling.type"] == "rigid"
    assert t.overrides == ("crank.offset_deg=60", "coupling={type: rigid}")
    assert t.parameters().set_index("key").loc["crank.offset_deg", "from"] == "--set #1"
    with pytest.raises(AttributeError, match="immutable"):
        s.name = "other"


def test_unknown_key_in_a_file_reads_as_in_the_cli(tmp_path):
    bad = tmp_path / "bad.yaml"
    text = (rd.Scene.load(model("balanced-4cart.yaml"))._s.text).replace("  count: 4", "  cuont: 4")
    bad.write_text(text)
    r = cli("check", bad, check=False)
    assert r.returncode == 2
    with pytest.raises(rd.SceneError) as e:
        rd.Scene.load(bad)
    assert r.stderr == f"rollerdyn: {e.value}\n"
    assert "did you mean 'count'?" in str(e.value)
    assert e.value.file == str(bad)
    assert e.value.line == text.splitlines().index("  cuont: 4") + 1
    assert e.value.key == "carts.cuont"
    assert isinstance(e.value, ValueError)


def test_bad_override_reads_as_the_cli_set():
    r = cli("check", model("balanced-4cart.yaml"), "--set", "crank.offset_deg=400", check=False)
    assert r.returncode == 2
    s = rd.Scene.load(model("balanced-4cart.yaml"))
    with pytest.raises(rd.SceneError) as e:
        s.with_({"crank.offset_deg": 400})
    assert r.stderr == f"rollerdyn: {e.value}\n"
    assert e.value.origin == "--set #1 (crank.offset_deg=400)" and e.value.line is None


def test_from_dict_has_the_file_keys_and_errors_without_lines():
    d = rd.Scene.load(model("balanced-4cart.yaml")).to_dict()
    d["carts"]["cuont"] = d["carts"].pop("count")
    with pytest.raises(rd.SceneError) as e:
        rd.Scene.from_dict(d, name="my-scene")
    assert str(e.value).startswith("my-scene: carts.cuont: expected one of the keys allowed under carts")
    assert "did you mean 'count'?" in str(e.value)
    assert e.value.line is None

    # Text where a number belongs is rejected, as a quoted "10" in a file is.
    d = rd.Scene.load(model("balanced-4cart.yaml")).to_dict()
    d["simulation"]["t_end"] = "10"
    with pytest.raises(rd.SceneError, match=r'simulation.t_end: expected a number > 0 \[s\], got "10"'):
        rd.Scene.from_dict(d)
    with pytest.raises(TypeError):
        rd.Scene.from_dict([1, 2])


def test_unknown_key_lookup_hints():
    with pytest.raises(KeyError, match="did you mean 'crank.offset_deg'"):
        rd.Scene.load(model("balanced-4cart.yaml"))["crank.ofset_deg"]


def test_scene_keys_are_the_schema():
    keys = rd.scene_keys()
    r = cli("schema")
    listed = [line.split(" ")[0] for line in r.stdout.splitlines() if line and not line.startswith(" ")]
    assert list(keys["key"]) == listed
    row = keys.set_index("key").loc["motor.overload_ratio"]
    assert row["unit"] == "-" and "eq. (37)" in row["source"]
