"""Archives of fleet tables read lazily by time range for the partitioned solver: Parquet files
(``parquet``), a folder of CSV files converted once (``csvfolder``), the large tables laid out by
time (``timeorder``), and an archive's plots with the targets an association by partitions gave
them (``labelled``). See docs/howto/register-an-archive.md."""

__all__: list[str] = []
