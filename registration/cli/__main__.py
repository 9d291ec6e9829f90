"""``python -m registration.cli``: the same as the ``registration`` command."""

import sys

from registration.cli import main

sys.exit(main())
