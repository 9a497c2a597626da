"""Shared set-up of the Python module's tests (run by ctest: tests/CMakeLists.txt sets
PYTHONPATH to build/python and ROLLERDYN_BINARY to the command line built beside it)."""

import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("ROLLERDYN_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
BINARY = pathlib.Path(os.environ.get("ROLLERDYN_BINARY", SOURCE_DIR / "build" / "rollerdyn"))
# Catalogue fits kept by the tests go to the build folder, never to the user's cache (ctest sets
# the same; a pytest run by hand gets it here, before any fit and for every command started).
os.environ.setdefault("ROLLERDYN_CACHE_DIR", str(BINARY.parent / "test-fit-cache"))


def model(name):
    """A shipped scene file, as a path relative to the source folder (tests run there)."""
    return f"model/{name}"


def cli(*args, check=True, timeout=600):
    """Runs the command line from the source folder; returns the CompletedProcess."""
    r = subprocess.run([str(BINARY), *map(str, args)], cwd=SOURCE_DIR, capture_output=True, text=True,
                       timeout=timeout)
    if check and r.returncode != 0:
        raise AssertionError(f"rollerdyn {' '.join(map(str, args))} exited {r.returncode}:\n{r.stdout}{r.stderr}")
    return r


@pytest.fixture(autouse=True)
def in_source_dir(monkeypatch):
    """Scene paths in the tests are relative to the source folder, as in the docs."""
    monkeypatch.chdir(SOURCE_DIR)
