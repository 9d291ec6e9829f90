"""``python -m registration``: the same as the ``registration`` command.

An entry point, not a library module: it runs ``registration.cli`` as a program (``runpy``), the
way ``python -m registration.cli`` does, so no library module imports the command line.
"""

import runpy

runpy.run_module("registration.cli", run_name="__main__", alter_sys=True)
