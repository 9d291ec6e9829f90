"""The run of registration register, stage by stage: plan, pairing stage (asynchronous form), the
checkpointed filtering and its state, the summary, and the pipeline
(docs/howto/register-recorded-files.md)."""

__all__: list[str] = []
