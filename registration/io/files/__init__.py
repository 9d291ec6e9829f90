"""Table files in general: CSV/Parquet by suffix, exact writing (``tablefile``), the field count of
every CSV line from the raw bytes (``csvrows``)."""
