"""The documentation's structure: the README lists every page in docs/, every command of the
command line is documented, and every relative link (and #anchor) in the pages resolves. The
examples of the pages are run by tests/docs/run_examples.py."""

import re

from conftest import SOURCE_DIR, cli

PAGES = [SOURCE_DIR / "README.md", SOURCE_DIR / "model" / "README.md", *sorted((SOURCE_DIR / "docs").glob("*.md"))]


def slug(heading):
    """The anchor GitHub gives a heading."""
    s = heading.strip().lower()
    s = re.sub(r"[^\w\- ]", "", s)
    return s.replace(" ", "-")


def anchors(page):
    return {slug(m.group(1)) for m in re.finditer(r"^#+ (.+)$", page.read_text(), re.M)}


def test_the_readme_lists_every_page_of_docs():
    readme = (SOURCE_DIR / "README.md").read_text()
    where_to_read_on = readme[readme.index("## Where to read on"):]
    for page in (SOURCE_DIR / "docs").glob("*.md"):
        assert f"(docs/{page.name})" in where_to_read_on, f"README's 'Where to read on' lacks docs/{page.name}"


def test_every_command_is_documented():
    help_text = cli("--help").stdout
    commands = re.findall(r"^  (\S+)\s{2,}", help_text[help_text.index("Subcommands:"):], re.M)
    assert "simulate" in commands and "schema" in commands
    docs = "\n".join(p.read_text() for p in PAGES)
    for c in commands:
        assert f"### {c}" in docs or f"`rollerdyn {c}" in docs, f"no page documents `rollerdyn {c}`"


def test_relative_links_and_anchors_resolve():
    for page in PAGES:
        for target in re.findall(r"\]\(([^)\s]+)\)", page.read_text()):
            if re.match(r"[a-z]+:", target):
                continue  # an address outside the repository
            path, _, anchor = target.partition("#")
            dest = (page.parent / path).resolve() if path else page
            assert dest.exists(), f"{page.name}: link to {target}: no such file"
            if anchor and dest.suffix == ".md":
                assert anchor in anchors(dest), f"{page.name}: link to {target}: no such heading"
