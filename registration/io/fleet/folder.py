"""A folder of fleet tables by their standard names: ``plots``, ``navigation``, ``sensors``,
``platforms``, ``reference`` and ``targets``, each as ``.csv``, ``.parquet`` or ``.pq``.

This is what ``registration import asterix|nmea --out DIR`` writes and what
``registration fleet register --tables DIR`` reads, so that an import and a registration chain in
two commands. A table given by its own option overrides the folder's file.
"""

from __future__ import annotations

from pathlib import Path

__all__ = ["TABLE_NAMES", "REQUIRED_TABLES", "SUFFIXES", "tables_in_folder"]

#: The standard table names, in the order of ``read_fleet_tables``' arguments.
TABLE_NAMES = ("plots", "navigation", "sensors", "platforms", "reference", "targets")
#: The tables a registration cannot do without.
REQUIRED_TABLES = ("plots", "navigation", "sensors")
#: The file suffixes looked for, in this order.
SUFFIXES = (".csv", ".parquet", ".pq")


def tables_in_folder(
    folder: Path | str, given: dict[str, Path | None] | None = None
) -> dict[str, Path | None]:
    """The path of each table: ``given[name]`` where it is not None, else the folder's file of that name.

    Raises ``ValueError`` naming the folder when it is not a folder, when a required table is
    neither given nor in the folder, or when the folder holds a table in two formats (which one
    was meant cannot be told).
    """
    folder = Path(folder)
    given = dict(given or {})
    if not folder.is_dir():
        raise ValueError(
            f"--tables {folder}: no such folder (expected the folder of an import: "
            f"{', '.join(n + '.csv' for n in TABLE_NAMES)}, or .parquet)"
        )
    paths: dict[str, Path | None] = {}
    for name in TABLE_NAMES:
        path = given.get(name)
        if path is not None:
            paths[name] = Path(path)
            continue
        found = [folder / (name + s) for s in SUFFIXES if (folder / (name + s)).is_file()]
        if len(found) > 1:
            raise ValueError(
                f"--tables {folder}: {name} is there in two formats ({', '.join(p.name for p in found)}); "
                f"remove one or name the table with --{name}"
            )
        paths[name] = found[0] if found else None
    missing = [n for n in REQUIRED_TABLES if paths[n] is None]
    if missing:
        raise ValueError(
            f"--tables {folder}: no {', '.join(missing)} table in the folder "
            f"(expected {', '.join(n + '.csv' for n in missing)} or .parquet) and none given by option"
        )
    return paths
