"""tautwire: blind, force-based robotic manipulation of cables.

The core (``model``, ``estimation``, ``control``, ``robot``, ``primitives``)
needs only NumPy and SciPy; the simulated world (``sim``) is the only package
that imports MuJoCo.
"""

from tautwire.errors import TautwireError

__all__ = ["TautwireError", "__version__"]
__version__ = "0.1.0"
