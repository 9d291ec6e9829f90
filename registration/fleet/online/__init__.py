"""The online fleet filter (docs/background/fleet-online.md): FleetFilter and
register_online, the information of one epoch, the Kalman update in information form and its
starting point, and the result."""

__all__: list[str] = []
