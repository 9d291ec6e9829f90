"""The live page's three files (``index.html``, ``app.js``, ``style.css``), shipped as package data in
``registration/live/web/`` and read with :mod:`importlib.resources`: the page loads nothing from any
other host, so it works on a machine without internet."""

from __future__ import annotations

from functools import cache
from importlib import resources

CONTENT_TYPES: dict[str, str] = {
    "index.html": "text/html; charset=utf-8",
    "app.js": "text/javascript; charset=utf-8",
    "style.css": "text/css; charset=utf-8",
}
"""The names the page is made of, each with the HTTP Content-Type to serve it with."""


@cache
def asset(name: str) -> tuple[bytes, str]:
    """The bytes of the page's file ``name`` and its Content-Type.

    ``name`` is one of :data:`CONTENT_TYPES` (``"index.html"`` for ``GET /``); any other name, such as
    a path with a folder in it, raises :class:`KeyError`, so a request cannot read another file.
    """
    if name not in CONTENT_TYPES:
        raise KeyError(f"no page asset {name!r}; the page has {sorted(CONTENT_TYPES)}")
    data = resources.files("registration.live").joinpath("web", name).read_bytes()
    return data, CONTENT_TYPES[name]
