"""The data of a fleet problem: the long-form tables and their columns, their checks, platform navigation at the plot times (and at seen times), the state layout, and FleetProblem (docs/fleet.md)."""

__all__: list[str] = []
