"""The peer ``bertini2`` (``pip install bertini2``; homotopy continuation) on a DGP
sub-problem, shared by ``bench_dgp.py --peer`` and ``bench_dgp_random.py --peer``: the same
polynomial system as ``taut.dgp.build_subproblem`` (its zero-dimensional solve
from the start system it infers, one thread), its real endpoints with non-negative tensions,
and how many of taut's certified solutions they reproduce."""

import time
from fractions import Fraction

import _common  # noqa: F401  (first: it pins the thread pools to one core)
import numpy as np

from taut.dgp import load, reference_choice
from taut.geometry import rotation_matrix

ALL_TAUT = (0, 1, 2)
REAL_TOL = 1e-8  # |imaginary part| per unknown, relative to max(1, |value|)
MATCH_TOL = 1e-5  # reference points and tensions agreeing with taut's solution
SEED = 1  # bertini2's random gamma and start system: the same paths every run


def import_bertini():
    """The ``bertini`` module, or None after printing why it cannot be used."""
    try:
        import bertini
    except ImportError as e:
        print(
            "bertini2: not installed (pip install bertini2)"
            if e.name == "bertini"
            else f"bertini2: not available ({e})"
        )
        return None
    return bertini


def _cross(u, v):
    return [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]


def bertini_system(bertini, robot, lengths, taut):
    """The equations of ``build_subproblem(robot, lengths, taut)`` as a ``bertini.System``:
    unknowns ``q_1, q_2, q_3`` (fixed-frame reference points) then the scaled tensions
    ``t_i = τ_i/ρ_i``; 3 rigidity relations, ``m`` cable lengths, 3 forces and 3 moments about
    the exit point of the first taut cable.  Every coefficient is the exact value of taut's
    double, so both tools solve the same system."""

    def c(x):
        return bertini.coefficient(Fraction(float(x)))

    a, r = robot.exits, robot.anchors
    f, mext, gp = load(robot)
    labels, refs = reference_choice(robot, taut, gp)
    qv = [bertini.Variable(f"q{s}{k}") for s in range(3) for k in range(3)]
    tv = [bertini.Variable(f"t{i}") for i in taut]
    q = [qv[0:3], qv[3:6], qv[6:9]]
    t = dict(zip(taut, tv))
    e1 = [q[1][k] - q[0][k] for k in range(3)]
    e2 = [q[2][k] - q[0][k] for k in range(3)]
    n12 = _cross(e1, e2)
    Eb = np.column_stack([refs[1] - refs[0], refs[2] - refs[0], np.cross(refs[1] - refs[0], refs[2] - refs[0])])

    def point(label, body):
        if label in labels:
            return q[labels.index(label)]
        beta = np.linalg.solve(Eb, body - refs[0])
        beta = np.where(np.abs(beta) < 1e-14, 0.0, beta)
        return [q[0][k] + c(beta[0]) * e1[k] + c(beta[1]) * e2[k] + c(beta[2]) * n12[k] for k in range(3)]

    b = {i: point(i, r[i]) for i in taut}
    g = point("G", gp)
    pole = a[taut[0]]
    eqs = []
    for i, j in ((0, 1), (0, 2), (1, 2)):
        d = float(np.linalg.norm(refs[i] - refs[j]))
        eqs.append(sum((q[i][k] - q[j][k]) ** 2 for k in range(3)) - c(d) ** 2)
    for i in taut:
        eqs.append(sum((b[i][k] - c(a[i][k])) ** 2 for k in range(3)) - c(lengths[i]) ** 2)
    for k in range(3):
        eqs.append(sum(t[i] * (c(a[i][k]) - b[i][k]) for i in taut) + c(f[k]))
    for k in range(3):
        k1, k2 = (k + 1) % 3, (k + 2) % 3
        acc = (g[k1] - c(pole[k1])) * c(f[k2]) - (g[k2] - c(pole[k2])) * c(f[k1]) + c(mext[k])
        for i in taut:
            arm = a[i] - pole
            acc = acc + t[i] * ((b[i][k1] - c(pole[k1])) * c(arm[k2]) - (b[i][k2] - c(pole[k2])) * c(arm[k1]))
        eqs.append(acc)
    system = bertini.System()
    system.add_variable_group(bertini.VariableGroup(qv + tv))
    for e in eqs:
        system.add_function(e)
    return system


def run_bertini(bertini, robot, lengths, mptype, taut=ALL_TAUT):
    """``(seconds, admissible endpoints (k, 9 + m) real, finite endpoints, paths)`` of the
    sub-problem of the taut cables ``taut``."""
    bertini.recording(False)  # no records directory written into the working directory
    bertini.random.set_random_seed(SEED)
    system = bertini_system(bertini, robot, lengths, taut)
    solver = bertini.nag_algorithm.ZeroDimSolver(system, mptype=mptype, num_threads=1)
    t0 = time.perf_counter()
    finite = solver.solve(show_progress=False)
    seconds = time.perf_counter() - t0
    x = np.array([[complex(v) for v in p] for p in finite]).reshape(len(finite), 9 + len(taut))
    real = np.all(np.abs(x.imag) <= REAL_TOL * np.maximum(1.0, np.abs(x)), axis=1)
    admissible = real & np.all(x.real[:, 9:] >= 0.0, axis=1)
    return seconds, x[admissible].real, len(finite), solver.num_paths()


def matching(robot, lengths, taut_solutions, endpoints, taut=ALL_TAUT):
    """How many of taut's solutions one of the peer's endpoints reproduces (reference points
    and scaled tensions within ``MATCH_TOL``)."""
    _, _, gp = load(robot)
    _, refs = reference_choice(robot, taut, gp)
    idx = list(taut)
    xs = [
        np.concatenate(
            [
                (s.position + refs @ rotation_matrix(s.orientation, robot.orientation).T).ravel(),
                s.tensions[idx] / lengths[idx],
            ]
        )
        for s in taut_solutions
    ]
    return sum(any(np.abs(e - x).max() <= MATCH_TOL for e in endpoints) for x in xs)
