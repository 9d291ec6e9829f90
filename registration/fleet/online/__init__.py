"""The online fleet filter (docs/fleet-online.md): FleetFilter and
register_online, the information of one epoch, and the result."""

__all__: list[str] = []
