"""The data of a fleet problem: the long-form tables and their columns, their checks (sensors,
plots, known targets), platform navigation at the plot times (and at seen times), the state
layout, FleetProblem, and the contract of a source of the tables read by parts, FleetSource
(docs/background/fleet-model.md)."""

__all__: list[str] = []
