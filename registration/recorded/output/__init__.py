"""What a recorded run writes: outputs, the report, the plots and their series, the writers, and
publication in --out (docs/register.md)."""

__all__: list[str] = []
