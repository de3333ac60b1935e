"""Bounds on the numbers taut accepts from a user, in robot files and on the command line,
kept in a module of their own so that the command line reads them without loading pydantic."""

#: Largest magnitude of a finite number in a robot file, an option or a pose (SI units): a
#: million kilometres, a million tonnes, a giganewton are beyond any cable robot, and below it
#: products such as mass·gravity·lever arm or squared lengths keep their precision.  The one
#: limit of every reader, of the command line's numbers and of pose coordinates.
MAX_MAGNITUDE = 1e9
