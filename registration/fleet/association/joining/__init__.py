"""Tracks of the other sensors joined to anchor targets: the units (grouping.units), the anchors' curves
(curves), the join test (attach), the joins (joins), their checks under the registration (checks),
single plots (singles)."""
