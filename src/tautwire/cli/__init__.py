"""The ``tautwire`` command line (thin: every command calls library functions)."""
