"""The simulated fleet: ships, sites, sensors and targets with
their true errors, through the generated geometry (docs/background/fleet-model.md)."""

__all__: list[str] = []
