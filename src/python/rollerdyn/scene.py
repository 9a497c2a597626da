"""Scenes: a scene file (or a dict with the same keys) and overrides, immutable."""

import html
import os

import pandas as pd

from . import _core


class Scene:
    """A scene as the command line reads it: the file, then overrides in order.

    Immutable: ``with_`` returns a new scene. Every value passes the scene file's parser, so a
    wrong key or value raises :class:`rollerdyn.SceneError` with the command line's text
    (file, line, key, what was expected, did-you-mean).
    """

    __slots__ = ("_s",)

    def __init__(self, core_scene):
        object.__setattr__(self, "_s", core_scene)

    def __setattr__(self, name, value):
        raise AttributeError("a Scene is immutable: scene.with_({key: value}) makes a changed one")

    @classmethod
    def load(cls, path):
        """The scene file at ``path`` (YAML), as ``rollerdyn simulate path`` reads it."""
        return cls(_core.Scene.load(os.fspath(path)))

    @classmethod
    def from_dict(cls, data, name="scene"):
        """A scene from a dict with the keys of a scene file (nested maps, as in the YAML).

        The same keys and the same errors as a file; errors name ``name`` instead of a file and
        line. Python values map to YAML ones: str is text (so "60" where a number belongs is an
        error, as a quoted "60" in a file is), bool is true/false.
        """
        return cls(_core.Scene.from_data(data, name))

    def with_(self, changes):
        """A new scene with ``changes`` ({"key.path": value, ...}) applied after the overrides
        so far, exactly as ``--set key.path=value`` on the command line (a whole section may be
        given as a dict)."""
        return Scene(self._s.with_(dict(changes)))

    @property
    def name(self):
        """The scene's name: the file's stem, or the name given to from_dict."""
        return self._s.name

    @property
    def path(self):
        """The scene file as given, or None for a scene from a dict."""
        return self._s.path

    @property
    def overrides(self):
        """The overrides applied, in order, as "key.path=value" (the --set arguments)."""
        return tuple(self._s.overrides)

    @property
    def source(self):
        """The citation of the paper the scene comes from (its `source` key)."""
        return self._s.source

    @property
    def effects(self):
        """The effects the scene builds (motor, coupling, rods, loads, friction, gravity, ...)."""
        return tuple(self._s.effects)

    def __getitem__(self, key):
        """The value of ``key`` as the run uses it: given, or the default; None for a key whose
        default follows from other keys (see ``derived()``)."""
        return self._s.value(key)

    def to_dict(self):
        """The keys the file and the overrides give, as a nested dict (Scene.from_dict of it
        gives the same scene)."""
        out = {}
        for key, value in self._s.given():
            node = out
            parts = key.split(".")
            for part in parts[:-1]:
                node = node.setdefault(part, {})
            node[parts[-1]] = value
        return out

    def parameters(self):
        """Every key with its value, unit, where the value came from (file, --set #N, default)
        and meaning: the scene table of the HTML report."""
        return pd.DataFrame(self._s.parameters(), columns=["key", "value", "unit", "from", "meaning"])

    def derived(self):
        """Quantities both models derive from the keys (critical slip, inertias, ...)."""
        return pd.DataFrame(self._s.derived(), columns=["quantity", "value", "unit", "from", "meaning"])

    def __repr__(self):
        where = f"path={self.path!r}" if self.path else "from a dict"
        return f"Scene({self.name!r}, {where}, overrides={list(self.overrides)!r})"

    def _repr_html_(self):
        head = (
            f"<p><b>scene {html.escape(self.name)}</b> ({html.escape(self.path or 'from a dict')}): "
            f"{html.escape(self.source)}<br>overrides: "
            + (", ".join(f"<code>{html.escape(o)}</code>" for o in self.overrides) or "none")
            + "<br>effects: " + html.escape(", ".join(self.effects)) + "</p>"
        )
        return head + self._s.html()


def as_scene(scene):
    """A Scene, or the scene file at a path."""
    if isinstance(scene, Scene):
        return scene
    if isinstance(scene, (str, os.PathLike)):
        return Scene.load(scene)
    raise TypeError(f"expected a rollerdyn.Scene or a scene file path, got {type(scene).__name__}")


def scene_keys():
    """Every key a scene file may contain (docs/scene-reference.md as a table): key, section,
    unit, presence, default, condition, allowed, meaning, source."""
    return pd.DataFrame(_core.scene_keys())
