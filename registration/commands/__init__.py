"""CLI sub-commands. Each module here defines ``HELP`` (one line), ``add_arguments(parser)`` and
``run(args) -> int``; :mod:`registration.cli` discovers them by name."""
