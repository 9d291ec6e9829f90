"""The description of one emitted function: sympy expressions plus names.

A :class:`FunctionSpec` is what every derivation module returns. The emitter
(:mod:`derive.emit`) turns it into a CasADi ``Function`` and C source; the tests
use the same spec to evaluate the sympy expressions directly and to check every
declared Jacobian against CasADi automatic differentiation and finite
differences.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp


@dataclass(frozen=True)
class Port:
    """A named input or output.

    ``expr`` is a sympy ``Matrix`` (column vector or matrix) or a single
    ``Symbol``/expression for a scalar. ``unit`` is free text for the manifest
    (SI units and radians only).
    """

    name: str
    expr: object
    unit: str = ""

    @property
    def matrix(self) -> sp.Matrix:
        return self.expr if isinstance(self.expr, sp.MatrixBase) else sp.Matrix([[self.expr]])

    @property
    def shape(self) -> tuple[int, int]:
        return tuple(self.matrix.shape)


@dataclass(frozen=True)
class JacobianDecl:
    """Declares that output ``output`` is d(``of``)/d(``wrt``...).

    ``wrt`` lists input names (each scalar or vector); the Jacobian's columns
    follow the concatenation of those inputs' entries in order.
    """

    output: str
    of: str
    wrt: tuple[str, ...]


@dataclass(frozen=True)
class FunctionSpec:
    """A function given by sympy expressions: its name, docstring, ports and declared Jacobians."""

    name: str
    doc: str
    inputs: tuple[Port, ...]
    outputs: tuple[Port, ...]
    jacobians: tuple[JacobianDecl, ...] = field(default_factory=tuple)
    #: Input domains for random testing: name -> (low, high) per entry.
    domain: dict = field(default_factory=dict)


def jacobian(f: sp.MatrixBase, *variables) -> sp.Matrix:
    """Symbolic Jacobian of column vector ``f`` with respect to the flattened variables."""
    flat = []
    for v in variables:
        flat.extend(list(v) if isinstance(v, sp.MatrixBase) else [v])
    return sp.Matrix(f).jacobian(sp.Matrix(flat))


@dataclass(frozen=True)
class CasadiPort:
    """An input or output of a function built directly in CasADi (no sympy expression)."""

    name: str
    shape: tuple[int, int]
    unit: str = ""


@dataclass(frozen=True)
class CasadiSpec:
    """A function composed in CasADi from sympy-derived pieces (e.g. a whole Kalman step).

    ``build()`` returns the ``casadi.Function``; its input/output names and shapes must match
    ``inputs``/``outputs``. There is no sympy expression to evaluate directly, so the tests check
    these against an independent NumPy composition instead.
    """

    name: str
    doc: str
    inputs: tuple[CasadiPort, ...]
    outputs: tuple[CasadiPort, ...]
    builder: object
    domain: dict = field(default_factory=dict)
    jacobians: tuple = ()

    def build(self):
        fn = self.builder()
        assert [fn.name_in(i) for i in range(fn.n_in())] == [p.name for p in self.inputs], self.name
        assert [fn.name_out(i) for i in range(fn.n_out())] == [p.name for p in self.outputs], self.name
        return fn
