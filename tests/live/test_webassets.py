"""The page's files come from the package, with their content types, and nothing else can be asked
for; none of them names another host to load from (the machines have no internet)."""

from __future__ import annotations

import re

import pytest

from registration.live.http.assets import CONTENT_TYPES, asset


@pytest.mark.parametrize(
    "name, ctype, start",
    [
        ("index.html", "text/html; charset=utf-8", b"<!doctype html>"),
        ("app.js", "text/javascript; charset=utf-8", b"// The live page"),
        ("style.css", "text/css; charset=utf-8", b"/* The live page"),
    ],
)
def test_each_file_with_its_content_type(name, ctype, start):
    data, content_type = asset(name)
    assert content_type == ctype and data.startswith(start)
    data.decode("utf-8")  # served as UTF-8: it must be


@pytest.mark.parametrize("name", ["", "/", "index.htm", "web/app.js", "../webassets.py", "__init__.py"])
def test_any_other_name_is_a_key_error(name):
    with pytest.raises(KeyError, match="no page asset"):
        asset(name)


def test_the_page_loads_only_its_own_files():
    html = asset("index.html")[0].decode()
    assert sorted(re.findall(r'(?:src|href)="([^"]+)"', html)) == ["app.js", "data:,", "style.css"]
    assert "default-src 'self'" in html  # the browser itself refuses any other host
    for name in CONTENT_TYPES:
        text = asset(name)[0].decode()
        urls = set(re.findall(r"\b(?:https?:)?//[\w.-]+", text)) - {"http://www.w3.org"}  # the SVG namespace
        assert not urls, (name, urls)
