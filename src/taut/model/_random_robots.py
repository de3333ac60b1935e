"""Seeded random suspended robots: test cases for the direct geometrico-static problem that
nobody tuned the solver to.

:func:`random_suspended_robot` draws a spatial rigid platform hung from ``n`` cables whose
exit points are spread over the top of a rectangular frame, the platform anchors on a
random body (flat — coplanar anchors — or not), its centre of mass below the anchors, and
cable lengths from the straight-line inverse kinematics of a random pose, perturbed by a
few per cent so that at the true equilibrium some cables may be slack — as when a user
measures lengths on a real robot (Berti 2015, §2.1: an under-constrained robot hangs on
whichever subset of its cables the lengths make taut).

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, §2.1. (docs/references.bib: berti2015)
"""

from __future__ import annotations

import numpy as np

from taut.errors import TautError
from taut.geometry import rotation_matrix
from taut.model._robot import Cable, Platform, Reference, Robot

#: Cable counts the generator draws (the DGP solves subsets of up to six taut cables).
MIN_CABLES, MAX_CABLES = 3, 8


def random_suspended_robot(
    n_cables: int,
    *,
    seed: int | np.random.Generator,
    coplanar: bool | None = None,
    perturbation: float = 0.02,
) -> tuple[Robot, np.ndarray]:
    """A random suspended spatial robot and cable lengths to solve its DGP for, drawn from a
    seed: the test suite and benchmark of robots nobody tuned the solver to.

    The frame is 2–6 m wide and deep with its exit points 2.5–4 m high, one per cable,
    spread round its top in the angular order of their anchors (the cables do not cross);
    the platform is 0.2–0.6 m across, its mass 1–10 kg under standard gravity (``−z``), its
    centre of mass ``platform.wrench_point`` 0.1–0.5 body sizes below the anchors' mean plane
    and off its axis.  The lengths are also stored as ``reference.lengths``, so the robot
    file alone is a complete ``taut fk`` case.

    Parameters
    ----------
    n_cables : int
        3 to 8.
    seed : int or numpy.random.Generator
        An int ≥ 0 (the robot is named after it and is the same on every machine) or a
        generator.
    coplanar : bool, optional
        All anchors in one platform plane (True), spread through the body's height (False),
        or drawn at random (None).
    perturbation : float, default 0.02
        The relative standard deviation of the lengths around the inverse kinematics of the
        drawn pose (0: every cable exactly reaches its anchor there, which is then generally
        not an equilibrium).

    Returns
    -------
    robot : Robot
    lengths : ndarray, shape (n_cables,)
        Cable lengths [m].

    Raises
    ------
    TautError
        For a cable count outside 3–8, a negative perturbation or a bad seed.

    Examples
    --------
    >>> robot, lengths = random_suspended_robot(3, seed=0)
    >>> robot.name, np.round(lengths, 3)
    ('random suspended 3-cable robot (seed 0)', array([1.822, 1.645, 1.835]))
    """
    if not (isinstance(n_cables, (int, np.integer)) and MIN_CABLES <= n_cables <= MAX_CABLES):
        raise TautError(f"a random suspended robot has {MIN_CABLES} to {MAX_CABLES} cables, got {n_cables!r}")
    if not (isinstance(perturbation, (int, float, np.number)) and np.isfinite(perturbation) and perturbation >= 0.0):
        raise TautError(f"the length perturbation must be a non-negative number, got {perturbation!r}")
    if not (isinstance(seed, np.random.Generator) or (isinstance(seed, (int, np.integer)) and seed >= 0)):
        raise TautError(f"seed must be an int >= 0 or a numpy.random.Generator, got {seed!r}")
    n = int(n_cables)
    rng = seed if isinstance(seed, np.random.Generator) else np.random.default_rng(seed)
    label = f" (seed {seed})" if not isinstance(seed, np.random.Generator) else ""
    if coplanar is None:
        coplanar = bool(rng.random() < 0.5)
    half = rng.uniform(1.0, 3.0, size=2)  # frame half-width and half-depth
    height = rng.uniform(2.5, 4.0)
    # one angle per cable, evenly spread and jittered: exits round the frame's top, anchors
    # round the platform in the same order
    angles = 2 * np.pi * (np.arange(n) + rng.uniform(-0.3, 0.3, n)) / n + rng.uniform(0, 2 * np.pi)
    ray = np.column_stack([np.cos(angles), np.sin(angles)])
    # the ray's point on the rectangle |x| ≤ hx, |y| ≤ hy
    scale = 1.0 / np.max(np.abs(ray) / half, axis=1)
    exits = np.column_stack([ray * scale[:, None], height + rng.uniform(-0.2, 0.2, n)])
    size = rng.uniform(0.1, 0.3)  # platform half-size
    radial = size * rng.uniform(0.6, 1.0, n)
    rim = angles + rng.uniform(-0.4, 0.4, n)
    heights = np.zeros(n) if coplanar else rng.uniform(-0.5, 0.5, n) * size
    anchors = np.column_stack([radial * np.cos(rim), radial * np.sin(rim), heights])
    com = np.array([*rng.uniform(-0.3, 0.3, 2) * size, -rng.uniform(0.1, 0.5) * 2 * size])
    mass = float(rng.uniform(1.0, 10.0))
    position = np.array([*(rng.uniform(-0.4, 0.4, 2) * half), rng.uniform(0.3, 0.6) * height])
    pose_angles = rng.uniform(-0.25, 0.25, 3)
    R = rotation_matrix(pose_angles, "xyz-fixed")
    reach = np.linalg.norm(exits - (position + anchors @ R.T), axis=1)
    lengths = reach * np.exp(perturbation * rng.standard_normal(n))
    name = f"random suspended {n}-cable robot{label}"
    robot = Robot(
        name=name,
        description=(
            f"{'Coplanar' if coplanar else 'Non-coplanar'} anchors; lengths from the inverse kinematics of the "
            f"pose {np.round(np.concatenate([position, pose_angles]), 4).tolist()} perturbed by {perturbation:g} "
            "(taut.model._random_robots)."
        ),
        dimension=3,
        orientation="xyz-fixed",
        platform=Platform(kind="rigid", mass=mass, wrench_point=tuple(float(c) for c in com)),
        cables=tuple(
            Cable(exit=tuple(float(c) for c in e), anchor=tuple(float(c) for c in b)) for e, b in zip(exits, anchors)
        ),
        reference=Reference(source="taut.model._random_robots", lengths=tuple(float(x) for x in lengths)),
    )
    return robot, lengths


#: Cable counts of :func:`random_point_mass_robot`, spatial and planar.
POINT_MASS_CABLES = {3: (2, 8), 2: (2, 6)}


def random_point_mass_robot(
    n_cables: int,
    *,
    dimension: int = 3,
    seed: int | np.random.Generator,
    perturbation: float = 0.02,
) -> tuple[Robot, np.ndarray]:
    """A random point mass hung from ``n`` cables, spatial or planar, and cable lengths to
    solve its DGP for: the point-mass cases of the test suite and benchmark.

    Spatial: exits round the top of a frame 2–6 m wide and deep, 2.5–4 m high, each raised or
    lowered by up to 0.5 m (not coplanar).  Planar: exits across the top of a frame 2–6 m
    wide at heights 2.5–4 m.  The mass, 0.5–10 kg under standard gravity (``−z``, ``−y`` in
    the plane), is drawn inside the frame's lower part; the lengths are the distances to its
    exits perturbed as in :func:`random_suspended_robot` (some cables then slack, or no
    equilibrium at all when some are shortened too much) and stored as
    ``reference.lengths``.

    Parameters
    ----------
    n_cables : int
        2 to 8 (spatial), 2 to 6 (planar).
    dimension : {3, 2}
    seed : int or numpy.random.Generator
    perturbation : float, default 0.02
        The relative standard deviation of the lengths around the drawn position's distances.

    Returns
    -------
    robot : Robot
    lengths : ndarray, shape (n_cables,)

    Raises
    ------
    TautError
        For a cable count or dimension out of range, a negative perturbation or a bad seed.

    Examples
    --------
    >>> robot, lengths = random_point_mass_robot(4, seed=0)
    >>> robot.name, robot.pose_names, lengths.shape
    ('random point-mass 4-cable robot (seed 0)', ['x', 'y', 'z'], (4,))
    """
    if dimension not in POINT_MASS_CABLES:
        raise TautError(f"a random point-mass robot is spatial (3) or planar (2), got dimension {dimension!r}")
    low, high = POINT_MASS_CABLES[dimension]
    if not (isinstance(n_cables, (int, np.integer)) and low <= n_cables <= high):
        raise TautError(f"a random {dimension}-D point-mass robot has {low} to {high} cables, got {n_cables!r}")
    if not (isinstance(perturbation, (int, float, np.number)) and np.isfinite(perturbation) and perturbation >= 0.0):
        raise TautError(f"the length perturbation must be a non-negative number, got {perturbation!r}")
    if not (isinstance(seed, np.random.Generator) or (isinstance(seed, (int, np.integer)) and seed >= 0)):
        raise TautError(f"seed must be an int >= 0 or a numpy.random.Generator, got {seed!r}")
    n = int(n_cables)
    rng = seed if isinstance(seed, np.random.Generator) else np.random.default_rng(seed)
    label = f" (seed {seed})" if not isinstance(seed, np.random.Generator) else ""
    height = rng.uniform(2.5, 4.0)
    if dimension == 3:
        half = rng.uniform(1.0, 3.0, size=2)
        angles = 2 * np.pi * (np.arange(n) + rng.uniform(-0.3, 0.3, n)) / n + rng.uniform(0, 2 * np.pi)
        ray = np.column_stack([np.cos(angles), np.sin(angles)])
        scale = 1.0 / np.max(np.abs(ray) / half, axis=1)
        exits = np.column_stack([ray * scale[:, None], height + rng.uniform(-0.5, 0.5, n)])
        position = np.array([*(rng.uniform(-0.5, 0.5, 2) * half), rng.uniform(0.2, 0.7) * height])
    else:
        half = rng.uniform(1.0, 3.0, size=1)
        xs = np.sort(rng.uniform(-1.0, 1.0, n)) * half
        exits = np.column_stack([xs, height + rng.uniform(-0.5, 0.5, n)])
        position = np.array([rng.uniform(-0.5, 0.5) * half[0], rng.uniform(0.2, 0.7) * height])
    mass = float(rng.uniform(0.5, 10.0))
    reach = np.linalg.norm(exits - position, axis=1)
    lengths = reach * np.exp(perturbation * rng.standard_normal(n))
    robot = Robot(
        name=f"random point-mass {n}-cable robot{label}",
        description=(
            f"{'Spatial' if dimension == 3 else 'Planar'} point mass; lengths from the position "
            f"{np.round(position, 4).tolist()} perturbed by {perturbation:g} (taut.model._random_robots)."
        ),
        dimension=3 if dimension == 3 else 2,
        platform=Platform(kind="point-mass", mass=mass),
        cables=tuple(Cable(exit=tuple(float(c) for c in e)) for e in exits),
        reference=Reference(source="taut.model._random_robots", lengths=tuple(float(x) for x in lengths)),
    )
    return robot, lengths
