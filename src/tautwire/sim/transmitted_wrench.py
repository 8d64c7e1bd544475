"""Two ways to compute the wrench that a gripper transmits.

:func:`free_joint_wrench` reads the constraint force on
the gripper's free joint, which sums every constraint acting on the gripper
and its fingers: the ``connect`` equality of a held cable and all contacts on
the finger pads. :func:`explicit_wrench` adds up the same forces one by one
(equality rows of ``efc_force`` and ``mj_contactForce`` of each contact on a
gripper geom); the tests check that both agree.

Both return the force that the cable and the contacts exert on the gripper
and the torque about the tool centre point (the gripper body's origin),
world frame, for the state at the start of the last physics step (the
world averages the free joint's over a control period's steps).
"""

from __future__ import annotations

import mujoco
import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]
IntArray = NDArray[np.int64]


def free_joint_wrench(
    data: mujoco.MjData, dof: int, orientation: FloatArray
) -> tuple[FloatArray, FloatArray]:
    """Wrench from the constraint force on a free joint.

    Args:
        data: MuJoCo data after a step.
        dof: First dof address of the gripper's free joint.
        orientation: Gripper orientation [w, x, y, z] at which the forces were
            computed.  # (4,)

    Returns:
        Force [N] and torque [N m] about the body origin, world frame.
    """
    qf = data.qfrc_constraint[dof : dof + 6]
    force: FloatArray = qf[0:3].copy()
    torque = np.empty(3)
    mujoco.mju_rotVecQuat(torque, qf[3:6], orientation)  # body frame -> world
    return force, torque


def explicit_wrench(
    model: mujoco.MjModel,
    data: mujoco.MjData,
    body_ids: IntArray,
    equality_ids: IntArray,
    tcp: FloatArray,
    orientation: FloatArray,
) -> tuple[FloatArray, FloatArray]:
    """Wrench summed over a gripper's equality constraints and contacts.

    Args:
        model: MuJoCo model.
        data: MuJoCo data after a step.
        body_ids: Bodies of the gripper (base and fingers).
        equality_ids: ``connect`` equalities with the gripper base as body1.
        tcp: Tool centre point [m] at which the forces were computed.  # (3,)
        orientation: Gripper orientation [w, x, y, z] then.  # (4,)

    Returns:
        Force [N] and torque [N m] about ``tcp``, world frame.
    """
    force = np.zeros(3)
    torque = np.zeros(3)
    bodies = set(int(b) for b in body_ids)
    eqs = set(int(e) for e in equality_ids)
    rows = np.flatnonzero(data.efc_type[: data.nefc] == mujoco.mjtConstraint.mjCNSTR_EQUALITY)
    anchor = np.empty(3)
    for e in sorted(eqs):
        if not data.eq_active[e]:
            continue
        mine = rows[data.efc_id[rows] == e]
        if len(mine) != 3:
            continue
        f = data.efc_force[mine].copy()  # on body1, world frame
        mujoco.mju_rotVecQuat(anchor, model.eq_data[e, 0:3], orientation)
        force += f
        torque += np.cross(anchor, f)
    local = np.zeros(6)
    frame_force = np.empty(3)
    for i in range(data.ncon):
        c = data.contact[i]
        g1, g2 = int(c.geom[0]), int(c.geom[1])
        on1 = g1 >= 0 and int(model.geom_bodyid[g1]) in bodies
        on2 = g2 >= 0 and int(model.geom_bodyid[g2]) in bodies
        if on1 == on2:
            continue
        mujoco.mj_contactForce(model, data, i, local)
        # force of geom1 on geom2 in the contact frame (rows of c.frame are its axes)
        frame_force[:] = c.frame.reshape(3, 3).T @ local[0:3]
        f = frame_force if on2 else -frame_force
        force += f
        torque += np.cross(c.pos - tcp, f)
    return force, torque
