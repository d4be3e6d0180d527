"""agglo: adhesive DEM with dielectric electrostatics and DSMC acoustic agglomeration (docs/python.md)."""
from ._agglo import *  # noqa: F401,F403
from ._agglo import __version__  # noqa: F401  (a star import leaves out dunder names)
