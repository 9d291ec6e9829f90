"""Registration of recorded data (``registration register``): file formats with units in the
column names, row checks with a reason for every bad row, pairing of asynchronous plots, and a
streaming run that is checkpointed and resumes bit for bit.

The run is a pipeline (:mod:`.run.runner`) of stages that take its plan: :mod:`.run.plan` (with
:mod:`registration.io.output.outfolder`; the unit check :mod:`.reading.unitcheck` through
:func:`.run.plan.input_warnings`) -> :mod:`.run.pairstage` (with :mod:`.reading.sources`,
:mod:`.reading.streams`, :mod:`.pairing.pairs`) -> :mod:`.run.filtering` (with :mod:`.run.runstate`,
:mod:`.output.outputs`) -> :mod:`.run.summary` and :mod:`.output.plots` -> publication in ``--out``.

Subpackages: ``run`` (the stages: plan, pairing stage, checkpointed filtering, summary, runner)
above ``reading`` (formats, row checks, field counts, unit checks, sources, streams), ``pairing``
(the pairing of two plot streams) and ``output`` (outputs, plots, writers); ``options`` (the run's
and the pairing's options) lies below them all.
"""

from registration.io.files.tablefile import REASON_CODES, FileFormatError, NoValidRowsError
from registration.io.output.checkpoint import CheckpointError, load_checkpoint, save_checkpoint
from registration.io.output.outfolder import OUTPUT_NAMES, OutputFolderError
from registration.recorded.options import PairingOptions, RunOptions
from registration.recorded.output.writers import CsvAppender, PartsWriter
from registration.recorded.reading.columns import (
    ESTIMATE_COLUMNS,
    NAV_FIELDS,
    PAIRED_COLUMNS,
    PLOT_FIELDS,
    POSITION_COLUMNS,
    REJECTED_COLUMNS,
    SYNC_COLUMNS,
    SYNC_FIELDS,
    UNPAIRED_COLUMNS,
    Field,
)
from registration.recorded.reading.formats import (
    from_file_frame,
    iter_frames,
    read_columns,
    read_table,
    to_file_frame,
    write_table,
)
from registration.recorded.reading.rowcheck import BadRowError, check_frame, sync_layout
from registration.recorded.reading.validate import validate_files
from registration.recorded.run.runner import run_register
from registration.recorded.run.summary import summary_consistency

__all__ = [
    "run_register",
    "validate_files",
    "summary_consistency",
    "RunOptions",
    "PairingOptions",
    "FileFormatError",
    "BadRowError",
    "CheckpointError",
    "OutputFolderError",
    "NoValidRowsError",
    "OUTPUT_NAMES",
    "read_table",
    "write_table",
    "to_file_frame",
    "from_file_frame",
    "iter_frames",
    "read_columns",
    "check_frame",
    "sync_layout",
    "REASON_CODES",
    "CsvAppender",
    "PartsWriter",
    "load_checkpoint",
    "save_checkpoint",
    "Field",
    "SYNC_FIELDS",
    "SYNC_COLUMNS",
    "PLOT_FIELDS",
    "NAV_FIELDS",
    "ESTIMATE_COLUMNS",
    "POSITION_COLUMNS",
    "REJECTED_COLUMNS",
    "UNPAIRED_COLUMNS",
    "PAIRED_COLUMNS",
]
