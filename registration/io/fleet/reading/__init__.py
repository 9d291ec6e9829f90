"""Reading one fleet file: its cells checked and converted from file units (``cells``), whole-file
checks (``checks``), the tables read in memory (``read``), bad rows and their reasons
(``rejects``) and the plots set aside with a note (``setaside``). See
docs/reference/fleet-tables.md."""

__all__: list[str] = []
