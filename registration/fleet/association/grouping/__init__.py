"""Targets confirmed among the position-fixing sensors: tracks per sensor (tracks), tracklets matched
across sensors per window (match, groups, cost), plot geometry (geometry), confirmation (confirm);
and the units, the tracks of every sensor that confirmation groups and joining joins (units)."""
