"""The reduced cable model {G, rho}: a path graph of feature points and edges.

Pure NumPy/SciPy (paper section "Model Representation").
"""

from tautwire.model.edge import Edge
from tautwire.model.feature_point import FEATURE_KINDS, FeatureKind, FeaturePoint
from tautwire.model.interpolation import lerp, slerp
from tautwire.model.mass import point_masses
from tautwire.model.path_graph import PathGraph
from tautwire.model.quaternion import orientation_along
from tautwire.model.sag import sag, sag_from_span
from tautwire.model.tension import GRAVITY, EdgeTension, edge_tension, hanging_end_tension

__all__ = [
    "FEATURE_KINDS",
    "GRAVITY",
    "Edge",
    "EdgeTension",
    "FeatureKind",
    "FeaturePoint",
    "PathGraph",
    "edge_tension",
    "hanging_end_tension",
    "lerp",
    "orientation_along",
    "point_masses",
    "sag",
    "sag_from_span",
    "slerp",
]
