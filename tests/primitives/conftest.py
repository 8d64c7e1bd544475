import numpy as np

from tautwire.model import PathGraph
from tautwire.primitives import PrimitiveContext, make_context

CONTACT = np.array([0.1, 0.0, 0.1])
GRIPPER = np.array([0.4, 0.0, 0.1])


def graph_for(contact_prior: np.ndarray = CONTACT, gripper: np.ndarray = GRIPPER) -> PathGraph:
    return PathGraph.from_positions(
        [contact_prior, gripper],
        mass_per_length=0.0,
        kinds=["fixed", "gripper"],
        labels=["A1", "left"],
    )


def context(k_initial: float = 100.0, **kwargs: object) -> PrimitiveContext:
    return make_context(graph_for(), "left", k_initial=k_initial, **kwargs)  # type: ignore[arg-type]
