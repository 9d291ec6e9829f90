"""Dissimilar-dimension fusion of a 3-D radar with a bearing-only or range-only remote sensor.

The pseudo-measurement method of the paper (GDOP, its claimed covariance and a consistent one),
the optimal maximum-likelihood fuser and the Cramér-Rao bound; ``scenarios`` holds the paper's
two scenarios and their Monte Carlo evaluation.
"""

from registration.fusion.fuser import (
    COMPONENTS, FusionResult, OptimalResult, crlb, fisher_information, fuse_optimal, fuse_paper, gdop, gdop_from_samples,
    parse_components, radar_point, wrap_angle,
)

__all__ = ["COMPONENTS", "FusionResult", "OptimalResult", "crlb", "fisher_information", "fuse_optimal", "fuse_paper",
           "gdop", "gdop_from_samples", "parse_components", "radar_point", "wrap_angle"]
