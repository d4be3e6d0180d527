"""agglo: adhesive DEM with dielectric electrostatics and DSMC acoustic agglomeration (docs/python.md)."""
from ._agglo import *  # noqa: F401,F403
