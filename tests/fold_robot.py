"""A robot of the random suite at a fold: seed 0, 3 cables, cable 1 lengthened by
:data:`FOLD_SIDE`, 7e-11 (relative) past the fold near 1.03537780442 where two all-taut
equilibria appear (4 of them below it, 6 above).  Double precision leaves boxes too narrow
to split around the nearly double pair; shared by the DGP and CLI tests."""

from taut.model import random_suspended_robot

FOLD_SIDE = 1.0353778044866666


def fold_robot():
    """``(robot, lengths, base lengths)``: the suite robot and its lengths at the fold side."""
    robot, base = random_suspended_robot(3, seed=0)
    lengths = base.copy()
    lengths[0] *= FOLD_SIDE
    return robot, lengths, base
