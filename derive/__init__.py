"""Symbolic derivations (sympy, CasADi) of every transform and Jacobian of the project.

This package is the single source of truth for the mathematics. ``python -m derive`` emits
CasADi functions (serialized and as C source) into ``generated/``; the runtime package
``registration`` only ever calls those.
"""
