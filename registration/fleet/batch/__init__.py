"""The batch solver of fleet registration (docs/background/fleet-model.md): target windows (``blocks``), the
plots laid
out for evaluation (``design``), residuals and normal equations (``normal``), the Schur complement
(``schur``), the Levenberg-Marquardt engine (``levenberg_marquardt``), starting values
(``initial``), what is set aside (``set_aside``), the fit (``solver``), covariance and fused
targets (``covariance``), residuals (``residuals``), :func:`solve_batch` (``estimate``), the
partitioned solve of an archive (``partitioned``) and its outputs (``outputs``)."""

__all__: list[str] = []
