"""Files in general: CSV/Parquet by suffix, exact writing and the folder writer (``tablefile``), the
field count of every CSV line from the raw bytes (``csvrows``), the rejected ledger of what a reader
set aside (``ledger``), the one error for a file that cannot be read (``unreadable``)."""
