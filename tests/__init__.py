"""The test suite.

One BLAS thread per test process, and per process a test starts (they inherit the environment):
the suite runs one test process per core, and OpenBLAS threads on top of them only wait on each
other (a batch solve took four to six times the CPU time, for the same result). Set here, in the
package pytest imports before tests/conftest.py and so before numpy is first imported; a value set
outside the suite is kept."""

import os

for _name in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")
