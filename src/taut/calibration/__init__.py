"""Calibration: a built robot's exits, encoder offsets and platform anchors from its own cable
measurements, the unknown poses of those measurements with them, an honest report of what the
data determine, and where to measure (Borgstrom et al. 2009; Miermeister & Pott 2012;
Triggs et al. 2000).

References
----------
.. [1] P. H. Borgstrom et al., "NIMS-PL: A Cable-Driven Robot With Self-Calibration
   Capabilities", IEEE Transactions on Robotics 25(5), 2009. (docs/references.bib: borgstrom2009)
.. [2] P. Miermeister, A. Pott, "Auto-Calibration Method for Overconstrained Cable-Driven
   Parallel Robots", IEEE ICRA 2012. (docs/references.bib: miermeister2012)
.. [3] B. Triggs, P. F. McLauchlan, R. I. Hartley, A. W. Fitzgibbon, "Bundle Adjustment — A
   Modern Synthesis", LNCS 1883, Springer, 2000. (docs/references.bib: triggs2000)
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from taut._lazy import lazy_exports

if TYPE_CHECKING:
    from taut.calibration._data import (
        MAX_ROWS,
        MeasurementError,
        Measurements,
        measurements,
        parse_measurements,
        read_measurements,
    )
    from taut.calibration._fit import (
        GAUGE_RULE,
        OUTLIER_THRESHOLD,
        ROBUST_LOSSES,
        CalibrationResult,
        calibrate,
    )
    from taut.calibration._identify import ESTIMATES, MAX_CONDITION, Identifiability, identifiability
    from taut.calibration._plan import PosePlan, plan_poses
    from taut.calibration._simulate import simulate_measurements

#: Every name is imported on first use (PEP 562), so that importing the package loads nothing heavy.
_LAZY = {
    "MAX_ROWS": "taut.calibration._data",
    "MeasurementError": "taut.calibration._data",
    "Measurements": "taut.calibration._data",
    "measurements": "taut.calibration._data",
    "parse_measurements": "taut.calibration._data",
    "read_measurements": "taut.calibration._data",
    "GAUGE_RULE": "taut.calibration._fit",
    "OUTLIER_THRESHOLD": "taut.calibration._fit",
    "ROBUST_LOSSES": "taut.calibration._fit",
    "CalibrationResult": "taut.calibration._fit",
    "calibrate": "taut.calibration._fit",
    "ESTIMATES": "taut.calibration._identify",
    "MAX_CONDITION": "taut.calibration._identify",
    "Identifiability": "taut.calibration._identify",
    "identifiability": "taut.calibration._identify",
    "PosePlan": "taut.calibration._plan",
    "plan_poses": "taut.calibration._plan",
    "simulate_measurements": "taut.calibration._simulate",
}

__all__ = [
    "ESTIMATES",
    "GAUGE_RULE",
    "MAX_CONDITION",
    "MAX_ROWS",
    "OUTLIER_THRESHOLD",
    "ROBUST_LOSSES",
    "CalibrationResult",
    "Identifiability",
    "MeasurementError",
    "Measurements",
    "PosePlan",
    "calibrate",
    "identifiability",
    "measurements",
    "parse_measurements",
    "plan_poses",
    "read_measurements",
    "simulate_measurements",
]

__getattr__, __dir__ = lazy_exports(__name__, _LAZY, __all__)
