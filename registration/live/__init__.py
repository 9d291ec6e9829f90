"""The live service (``registration serve``): registration between the sensors and the tracker,
on streams of ASTERIX datagrams, with an HTTP API, a web page, CAT063 status messages, corrected
plots and a state that survives restarts; and ``registration replay``, which sends recordings at
their recorded pace (docs/howto/serve.md)."""
