"""``python -m registration.io.fleet``: the reference page of the fleet files in Markdown
(:func:`registration.io.fleet.schema.schema_markdown`), as docs/reference/fleet-tables.md holds it:
``python -m registration.io.fleet > docs/reference/fleet-tables.md``."""

from registration.io.fleet.schemadoc import schema_markdown

__all__: list[str] = []

print(schema_markdown(), end="")
