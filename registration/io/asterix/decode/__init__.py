"""The records decoded: UAPs per category and edition (uap), the vectorised walk of FSPEC and items
(walker) and its plain reference (scalar), the items of CAT048,
CAT034 and CAT021 (decode48, decode34, decode21), one file decoded (reader)."""
