"""``python -m taut``: the ``taut`` command line."""

import sys

try:
    from taut.cli import entry
except KeyboardInterrupt:  # Ctrl-C while the command line loads: exit as it would have
    print("taut: interrupted", file=sys.stderr)
    raise SystemExit(130) from None

if __name__ == "__main__":
    entry()
