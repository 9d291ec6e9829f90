"""Association of plots without target ids, jointly with the registration (docs/background/association.md).

``associate`` (:func:`associate_and_register`) runs it: ``problems`` (the ids the plots carry, the
problems of all and of the labelled plots, references), ``options``, ``grouping/`` (targets confirmed
among the position-fixing sensors: tracks per sensor, tracklets matched per window, confirmation),
``references`` (confirmed targets that are reference targets), ``joining/`` (the other sensors' tracks
joined to the anchor targets under the registration, and checked after every solve), ``solves`` (the
registrations on the way), ``report`` and ``result``; ``simulated/`` holds the simulated clutter scenarios
and the test fleets.
"""

__all__: list[str] = []
