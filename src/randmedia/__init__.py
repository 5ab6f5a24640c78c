"""randmedia: generate and characterize disordered two-phase media and point patterns.

Reproduces, from code alone, the figures, tables and quoted numbers of

* Ma & Torquato, PRE 102, 043310 (2020) -- Debye random media (``debye2020``);
* Klatt & Torquato, PRE 94, 022152 (2016) -- MRJ sphere packings II (``mrj2016``);
* Hyperuniformity on spherical surfaces, PRE 100, 022107 (2019) (``sphere2019``).

Data flows one way: :mod:`randmedia.generate` -> :mod:`randmedia.describe` ->
:mod:`randmedia.fit` -> :mod:`randmedia.plot` / :mod:`randmedia.compare`.
"""

import os as _os

# HDF5 (behind netCDF4) takes a POSIX lock on every file it opens; on network
# or container file systems and with parallel Snakemake jobs that fails with
# "unable to lock file". Our writes are atomic renames, so locking buys nothing.
_os.environ.setdefault("HDF5_USE_FILE_LOCKING", "FALSE")

__version__ = "0.1.0"
