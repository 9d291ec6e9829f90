"""Diagnostics that name what a fleet registration's model misses: each sensor's normalised
residuals binned by measured azimuth, range, time, plot kind and target, with the tests that point
at an unmodelled eccentricity, range gain, bias change, PSR/SSR difference or a wrong target id
(:func:`diagnose`); and for a run outside its consistency band, which sensors and bins carry the
excess. See docs/background/diagnostics.md."""

from registration.fleet.diagnostics.run import Diagnostics, diagnose, sensor_plots
from registration.fleet.diagnostics.sensor import Candidate, SensorPlots

__all__ = ["Candidate", "Diagnostics", "SensorPlots", "diagnose", "sensor_plots"]
