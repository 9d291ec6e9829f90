"""Dissimilar-dimension fusion of a radar with a remote sensor that measures fewer polar components.

``paper``: the paper's pseudo-measurement method with its claimed and its consistent covariance;
``optimal``: the maximum-likelihood fuser, Fisher information and Cramér-Rao bound; ``gdop``: the
accuracy figure; ``polar`` and ``checks``: components, transforms and input checks;
``scenarios``: the paper's two scenarios and their Monte Carlo evaluation.
"""

from registration.core.angles import wrap_angle
from registration.fusion.gdop import gdop, gdop_from_samples
from registration.fusion.optimal import OptimalResult, crlb, fisher_information, fuse_optimal
from registration.fusion.paper import FusionResult, fuse_paper, radar_point
from registration.fusion.polar import COMPONENTS, parse_components

__all__ = [
    "COMPONENTS",
    "FusionResult",
    "OptimalResult",
    "crlb",
    "fisher_information",
    "fuse_optimal",
    "fuse_paper",
    "gdop",
    "gdop_from_samples",
    "parse_components",
    "radar_point",
    "wrap_angle",
]
