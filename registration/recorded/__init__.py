"""Registration of recorded data: file formats, row checks, pairing of asynchronous plots,
checkpoints and the resumable streaming run behind ``registration register``."""

from registration.recorded.runner import RunOptions, run_register, validate_files

__all__ = ["RunOptions", "run_register", "validate_files"]
