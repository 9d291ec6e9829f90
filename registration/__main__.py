"""``python -m registration``: the same as the ``registration`` command (an entry point, on top of
the CLI)."""

import sys

from registration.cli import main

sys.exit(main())
