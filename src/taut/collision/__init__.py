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

from __future__ import annotations

from typing import TYPE_CHECKING

from taut._lazy import lazy_exports

if TYPE_CHECKING:
    from taut.collision._capsules import CapsuleModel, capsule_model, capsule_segments
    from taut.collision._proximity import ProximityResult, proximity
    from taut.collision._singularity import force_closure_singular, jacobian_singular, positive_span_lp
    from taut.collision._trajectory import CheckResult, check_poses, load_trajectory, straight_moves, trajectory_poses

#: Every name is imported on first use (PEP 562), so that importing the package loads nothing heavy.
_LAZY = {
    "CapsuleModel": "taut.collision._capsules",
    "capsule_model": "taut.collision._capsules",
    "capsule_segments": "taut.collision._capsules",
    "ProximityResult": "taut.collision._proximity",
    "proximity": "taut.collision._proximity",
    "force_closure_singular": "taut.collision._singularity",
    "jacobian_singular": "taut.collision._singularity",
    "positive_span_lp": "taut.collision._singularity",
    "CheckResult": "taut.collision._trajectory",
    "check_poses": "taut.collision._trajectory",
    "load_trajectory": "taut.collision._trajectory",
    "straight_moves": "taut.collision._trajectory",
    "trajectory_poses": "taut.collision._trajectory",
}

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

__getattr__, __dir__ = lazy_exports(__name__, _LAZY, __all__)
