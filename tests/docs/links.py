"""The relative links of README.md and docs/**/*.md: where each points, the headings a page offers as
anchors (as GitHub makes them), and the map of the pages moved when the docs were reorganised by task.

``python -m tests.docs.links FILE...`` rewrites the links (Markdown files) and the plain mentions
(``docs/fleet.md#the-solver`` in any other text file) of moved pages in FILE... to their new places.
"""

from __future__ import annotations

import os
import re
import sys
from pathlib import Path

__all__ = ["ROOT", "MOVED", "markdown_files", "links", "anchors", "resolve", "new_place", "relink", "main"]

ROOT = Path(__file__).resolve().parents[2]

#: old page -> its new place(s); a page split in parts lists each, and an anchor goes to the part
#: that has that heading (a link without an anchor to the first).
MOVED = {
    "docs/asterix.md": ["docs/howto/import-asterix.md", "docs/background/importers.md"],
    "docs/nmea.md": ["docs/howto/import-nmea.md", "docs/background/importers.md"],
    "docs/archive.md": ["docs/howto/register-an-archive.md", "docs/background/archive-solver.md"],
    "docs/register.md": ["docs/howto/register-recorded-files.md"],
    "docs/scale.md": ["docs/howto/monte-carlo-and-dask.md"],
    "docs/stonesoup.md": ["docs/howto/stonesoup.md"],
    "docs/conventions.md": ["docs/reference/conventions.md"],
    "docs/online.md": ["docs/background/online.md"],
    "docs/fusion.md": ["docs/background/fusion.md"],
    "docs/landing.md": ["docs/background/landing.md"],
    "docs/fleet-online.md": ["docs/background/fleet-online.md"],
    "docs/association.md": ["docs/background/association.md"],
    "docs/fleet.md": [
        "docs/background/fleet-model.md",
        "docs/howto/register-a-fleet.md",
        "docs/reference/fleet-files.md",
    ],
}

_FENCE = re.compile(r"^(```|~~~).*?^\1", re.M | re.S)
_CODE = re.compile(r"`[^`\n]*`")
_LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
_HEADING = re.compile(r"^#{1,6}\s+(.*?)\s*#*\s*$", re.M)
_HTML_ANCHOR = re.compile(r"<a\s+(?:id|name)=\"([^\"]+)\"")
#: For a mention of a split page without anchor or section: words just before it, and the part they ask for.
_HINTS = [
    (re.compile(r"estimates\.csv|command", re.I), "docs/howto/"),
    (re.compile(r"column|degrees", re.I), "docs/reference/"),
]
_MENTION = re.compile(r"(docs/[\w./-]+\.md)(?:#([\w-]+))?(, \"[^\"\n]+\")?")


def markdown_files(root: Path = ROOT) -> list[Path]:
    """README.md and every Markdown page under docs/."""
    return [root / "README.md", *sorted((root / "docs").rglob("*.md"))]


def _prose(text: str) -> str:
    """The text without fenced code blocks (a heading or link there is code, not Markdown)."""
    return _FENCE.sub("", text)


def links(text: str) -> list[str]:
    """The targets of the relative links (no scheme) in a page's prose, inline code left out."""
    found = _LINK.findall(_CODE.sub("", _prose(text)))
    return [t for t in found if not re.match(r"^[a-z][a-z0-9+.-]*:", t, re.I)]


def _slug(heading: str) -> str:
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # a link in a heading: its text
    return re.sub(r"[^\w\- ]", "", text.strip().lower()).replace(" ", "-")


def anchors(text: str) -> set[str]:
    """The anchors of a page: GitHub's slug of every heading (-1, -2 ... for repeats) and <a id>s."""
    out: set[str] = set(_HTML_ANCHOR.findall(text))
    seen: dict[str, int] = {}
    for heading in _HEADING.findall(_prose(text)):
        slug = _slug(heading)
        out.add(f"{slug}-{seen[slug]}" if slug in seen else slug)
        seen[slug] = seen.get(slug, 0) + 1
    return out


def resolve(page: Path, target: str) -> tuple[Path, str]:
    """The file a link of ``page`` points to and its anchor ('' if none)."""
    path, _, anchor = target.partition("#")
    return ((page.parent / path).resolve() if path else page.resolve()), anchor


def new_place(old: str, anchor: str, root: Path = ROOT, section: str = "") -> str | None:
    """The new repository path of moved page ``old`` (repository-relative), chosen by ``anchor`` or,
    for a mention such as ``docs/fleet.md, "The files"``, by the heading the ``section`` begins."""
    places = MOVED.get(old)
    if not places:
        return None
    for place in places:
        found = anchors((root / place).read_text(encoding="utf-8"))
        if (anchor and anchor in found) or (section and any(a.startswith(_slug(section)) for a in found)):
            return place
    return places[0]


def _relinked(page: Path, target: str, root: Path, base: Path) -> str:
    path, anchor = resolve(base / page.name, target)
    if not links(f"[]({target})") or not target.partition("#")[0] or not path.is_relative_to(root):
        return target
    place = new_place(path.relative_to(root).as_posix(), anchor, root)
    if place is None and base == page.parent:
        return target
    rel = os.path.relpath(root / place if place else path, page.parent).replace(os.sep, "/")
    return rel + (f"#{anchor}" if anchor else "")


def _link(m: re.Match[str], target: str) -> str:
    """The link of ``m`` to ``target``; a link text that named the old file (``fleet.md`` or
    ``docs/fleet.md``) names the new one in the same form."""
    whole, old = m.group(0), m.group(1)
    start, end = m.start(1) - m.start(0), m.end(1) - m.start(0)
    text = whole[:start] + target + whole[end:]
    name, new_name = old.partition("#")[0].rsplit("/", 1)[-1], target.partition("#")[0].rsplit("/", 1)[-1]
    label = re.match(r"!?\[([^\]]*)\]", text)
    if label is None or not name:
        return text
    new_label = label.group(1)
    if label.group(1) in MOVED:  # docs/fleet.md: the part the target chose, by its file name
        new_label = next((p for p in MOVED[label.group(1)] if p.endswith(f"/{new_name}")), new_label)
    elif label.group(1) == name:
        new_label = new_name
    return text.replace(f"[{label.group(1)}]", f"[{new_label}]", 1)


def relink(page: Path, root: Path = ROOT, base: Path | None = None) -> str:
    """``page``'s text with its links (Markdown) or mentions (other files) of moved pages updated;
    ``base``: the folder its links were written from, if the page itself moved (default: its own)."""
    text = page.read_text(encoding="utf-8")
    if page.suffix == ".md":
        folder = (base or page.parent).resolve()
        return _LINK.sub(lambda m: _link(m, _relinked(page.resolve(), m.group(1), root, folder)), text)

    def mention(m: re.Match[str]) -> str:
        old, anchor, section = m.group(1), m.group(2) or "", m.group(3) or ""
        place = new_place(old, anchor, root, section.strip(', "'))
        before = text[max(0, m.start() - 120) : m.start()]
        if not (anchor or section) and place is not None and len(MOVED[old]) > 1:
            for hint, folder in _HINTS:  # a split page: the words before the mention choose the part
                place = next((p for p in MOVED[old] if hint.search(before) and p.startswith(folder)), place)
        return m.group(0) if place is None else place + (f"#{anchor}" if anchor else "") + section

    return _MENTION.sub(mention, text)


def main(argv: list[str]) -> int:
    for name in argv:
        page = Path(name).resolve()
        if page.is_relative_to(Path(__file__).parent):
            continue  # the move map and its tests name the old pages on purpose
        text = relink(page)
        if text != page.read_text(encoding="utf-8"):
            page.write_text(text, encoding="utf-8")
            print(f"relinked {name}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
