"""``python -m tautwire``: the ``tautwire`` command line."""

from __future__ import annotations

import sys

from tautwire.cli.main import main

if __name__ == "__main__":
    sys.exit(main())
