"""The ``taut`` command line (``docs/architecture.md`` §4): thin wrappers over the library."""
