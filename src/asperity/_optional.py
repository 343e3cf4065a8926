"""Optional dependencies: one place that imports them lazily and says how to install them.

``import asperity`` needs only NumPy and SciPy.  Every capability that needs more (plots,
units, measured surfaces, fitting, sweeps, the explorer, boundary elements) imports its
package through :func:`require`, which raises an :class:`ImportError` whose message names
the capability and the extra to install, e.g.::

    fitting needs lmfit: pip install 'asperity[fit]'

The error is a :class:`MissingDependency`, a subclass of :class:`ImportError`, so
``except ImportError`` still catches it; the command line turns it into one line and exit
status 2.
"""

from __future__ import annotations

import importlib
import warnings

__all__ = ["require", "install_hint", "EXTRAS", "MissingDependency"]

#: The extra that provides each optional top-level package.
EXTRAS = {
    "matplotlib": "plot",
    "pandas": "frame",
    "pint": "units",
    "mpmath": "reference",
    "SurfaceTopography": "topography",
    "ContactMechanics": "bem",
    "lmfit": "fit",
    "xarray": "sweep",
    "dask": "sweep",
    "distributed": "sweep",
    "zarr": "sweep",
    "h5netcdf": "sweep",
    "netCDF4": "sweep",
    "tqdm": "sweep",
    "bokeh": "explore",
}


class MissingDependency(ImportError):
    """An optional package is not installed; the message says which extra installs it."""


def install_hint(module: str, extra: str | None = None) -> str:
    """``"pip install 'asperity[EXTRA]'"`` for ``module`` (its extra from :data:`EXTRAS`)."""
    extra = extra or EXTRAS.get(module.split(".")[0], "all")
    return f"pip install 'asperity[{extra}]'"


def require(module: str, *, purpose: str, extra: str | None = None):
    """Import and return ``module``; if missing, raise ImportError saying how to install it.

    Parameters
    ----------
    module : str
        Module to import, e.g. ``"lmfit"`` or ``"matplotlib.pyplot"``.
    purpose : str
        What needs it, for the message: ``"fitting"`` gives "fitting needs lmfit: ...".
    extra : str, optional
        The extra that installs it (default: looked up in :data:`EXTRAS`).

    Raises
    ------
    MissingDependency
        (an :class:`ImportError`) ``"{purpose} needs {package}: pip install 'asperity[{extra}]'"``.
    """
    try:
        with warnings.catch_warnings():
            # SurfaceTopography's MPI stub warns when mpi4py is absent; nothing else is silenced.
            warnings.filterwarnings("ignore", message="Could not import mpi4py", category=ImportWarning)
            return importlib.import_module(module)
    except ImportError as err:
        package = module.split(".")[0]
        raise MissingDependency(f"{purpose} needs {package}: {install_hint(package, extra)}") from err
