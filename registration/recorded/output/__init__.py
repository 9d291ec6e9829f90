"""What a recorded run writes: outputs, the plots and their series, the writers, and publication in
--out (docs/howto/register-recorded-files.md); the summary is a stage of the run (run.summary)."""

__all__: list[str] = []
