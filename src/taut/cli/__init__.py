"""The ``taut`` command line (``DESIGN.md`` §4): thin wrappers over the library."""
