"""``python -m taut``: the ``taut`` command line."""

from taut.cli.main import entry

if __name__ == "__main__":
    entry()
