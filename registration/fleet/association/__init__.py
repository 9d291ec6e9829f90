"""Association of plots without target ids, jointly with the registration (docs/association.md): tracks per sensor, tracklets, matching and grouping, costs, the result, and the simulated clutter scenarios."""

__all__: list[str] = []
