"""Bounds on the numbers taut accepts from a user, in robot files and on the command line,
kept in a module of their own so that the command line reads them without loading pydantic."""

#: Largest magnitude of a finite number in a robot file or an option (SI units): beyond it
#: products such as mass·gravity·lever arm or squared lengths lose all precision or overflow.
MAX_MAGNITUDE = 1e12
