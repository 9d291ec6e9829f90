"""Every relative link in README.md and docs/**/*.md points to a file that exists and, with an
#anchor into a Markdown page, to a heading (or <a id>) of that page: moving a page or renaming a
heading cannot leave a dead link."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.docs.links import MOVED, ROOT, anchors, links, markdown_files, new_place, relink, resolve


def _dead(page: Path) -> list[str]:
    out = []
    for target in links(page.read_text(encoding="utf-8")):
        path, anchor = resolve(page, target)
        rel = path.relative_to(ROOT).as_posix() if path.is_relative_to(ROOT) else str(path)
        if not path.exists():
            out.append(f"{target}: no file {rel}")
        elif anchor and path.suffix == ".md" and anchor not in anchors(path.read_text(encoding="utf-8")):
            out.append(f"{target}: no heading #{anchor} in {rel}")
    return out


@pytest.mark.parametrize("page", markdown_files(), ids=lambda p: p.relative_to(ROOT).as_posix())
def test_every_relative_link_resolves(page):
    rel = page.relative_to(ROOT).as_posix()
    dead = _dead(page)
    assert not dead, f"{rel}: dead links:\n" + "\n".join(dead)


def test_moved_pages_are_gone_and_their_places_exist():
    for old, places in MOVED.items():
        assert not (ROOT / old).exists(), f"{old} is back: remove it from MOVED or the page"
        for place in places:
            assert (ROOT / place).exists(), place


def test_a_split_page_sends_each_anchor_to_its_part():
    assert new_place("docs/fleet.md", "the-solver") == "docs/background/fleet-model.md"
    assert new_place("docs/fleet.md", "files-and-commands") == "docs/howto/register-a-fleet.md"
    assert new_place("docs/fleet.md", "the-input-tables-in-memory-si") == "docs/reference/fleet-files.md"
    assert new_place("docs/fleet.md", "") == "docs/background/fleet-model.md"
    assert new_place("docs/fleet.md", "", section="What is rejected") == "docs/reference/fleet-files.md"
    assert new_place("docs/fleet.md", "", section="Sensor error model") == "docs/background/fleet-model.md"


def test_the_checker_sees_a_dead_link_and_a_dead_anchor(tmp_path):
    (tmp_path / "a.md").write_text("# Top\n\n## Speed (`bench.py`)\n", encoding="utf-8")
    page = tmp_path / "b.md"
    page.write_text(
        "[ok](a.md#speed-benchpy) [bad](a.md#nope) [gone](c.md) [web](https://x.org/c.md)\n"
        "`[code](c.md)`\n```\n[fenced](c.md)\n```\n",
        encoding="utf-8",
    )
    found = [(t, resolve(page, t)) for t in links(page.read_text(encoding="utf-8"))]
    assert [t for t, _ in found] == ["a.md#speed-benchpy", "a.md#nope", "c.md"]
    ok = [t for t, (p, a) in found if p.exists() and (not a or a in anchors(p.read_text(encoding="utf-8")))]
    assert ok == ["a.md#speed-benchpy"]


def test_the_relink_tool_moves_mentions_in_code(tmp_path):
    """Mentions of moved pages in docstrings and comments are rewritten to the new places."""
    code = tmp_path / "module.py"
    code.write_text(
        '"""See docs/fleet.md, "What is rejected"; docs/nmea.md; the columns of docs/fleet.md."""\n',
        encoding="utf-8",
    )
    assert relink(code) == (
        '"""See docs/reference/fleet-files.md, "What is rejected"; docs/howto/import-nmea.md; '
        'the columns of docs/reference/fleet-files.md."""\n'
    )
