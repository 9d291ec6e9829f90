"""The live service (``registration serve``): registration of radars while they stream, with a JSON
API and one web page on 127.0.0.1. The page's files are package data in ``web/``, served through
:func:`registration.live.webassets.asset`."""
