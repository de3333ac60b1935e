"""Self-collision and singularity analysis for every robot of taut (Lieskovský 2020,
§2.3): capsule models (:mod:`.capsules`), proximity matrices and colliding pairs
(:mod:`.proximity`), Jacobian and force-closure singularities (:mod:`.singularity`), and the
check of a trajectory (:mod:`.trajectory`).

References
----------
.. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
   Bachelor thesis, Czech Technical University in Prague, 2020, §2.3, §3.4–3.5.
   (docs/references.bib: lieskovsky2020)
"""

from taut.collision.capsules import CapsuleModel, capsule_model, capsule_segments
from taut.collision.proximity import ProximityResult, proximity
from taut.collision.singularity import force_closure_singular, jacobian_singular, positive_span_lp
from taut.collision.trajectory import CheckResult, check_poses, load_trajectory, straight_moves, trajectory_poses

__all__ = [
    "CapsuleModel",
    "CheckResult",
    "ProximityResult",
    "capsule_model",
    "capsule_segments",
    "check_poses",
    "force_closure_singular",
    "jacobian_singular",
    "load_trajectory",
    "positive_span_lp",
    "proximity",
    "straight_moves",
    "trajectory_poses",
]
