"""Seeded random suspended robots: test cases for the direct geometrico-static problem that
nobody tuned the solver to.

:func:`random_suspended_robot` draws a spatial rigid platform hung from ``n`` cables whose
exit points are spread over the top of a rectangular frame, the platform anchors on a
random body (flat — coplanar anchors — or not), its centre of mass below the anchors, and
cable lengths from the straight-line inverse kinematics of a random pose, perturbed by a
few per cent so that at the true equilibrium some cables may be slack — as when a user
measures lengths on a real robot (Berti 2015, §2.1: an under-constrained robot hangs on
whichever subset of its cables the lengths make taut).  With ``pulley_radius`` its cables leave
through swivelling pulleys (Pott 2018, pulley kinematics), built about the drawn pose so that
their lengths, wound arcs included, follow from it in closed form.

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, §2.1. (docs/references.bib: berti2015)
.. [2] A. Pott, "Cable-Driven Parallel Robots: Theory and Application", Springer Tracts in
   Advanced Robotics 120, Springer, 2018, pulley kinematics. (docs/references.bib: pott2018)
"""

from __future__ import annotations

import numpy as np

from taut.errors import TautError
from taut.geometry import rotation_matrix
from taut.model._robot import Cable, Platform, Reference, Robot, SwivelPulley

#: Cable counts the generator draws (the DGP solves subsets of up to six taut cables).
MIN_CABLES, MAX_CABLES = 3, 8

#: Largest ``pulley_radius`` of :func:`random_suspended_robot` [m]: well below the cables'
#: free lengths (over a metre), so that no cable is refused as shorter than its pulley.
MAX_PULLEY_RADIUS = 0.5

#: Largest tilt [rad] of a random robot's swivel axes from straight down.
MAX_AXIS_TILT = 0.3


def _swivel_exits(
    tangents: np.ndarray, anchors: np.ndarray, axes: np.ndarray, radius: float
) -> tuple[np.ndarray, np.ndarray]:
    """Swivelling pulleys of ``radius`` whose cables leave at the points ``tangents`` towards
    ``anchors`` (both ``(n, 3)``), the cables coming along the unit ``axes``: the points where
    the cables run onto the pulleys, and the cable lengths with the arcs.

    In the pulley's plane — spanned by ``k``, the axis, and ``e``, the unit part of the free
    cable's direction ``u`` normal to it — the cable runs along ``k`` onto the circle and wraps
    it through ``β`` (``cos β = u·k``, ``sin β = u·e``) to the tangent point ``C``, whose centre
    is then ``C + r (cos β e − sin β k)`` and the run-on point ``r e`` before the centre; the
    length is ``r β + ‖b − C‖`` (Pott 2018, pulley kinematics)."""
    free = anchors - tangents
    lf = np.linalg.norm(free, axis=1)
    u = free / lf[:, None]
    along = np.einsum("ij,ij->i", u, axes)
    normal = u - along[:, None] * axes
    across = np.linalg.norm(normal, axis=1)
    e = normal / across[:, None]
    beta = np.arctan2(across, along)
    exits = tangents + radius * ((np.cos(beta) - 1.0)[:, None] * e - np.sin(beta)[:, None] * axes)
    return exits, radius * beta + lf


def random_suspended_robot(
    n_cables: int,
    *,
    seed: int | np.random.Generator,
    coplanar: bool | None = None,
    perturbation: float = 0.02,
    pulley_radius: float | None = None,
) -> tuple[Robot, np.ndarray]:
    """A random suspended spatial robot and cable lengths to solve its DGP for, drawn from a
    seed: the test suite and benchmark of robots nobody tuned the solver to.

    The frame is 2–6 m wide and deep with its exit points 2.5–4 m high, one per cable,
    spread round its top in the angular order of their anchors (the cables do not cross);
    the platform is 0.2–0.6 m across, its mass 1–10 kg under standard gravity (``−z``), its
    centre of mass ``platform.wrench_point`` 0.1–0.5 body sizes below the platform's plane
    ``z = 0`` (the anchors' plane when they are coplanar) and off its axis.  The lengths are also stored as ``reference.lengths``, so the robot
    file alone is a complete ``taut fk`` case.

    With ``pulley_radius``, every cable leaves through a swivelling pulley of that radius
    (``cables[].swivel``) instead, coming along an axis tilted up to :data:`MAX_AXIS_TILT`
    from straight down; the pulleys are placed so that at the drawn pose the cables leave
    them at the point-exit robot's exit points, and the lengths are the pulley lengths, arcs
    wound included, perturbed alike.  The drawn pose is then ``reference.poses["drawn"]``.
    The robot is the point-exit one of the same seed, plus the pulleys: as the radius tends to
    0, the exits and lengths tend to its own.

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
    pulley_radius : float, optional
        Swivelling pulleys of this radius [m], 0 < radius ≤ :data:`MAX_PULLEY_RADIUS`
        (default: none, the cables leave from fixed exit points).

    Returns
    -------
    robot : Robot
    lengths : ndarray, shape (n_cables,)
        Cable lengths [m].

    Raises
    ------
    TautError
        For a cable count outside 3–8, a negative perturbation, a pulley radius out of range
        or a bad seed.

    References
    ----------
    .. [1] A. Pott, "Cable-Driven Parallel Robots: Theory and Application", Springer Tracts
       in Advanced Robotics 120, Springer, 2018, pulley kinematics.
       (docs/references.bib: pott2018)

    Examples
    --------
    >>> robot, lengths = random_suspended_robot(3, seed=0)
    >>> robot.name, np.round(lengths, 3)
    ('random suspended 3-cable robot (seed 0)', array([1.822, 1.645, 1.835]))

    The same robot with pulleys of 5 cm: the arcs lengthen the cables by centimetres.

    >>> pulleys, longer = random_suspended_robot(3, seed=0, pulley_radius=0.05)
    >>> pulleys.name, pulleys.swivel_cables, np.round(longer - lengths, 3)
    ('random suspended 3-cable pulley robot (seed 0)', (0, 1, 2), array([0.054, 0.04 , 0.05 ]))
    """
    if not (isinstance(n_cables, (int, np.integer)) and MIN_CABLES <= n_cables <= MAX_CABLES):
        raise TautError(f"a random suspended robot has {MIN_CABLES} to {MAX_CABLES} cables, got {n_cables!r}")
    if not (isinstance(perturbation, (int, float, np.number)) and np.isfinite(perturbation) and perturbation >= 0.0):
        raise TautError(f"the length perturbation must be a non-negative number, got {perturbation!r}")
    if not (isinstance(seed, np.random.Generator) or (isinstance(seed, (int, np.integer)) and seed >= 0)):
        raise TautError(f"seed must be an int >= 0 or a numpy.random.Generator, got {seed!r}")
    if pulley_radius is not None and not (
        isinstance(pulley_radius, (int, float, np.number)) and 0.0 < pulley_radius <= MAX_PULLEY_RADIUS
    ):
        raise TautError(f"the pulley radius must be a number in (0, {MAX_PULLEY_RADIUS:g}] m, got {pulley_radius!r}")
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
    b = position + anchors @ R.T
    reach = np.linalg.norm(exits - b, axis=1)
    noise = np.exp(perturbation * rng.standard_normal(n))
    swivels: list[SwivelPulley | None] = [None] * n
    poses = {}
    kind = ""
    if pulley_radius is None:
        lengths = reach * noise
    else:
        # drawn after everything else: the point-exit robot of the seed is the same
        tilt, turn = rng.uniform(0.0, MAX_AXIS_TILT, n), rng.uniform(0.0, 2 * np.pi, n)
        axes = np.column_stack([np.sin(tilt) * np.cos(turn), np.sin(tilt) * np.sin(turn), -np.cos(tilt)])
        exits, spans = _swivel_exits(exits, b, axes, float(pulley_radius))
        lengths = spans * noise
        swivels = [SwivelPulley(axis=tuple(float(c) for c in k), radius=float(pulley_radius)) for k in axes]
        poses = {"drawn": tuple(float(x) for x in np.concatenate([position, pose_angles]))}
        kind = " pulley"
    name = f"random suspended {n}-cable{kind} robot{label}"
    pulleys = "" if pulley_radius is None else f", cables through swivelling pulleys of radius {pulley_radius:g} m"
    robot = Robot(
        name=name,
        description=(
            f"{'Coplanar' if coplanar else 'Non-coplanar'} anchors{pulleys}; lengths from the inverse kinematics "
            f"of the pose {np.round(np.concatenate([position, pose_angles]), 4).tolist()} perturbed by "
            f"{perturbation:g} (taut.model._random_robots)."
        ),
        dimension=3,
        orientation="xyz-fixed",
        platform=Platform(kind="rigid", mass=mass, wrench_point=tuple(float(c) for c in com)),
        cables=tuple(
            Cable(exit=tuple(float(c) for c in e), anchor=tuple(float(c) for c in a), swivel=k)
            for e, a, k in zip(exits, anchors, swivels)
        ),
        reference=Reference(source="taut.model._random_robots", lengths=tuple(float(x) for x in lengths), poses=poses),
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


#: Cable counts :func:`random_planar_robot` draws (a planar platform hangs on up to three).
MIN_PLANAR_CABLES, MAX_PLANAR_CABLES = 2, 6


def random_planar_robot(
    n_cables: int, *, seed: int | np.random.Generator, perturbation: float = 0.02
) -> tuple[Robot, np.ndarray]:
    """A random suspended planar robot (pose ``x, y, θ``) and cable lengths to solve its DGP
    for, drawn from a seed: the planar counterpart of :func:`random_suspended_robot`.

    The frame is 2–6 m wide with its exit points 2.5–4 m high, spread along its top from left
    to right; the platform is 0.2–0.6 m across with its anchors in the same order (the cables
    do not cross), not all on one line; its mass 1–10 kg under standard gravity (``−y``), its
    centre of mass ``platform.wrench_point`` 0.1–0.5 body sizes below the anchors and off
    centre.  The lengths — the inverse kinematics of a random pose, perturbed — are also the
    robot's ``reference.lengths``.

    Parameters
    ----------
    n_cables : int
        2 to 6.
    seed : int or numpy.random.Generator
        An int ≥ 0 (the robot is named after it and is the same on every machine) or a
        generator.
    perturbation : float, default 0.02
        The relative standard deviation of the lengths around the inverse kinematics of the
        drawn pose.

    Returns
    -------
    robot : Robot
    lengths : ndarray, shape (n_cables,)
        Cable lengths [m].

    Raises
    ------
    TautError
        For a cable count outside 2–6, a negative perturbation or a bad seed.

    Examples
    --------
    >>> robot, lengths = random_planar_robot(2, seed=0)
    >>> robot.name, robot.dimension, lengths.shape
    ('random planar 2-cable robot (seed 0)', 2, (2,))
    """
    if not (isinstance(n_cables, (int, np.integer)) and MIN_PLANAR_CABLES <= n_cables <= MAX_PLANAR_CABLES):
        raise TautError(
            f"a random planar robot has {MIN_PLANAR_CABLES} to {MAX_PLANAR_CABLES} cables, got {n_cables!r}"
        )
    if not (isinstance(perturbation, (int, float, np.number)) and np.isfinite(perturbation) and perturbation >= 0.0):
        raise TautError(f"the length perturbation must be a non-negative number, got {perturbation!r}")
    if not (isinstance(seed, np.random.Generator) or (isinstance(seed, (int, np.integer)) and seed >= 0)):
        raise TautError(f"seed must be an int >= 0 or a numpy.random.Generator, got {seed!r}")
    n = int(n_cables)
    rng = seed if isinstance(seed, np.random.Generator) else np.random.default_rng(seed)
    label = f" (seed {seed})" if not isinstance(seed, np.random.Generator) else ""
    half = rng.uniform(1.0, 3.0)
    height = rng.uniform(2.5, 4.0)
    spread = (np.arange(n) + 0.5 + rng.uniform(-0.3, 0.3, n)) / n * 2.0 - 1.0  # in (−1, 1), increasing
    exits = np.column_stack([half * spread, height + rng.uniform(-0.2, 0.2, n)])
    size = rng.uniform(0.1, 0.3)  # platform half-size
    anchors = np.column_stack([size * spread, size * rng.uniform(-0.3, 0.3, n)])
    if n == 2:  # two anchors are never collinear; the third point, G, must be off their line
        anchors[:, 1] = 0.0
    com = np.array([rng.uniform(-0.3, 0.3) * size, -rng.uniform(0.1, 0.5) * 2 * size])
    mass = float(rng.uniform(1.0, 10.0))
    pose = np.array([rng.uniform(-0.4, 0.4) * half, rng.uniform(0.3, 0.6) * height, rng.uniform(-0.25, 0.25)])
    c, s = np.cos(pose[2]), np.sin(pose[2])
    reach = np.linalg.norm(exits - (pose[:2] + anchors @ np.array([[c, -s], [s, c]]).T), axis=1)
    lengths = reach * np.exp(perturbation * rng.standard_normal(n))
    robot = Robot(
        name=f"random planar {n}-cable robot{label}",
        description=(
            f"Suspended planar platform; lengths from the inverse kinematics of the pose "
            f"{np.round(pose, 4).tolist()} perturbed by {perturbation:g} (taut.model._random_robots)."
        ),
        dimension=2,
        platform=Platform(kind="rigid", mass=mass, wrench_point=tuple(float(x) for x in com)),
        cables=tuple(
            Cable(exit=tuple(float(x) for x in e), anchor=tuple(float(x) for x in b)) for e, b in zip(exits, anchors)
        ),
        reference=Reference(source="taut.model._random_robots", lengths=tuple(float(x) for x in lengths)),
    )
    return robot, lengths
