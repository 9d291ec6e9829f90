"""Every relative link in README.md and docs/**/*.md points to a file that exists and, with an
#anchor into a Markdown page, to a heading (or <a id>) of that page: moving a page or renaming a
heading cannot leave a dead link."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.docs.links import MOVED, ROOT, anchors, links, markdown_files, new_place, relink, resolve

#: Pages another change is editing while the docs move; their links to moved pages are rewritten by
#: ``python -m tests.docs.links PAGE...`` once both are in, and then the page leaves this set.
PENDING_RELINK = {"docs/results.md"}
#: Pages written by a generator of another change; links to them may precede them.
PENDING_PAGES: set[str] = set()


def _dead(page: Path) -> list[str]:
    out = []
    for target in links(page.read_text(encoding="utf-8")):
        path, anchor = resolve(page, target)
        rel = path.relative_to(ROOT).as_posix() if path.is_relative_to(ROOT) else str(path)
        if not path.exists():
            if rel not in PENDING_PAGES:
                out.append(f"{target}: no file {rel}")
        elif anchor and path.suffix == ".md" and anchor not in anchors(path.read_text(encoding="utf-8")):
            out.append(f"{target}: no heading #{anchor} in {rel}")
    return out


@pytest.mark.parametrize("page", markdown_files(), ids=lambda p: p.relative_to(ROOT).as_posix())
def test_every_relative_link_resolves(page):
    rel = page.relative_to(ROOT).as_posix()
    dead = _dead(page)
    if rel in PENDING_RELINK:  # only links to moved pages may be dead here, and the tool fixes them
        old = {o for o in MOVED} | {Path(o).name for o in MOVED}
        dead = [d for d in dead if not any(d.startswith(f"{name}") for name in old)]
    assert not dead, f"{rel}: dead links:\n" + "\n".join(dead)


@pytest.mark.parametrize("name", sorted(PENDING_RELINK))
def test_the_relink_tool_leaves_no_dead_link_in_the_pending_pages(name, tmp_path):
    page = ROOT / name
    if not page.exists():
        pytest.skip(f"{name} is gone")
    fixed = tmp_path / page.relative_to(ROOT)  # the same place relative to a copy of the root
    fixed.parent.mkdir(parents=True)
    fixed.write_text(relink(page), encoding="utf-8")
    dead = []
    for target in links(fixed.read_text(encoding="utf-8")):
        path, anchor = resolve(page, target)  # resolved from the real page's folder
        if not path.exists():
            dead.append(target)
        elif anchor and path.suffix == ".md" and anchor not in anchors(path.read_text(encoding="utf-8")):
            dead.append(target)
    assert not dead


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
    """(Its links in Markdown: test_the_relink_tool_leaves_no_dead_link_in_the_pending_pages.)"""
    code = tmp_path / "module.py"
    code.write_text(
        '"""See docs/fleet.md, "What is rejected"; docs/nmea.md; the columns of docs/fleet.md."""\n',
        encoding="utf-8",
    )
    assert relink(code) == (
        '"""See docs/reference/fleet-files.md, "What is rejected"; docs/howto/import-nmea.md; '
        'the columns of docs/reference/fleet-files.md."""\n'
    )


def test_the_pending_sets_hold_only_what_is_still_pending():
    """Once a page is relinked or a generated page is in, it leaves its set, so the check is whole again."""
    for name in sorted(PENDING_RELINK):
        page = ROOT / name
        dead = _dead(page) if page.exists() else []
        assert dead, f"{name} has no dead link left: remove it from PENDING_RELINK"
    for name in sorted(PENDING_PAGES):
        assert not (ROOT / name).exists(), f"{name} exists now: remove it from PENDING_PAGES"
