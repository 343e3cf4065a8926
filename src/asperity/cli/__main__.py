"""``python -m asperity.cli``: the same as the ``asperity`` command."""

import sys

from . import main

sys.exit(main())
