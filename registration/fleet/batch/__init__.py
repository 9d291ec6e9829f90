"""The batch solver of fleet registration: target windows (blocks), normal equations, the Schur complement, Levenberg-Marquardt, starting values, covariance and fused targets, residuals, and solve_batch (docs/fleet.md)."""

__all__: list[str] = []
