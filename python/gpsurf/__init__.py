"""Gaussian-Product Subdivision surfaces: covariance meshes, exact subdivision and evaluation, fitting,
distances and off-screen rendering, with numpy arrays in and out.

Arrays handed out are read-only copies; assign whole arrays to change a Mesh. Every call that
computes runs without the GIL (other Python threads run meanwhile) and stops on Ctrl-C. Errors
raise gpsurf.Error with the command line's one-line message, ValueError, TypeError or IndexError
for arguments. help(gpsurf.Mesh), help(gpsurf.Surface) and the stubs (__init__.pyi) give the API.
"""
from ._gpsurf import *  # noqa: F401,F403
from ._gpsurf import __version__  # noqa: F401
from . import _gpsurf

# Named by the package, as Python users import them (pickle, repr, help).
for _name in dir(_gpsurf):
    if not _name.startswith("_"):
        try:
            getattr(_gpsurf, _name).__module__ = __name__
        except (AttributeError, TypeError):
            pass
del _name
