"""Henderson's continuation and A* on manifolds of known geometry (circle, sphere, torus)."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from taut.errors import TautError
from taut.planning import Atlas, ImplicitManifold, Polytope, Symmetry, plan_path, tangent_basis

CIRCLE = ImplicitManifold(lambda x: np.array([x @ x - 1]), lambda x: 2 * x[None, :], 1)
SPHERE = ImplicitManifold(lambda x: np.array([x @ x - 1]), lambda x: 2 * x[None, :], 2)
R0, R1 = 1.0, 0.4


def _torus_f(x):
    q = np.hypot(x[0], x[1])
    return np.array([(q - R0) ** 2 + x[2] ** 2 - R1**2])


def _torus_j(x):
    q = np.hypot(x[0], x[1])
    return np.array([[2 * (q - R0) * x[0] / q, 2 * (q - R0) * x[1] / q, 2 * x[2]]])


TORUS = ImplicitManifold(_torus_f, _torus_j, 2)


def _sphere_points(n, seed=0):
    p = np.random.default_rng(seed).normal(size=(n, 3))
    return p / np.linalg.norm(p, axis=1)[:, None]


def _torus_points(n, seed=0):
    a, b = np.random.default_rng(seed).uniform(0, 2 * np.pi, (2, n))
    return np.stack([(R0 + R1 * np.cos(b)) * np.cos(a), (R0 + R1 * np.cos(b)) * np.sin(a), R1 * np.sin(b)], 1)


def test_tangent_basis_is_orthonormal_null_space():
    J = np.random.default_rng(1).normal(size=(3, 7))
    Q = tangent_basis(J, 4)
    assert np.allclose(Q.T @ Q, np.eye(4)) and np.allclose(J @ Q, 0)


def test_polytope_cut_keeps_halfspace_and_vertex_count():
    P = Polytope(3, 1.0)
    assert P.cut(np.array([1.0, 1.0, 1.0]), 2.0, 10)  # cuts off the corner (1, 1, 1)
    assert len(P.vertices) == 10 and np.all(P.vertices @ np.ones(3) <= 2 + 1e-9)
    assert not P.cut(np.array([1.0, 0, 0]), 5.0, 11)


def _brute_force_vertices(k, half, normals, offsets):
    """Every point where k of the constraints (cube faces, cutting planes) are active and
    all hold: the vertices of the polytope, by enumeration."""
    import itertools

    A = np.vstack([np.eye(k), -np.eye(k), normals])
    b = np.concatenate([np.full(2 * k, half), offsets])
    out = []
    for rows in itertools.combinations(range(len(A)), k):
        M = A[list(rows)]
        if np.linalg.svd(M, compute_uv=False)[-1] < 1e-9:
            continue
        x = np.linalg.solve(M, b[list(rows)])
        if np.all(A @ x <= b + 1e-9):
            out.append(x)
    return np.unique(np.round(out, 7), axis=0)


@settings(max_examples=40, deadline=None)
@given(
    st.integers(2, 4),
    st.lists(
        st.tuples(st.lists(st.floats(-1, 1), min_size=4, max_size=4), st.floats(0.2, 1.3)), min_size=1, max_size=6
    ),
)
def test_polytope_cuts_give_the_vertices_of_the_intersection(k, cuts):
    """The vertices after a sequence of cuts (each crossing edge found by the constraints its
    two ends share) are those of the intersection of the cube and the half-spaces."""
    P = Polytope(k, 1.0)
    normals, offsets = [], []
    for c, (normal, offset) in enumerate(cuts):
        a = np.array(normal[:k])
        if np.linalg.norm(a) < 0.1:
            continue
        P.cut(a, offset, 2 * k + c)
        normals.append(P.normals[-1] if len(P.normals) > len(normals) else a / np.linalg.norm(a))
        offsets.append(P.offsets[-1] if len(P.offsets) > len(offsets) else offset / np.linalg.norm(a))
    expected = _brute_force_vertices(k, 1.0, np.reshape(normals, (-1, k)), np.array(offsets))
    got = np.unique(np.round(P.vertices, 7), axis=0)
    assert got.shape == expected.shape and np.allclose(got, expected, atol=1e-6)
    assert P.active.shape == (len(P.vertices), k)


def test_circle_atlas_spacing():
    a = Atlas(CIRCLE, [1.0, 0.0], radius=0.1)
    assert a.complete()
    n = len(a.charts)
    assert 0.95 * 2 * np.pi / 0.1 <= n <= 1.2 * 2 * np.pi / 0.1  # one chart per step r
    assert np.allclose(np.linalg.norm(a.centres, axis=1), 1)
    ang = np.sort(np.arctan2(a.centres[:, 1], a.centres[:, 0]))
    gaps = np.diff(np.concatenate([ang, ang[:1] + 2 * np.pi]))
    assert gaps.max() < 0.2  # consecutive chart centres never farther than 2 r


@pytest.mark.parametrize(
    "manifold,x0,points,area,factor",
    [
        (SPHERE, [0, 0, 1.0], _sphere_points(400), 4 * np.pi, 3),
        # the tube radius 0.4 is only twice the chart radius: steps shrink with the curvature
        (TORUS, [R0 + R1, 0, 0], _torus_points(400), 4 * np.pi**2 * R0 * R1, 4),
    ],
)
def test_complete_atlas_covers_the_surface(manifold, x0, points, area, factor):
    r = 0.2
    a = Atlas(manifold, x0, radius=r)
    assert a.complete()
    assert all(abs(manifold.function(c)[0]) < 1e-9 for c in a.centres)  # centres on M
    assert not any(c.frontier for c in a.charts)
    # hexagons of circumradius r: area / (3√3/2 r²) charts at least; centres a step r
    # apart on a hexagonal lattice would need three times as many
    ideal = area / (1.5 * np.sqrt(3) * r**2)
    assert ideal <= len(a.charts) <= factor * ideal
    assert all(a.covering_chart(p) is not None for p in points)
    assert max(np.linalg.norm(a.centres - p, axis=1).min() for p in points) < r


def test_sphere_antipodes_path_close_to_geodesic():
    res = plan_path(SPHERE, [0, 0, 1.0], [0, 0, -1.0], radius=0.2)
    assert res.found
    assert np.allclose(res.path[0], [0, 0, 1]) and np.allclose(res.path[-1], [0, 0, -1])
    assert np.allclose(np.linalg.norm(res.path, axis=1), 1, atol=1e-9)
    assert np.linalg.norm(np.diff(res.path, axis=0), axis=1).max() < 0.1  # refined, continuous
    assert np.pi <= res.length <= 1.15 * np.pi


def test_torus_path_around_the_hole_and_over_the_tube():
    start, goal = [R0 + R1, 0, 0], [-(R0 - R1), 0, 0]  # outer equator → inner equator, opposite side
    res = plan_path(TORUS, start, goal, radius=0.1)
    assert res.found
    assert np.abs([_torus_f(p)[0] for p in res.path]).max() < 1e-9
    # geodesic ≥ the planar distance, and the path cannot cross the hole
    assert res.length >= np.linalg.norm(np.subtract(goal, start))
    assert np.hypot(res.path[:, 0], res.path[:, 1]).min() >= R0 - R1 - 1e-9


def test_boxed_component_gives_no_path_with_exhaustion():
    # a sphere cut by the box z ≥ 0.5 (frontier charts stop the atlas): the south pole is
    # unreachable and the search ends having closed every chart
    box = ImplicitManifold(
        SPHERE.function, SPHERE.jacobian, 2, lower=np.array([-2, -2, 0.5]), upper=np.array([2, 2, 2])
    )
    res = plan_path(box, [0, 0, 1.0], [0, 0, -1.0], radius=0.2)
    assert not res.found and res.no_path and res.charts > 5
    assert res.atlas.centres[:, 2].min() > 0.5 - 0.2


def test_the_chart_budget_stops_a_search_within_an_expansion():
    """Budgets of 3 and 9 charts (an expansion of a sphere's chart creates four): the
    atlas stops at the budget exactly, the chart being grown stays open, and the answer is
    no path, without a proof."""
    for budget in (3, 9):
        res = plan_path(SPHERE, [0, 0, 1.0], [0, 0, -1.0], radius=0.2, max_charts=budget)
        assert res.charts == budget and not res.found and not res.no_path
        assert sum(c.expanded for c in res.atlas.charts) == res.expanded < budget
    a = Atlas(SPHERE, [0, 0, 1.0], radius=0.2)
    assert a.grow(0, max_charts=4) == [1, 2, 3] and not a.charts[0].expanded
    assert a.grow(0) == [4] and a.charts[0].expanded  # grown again, the chart closes
    with pytest.raises(TautError, match="max_charts"):
        plan_path(SPHERE, [0, 0, 1.0], [0, 0, -1.0], radius=0.2, max_charts=1)


def test_start_off_manifold_is_rejected():
    with pytest.raises(TautError):
        Atlas(SPHERE, [0, 0, 2.0], radius=0.2)


def test_progress_counts_the_charts_expanded():
    calls = []
    res = plan_path(
        SPHERE, [0, 0, 1.0], [0, 0, -1.0], radius=0.2, progress=lambda done, total: calls.append((done, total))
    )
    assert res.found and res.expanded > 1
    assert calls == [(k, None) for k in range(1, res.expanded + 1)] + [(res.expanded, res.expanded)]


_angle = st.floats(-12, 12, allow_nan=False, allow_subnormal=False)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(_angle, _angle, _angle), min_size=1, max_size=20), st.tuples(_angle, _angle, _angle))
def test_symmetry_images_are_equivalent_and_nearest(points, reference):
    """The half-turn ``(φ, θ) → (φ + π, −θ)`` and 2π periods: the image found is an image
    (by brute force over the group), no image is nearer the reference, and the canonical
    form is an image inside its window."""
    sym = Symmetry(((0, 2 * np.pi, -np.pi), (1, 2 * np.pi, -np.pi / 2)), flip=(0, 1))
    X = np.array(points)
    ref = np.array(reference)
    near, flipped = sym.nearest(X, ref)
    np.testing.assert_allclose(near[:, 2], X[:, 2])  # not a periodic coordinate
    for x, y, f in zip(X, near, flipped):
        images = np.array(
            [
                (x[0] + h * np.pi + 2 * np.pi * i, (-1) ** h * x[1] + 2 * np.pi * j)
                for h in (0, 1)
                for i in range(-5, 6)
                for j in range(-5, 6)
            ]
        )
        assert np.linalg.norm(images - y[:2], axis=1).min() < 1e-9  # y is an image of x
        assert np.linalg.norm(y[:2] - ref[:2]) <= np.linalg.norm(images - ref[:2], axis=1).min() + 1e-9
        cx, _ = sym.canonical(x)
        assert -np.pi <= cx[0] < np.pi and 0 <= cx[1] <= np.pi
        assert np.linalg.norm(images - cx[:2], axis=1).min() < 1e-9
        # tangent vectors follow the flip: the θ component changes sign
        assert sym.tangent(np.eye(3), bool(f))[1, 1] == (-1.0 if f else 1.0)


def test_symmetry_canonical_form_is_unique_and_arguments_checked():
    sym = Symmetry(((0, 2 * np.pi, -np.pi), (1, 2 * np.pi, -np.pi / 2)), flip=(0, 1))
    # images of one point, also on the lines θ = 0 and θ = π that the half-turn keeps
    for phi, theta in ((2.0, 0.7), (2.0, 0.0), (-0.5, np.pi), (3.0, 2.5)):
        forms = [
            sym.canonical(np.array([phi + h * np.pi + 2 * np.pi * i, (-1) ** h * theta + 2 * np.pi * j, 0.0]))[0]
            for h in (0, 1)
            for i in (-1, 0, 1)
            for j in (-1, 0, 1)
        ]
        np.testing.assert_allclose(forms, np.broadcast_to(forms[0], (len(forms), 3)), atol=1e-9)
        assert -np.pi <= forms[0][0] < np.pi and 0 <= forms[0][1] <= np.pi
    with pytest.raises(TautError, match="flip"):
        Symmetry(((0, 2 * np.pi, -np.pi),), flip=(0, 1))
    with pytest.raises(TautError, match="positive"):
        Symmetry(((0, 0.0, 0.0),))


def test_polytope_membership_by_planes_matches_the_hull_of_its_vertices():
    """``contains`` (cube and cutting planes) agrees with the convex hull of the vertices the
    cuts produce, and a plane-only polytope (AtlasRRT's) answers the same."""
    from scipy.spatial import Delaunay

    rng = np.random.default_rng(5)
    P, Q = Polytope(3, 1.0), Polytope(3, 1.0, vertices=False)
    for ident in range(6, 16):
        n = rng.normal(size=3)
        off = rng.uniform(0.4, 1.2)
        P.cut(n, off, ident)
        Q.cut(n, off, ident)
    hull = Delaunay(P.vertices)
    U = rng.uniform(-1.1, 1.1, (2000, 3))
    inside = hull.find_simplex(U) >= 0
    near_face = np.abs(U).max(axis=1) > 0.999  # avoid ties on the cube faces
    by_planes = np.array([P.contains(u) for u in U])
    assert np.array_equal(by_planes[~near_face], inside[~near_face]) and inside.sum() > 50
    assert np.array_equal(by_planes, [Q.contains(u) for u in U])
    with pytest.raises(TautError, match="no vertices"):
        Q.exterior(0.5)
