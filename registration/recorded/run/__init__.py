"""The run of registration register: plan, the checkpointed
filtering and its state, the pipeline (docs/register.md)."""

__all__: list[str] = []
