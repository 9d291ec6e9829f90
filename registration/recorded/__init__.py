"""Registration of recorded data (``registration register``): file formats with units in the
column names, row checks with a reason for every bad row, pairing of asynchronous plots, and a
streaming run that is checkpointed and resumes bit for bit.

The run is a pipeline (:mod:`.runner`): :mod:`.plan` (with :mod:`.outfolder`) -> :mod:`.unitcheck`
-> :mod:`.paired` (with :mod:`.sources`, :mod:`.streams`, :mod:`.pairing`) -> :mod:`.filtering`
(with :mod:`.runstate`, :mod:`.outputs`) -> :mod:`.report` and :mod:`.plots` -> publication in
``--out`` (:mod:`.outfolder`). Below them: :mod:`.columns`, :mod:`.rowcheck`, :mod:`.formats`,
:mod:`.writers`, :mod:`.checkpoint`, :mod:`.options`.
"""

from registration.recorded.checkpoint import CheckpointError, load_checkpoint, save_checkpoint
from registration.recorded.columns import (
    ESTIMATE_COLUMNS, NAV_FIELDS, PAIRED_COLUMNS, PLOT_FIELDS, POSITION_COLUMNS, REJECTED_COLUMNS, SYNC_COLUMNS, SYNC_FIELDS,
    UNPAIRED_COLUMNS, Field, FileFormatError,
)
from registration.recorded.formats import from_file_frame, iter_frames, read_columns, read_table, to_file_frame, write_table
from registration.recorded.filtering import NoValidRowsError
from registration.recorded.options import PairingOptions, RunOptions
from registration.recorded.outfolder import OUTPUT_NAMES, OutputFolderError
from registration.recorded.report import summary_consistency
from registration.recorded.rowcheck import REASON_CODES, BadRowError, check_frame, sync_layout
from registration.recorded.runner import run_register
from registration.recorded.validate import validate_files
from registration.recorded.writers import CsvAppender, PartsWriter

__all__ = [
    "run_register", "validate_files", "summary_consistency", "RunOptions", "PairingOptions",
    "FileFormatError", "BadRowError", "CheckpointError", "OutputFolderError", "NoValidRowsError", "OUTPUT_NAMES",
    "read_table", "write_table", "to_file_frame", "from_file_frame", "iter_frames", "read_columns",
    "check_frame", "sync_layout", "REASON_CODES", "CsvAppender", "PartsWriter", "load_checkpoint", "save_checkpoint",
    "Field", "SYNC_FIELDS", "SYNC_COLUMNS", "PLOT_FIELDS", "NAV_FIELDS",
    "ESTIMATE_COLUMNS", "POSITION_COLUMNS", "REJECTED_COLUMNS", "UNPAIRED_COLUMNS", "PAIRED_COLUMNS",
]
