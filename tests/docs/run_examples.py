"""Runs every example of one documentation page (README.md, docs/*.md, model/README.md), so that
no example in the docs can stop working unnoticed. Usage (ctest runs it, one entry per page):

    PYTHONPATH=build/python /usr/bin/python3 tests/docs/run_examples.py PAGE

The examples run in a fresh folder holding the repository's model/, examples/, scripts/, docs/,
validation/published/ and build/ (links), so what they write lands there, never in the repository.

- ```sh blocks run with bash, each stopping at its first failing command;
- ```python blocks of the page run in order in one interpreter (this one), like a notebook;
- a ```text block right after a ```sh block is its expected output: each line must appear in what
  the commands printed (stdout and stderr), "..." standing for anything;
- ```yaml blocks must parse, and every key path in them must be a scene key;
- "bash scripts/setup.sh && X" (the README's two commands) is not run again: X is, unless X runs
  the tests, which must then be exactly the command .ci/run runs.
Other blocks are not examples.
"""

import os
import pathlib
import re
import subprocess
import sys
import tempfile

import yaml

import rollerdyn as rd

SOURCE = pathlib.Path(os.environ.get("ROLLERDYN_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
BUILD = pathlib.Path(os.environ.get("ROLLERDYN_BINARY", SOURCE / "build" / "rollerdyn")).resolve().parent
SETUP = "bash scripts/setup.sh && "


def blocks(text):
    """(info, body, first line, follows) of every fenced block; `follows` is the info of the block
    just before it when only blank lines separate them."""
    out, lines, i, prev_end, prev_info = [], text.splitlines(), 0, None, None
    while i < len(lines):
        m = re.match(r"^```(\w*)\s*$", lines[i])
        if not m:
            i += 1
            continue
        start, info, body = i, m.group(1), []
        i += 1
        while i < len(lines) and not lines[i].startswith("```"):
            body.append(lines[i])
            i += 1
        adjacent = prev_end is not None and all(not l.strip() for l in lines[prev_end + 1:start])
        out.append((info, "\n".join(body) + "\n", start + 1, prev_info if adjacent else None))
        prev_end, prev_info = i, info
        i += 1
    return out


def sandbox():
    d = pathlib.Path(tempfile.mkdtemp(prefix="rollerdyn-docs-"))
    for name in ("model", "examples", "scripts", "docs"):
        (d / name).symlink_to(SOURCE / name)
    (d / "build").symlink_to(BUILD)
    (d / "validation").mkdir()
    (d / "validation" / "published").symlink_to(SOURCE / "validation" / "published")
    return d


def shell_script(body, where):
    lines = []
    for line in body.replace("\\\n", " ").splitlines():
        stripped = line.strip()
        if stripped.startswith(SETUP):
            rest = stripped[len(SETUP):]
            if rest.startswith("ctest"):
                ci = (SOURCE / ".ci" / "run").read_text()
                if stripped not in ci.splitlines():
                    raise AssertionError(f"{where}: the test command is not the one .ci/run runs: {stripped}")
                continue
            line = rest
        lines.append(line)
    return "set -e\n" + "\n".join(lines) + "\n"


def check_output(expected, printed, where):
    got = [l.strip() for l in printed.splitlines()]
    for line in expected.splitlines():
        want = line.strip()
        if not want or want == "...":
            continue
        pattern = re.compile(".*".join(re.escape(p) for p in want.split("...")))
        if not any(pattern.search(g) for g in got):
            raise AssertionError(f"{where}: expected output line not printed:\n  {want}\nprinted:\n{printed}")


def key_paths(node, prefix=""):
    if isinstance(node, yaml.MappingNode):
        for k, v in node.value:
            path = f"{prefix}.{k.value}" if prefix else k.value
            if isinstance(v, yaml.MappingNode):
                yield from key_paths(v, path)
            else:
                yield path
    else:
        yield prefix


def main(page):
    page = pathlib.Path(page)
    rel = page.resolve().relative_to(SOURCE.resolve())
    text = page.read_text()
    work = sandbox()
    env = dict(os.environ, PYTHONPATH=str(BUILD / "python"), MPLBACKEND="Agg")
    keys = set(k["key"] for k in rd._core.scene_keys())
    python, last_output, ran = [], "", 0
    for info, body, line, follows in blocks(text):
        where = f"{rel}:{line}"
        if info == "sh":
            r = subprocess.run(["bash", "-c", shell_script(body, where)], cwd=work, env=env,
                               capture_output=True, text=True, timeout=900)
            last_output = r.stdout + r.stderr
            if r.returncode != 0:
                raise AssertionError(f"{where}: exit code {r.returncode}\n{body}\n{last_output}")
            ran += 1
        elif info == "text" and follows == "sh":
            check_output(body, last_output, where)
            ran += 1
        elif info == "python":
            python.append(f"# {where}\n{body}")
        elif info == "yaml":
            for doc in yaml.compose_all(body):
                for path in key_paths(doc):
                    if path not in keys:
                        raise AssertionError(f"{where}: '{path}' is not a scene key")
            ran += 1
    if python:
        script = work / "examples_of_the_page.py"
        script.write_text("\n".join(python))
        r = subprocess.run([sys.executable, str(script)], cwd=work, env=env, capture_output=True, text=True,
                           timeout=900)
        if r.returncode != 0:
            raise AssertionError(f"{rel}: the Python examples failed:\n{r.stdout}{r.stderr}")
        ran += len(python)
    print(f"{rel}: {ran} examples ran in {work}")


if __name__ == "__main__":
    main(sys.argv[1])
