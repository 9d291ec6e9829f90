"""sensor-registration: register and fuse radar measurements across moving ships.

Runtime package. All mathematics (transforms, Jacobians) is derived once in ``derive/`` and
reached only through the generated functions (:mod:`registration._codegen`). Subpackages:
``core`` (frames, angles, validation, alignment, observability), the capabilities ``online``,
``fusion``, ``landing`` and ``recorded``, and ``cli`` on top. SI units and radians throughout;
frames are named in variable names (``p_ecef``, ``u_deck``).
"""

__version__ = "0.1.0"
