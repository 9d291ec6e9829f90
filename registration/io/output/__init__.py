"""Output folders published whole (``outfolder``: a run writes into ``OUT/partial-*`` and moves its
files in at the end, so ``--out`` never holds a half-written run) and checkpoints (``checkpoint``)."""
