"""Tracks of the other sensors joined to anchor targets: the units (grouping.units), the target
windows fitted with the states held (windowfit), the anchors' curves (curves, and passcurves: those
of the join passes), the join test (attach), the joins (joins), their checks under the registration
(checks), single plots (singles)."""
