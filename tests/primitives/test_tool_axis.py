import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from tautwire.model.quaternion import orientation_along, rotate, turn_x_onto_line
from tautwire.primitives.tool_axis import ToolAxis

angles = st.floats(-np.pi, np.pi)


@settings(max_examples=200, deadline=None)
@given(angles, angles)
def test_turn_onto_line_never_turns_more_than_a_quarter(yaw, cable_yaw):
    q = orientation_along([np.cos(yaw), np.sin(yaw), 0.0])
    d = np.array([np.cos(cable_yaw), np.sin(cable_yaw), 0.0])
    q2 = turn_x_onto_line(q, d)
    x2 = rotate(q2, [1.0, 0.0, 0.0])
    assert abs(abs(x2 @ d) - 1.0) < 1e-9  # x lies on the line
    x = rotate(q, [1.0, 0.0, 0.0])
    assert x @ x2 >= -1e-9  # at most 90 deg of turn
    z2 = rotate(q2, [0.0, 0.0, 1.0])
    assert z2[2] > 1.0 - 1e-9  # a yaw: the fingers stay upright


@settings(max_examples=200, deadline=None)
@given(angles, angles)
def test_tool_axis_sign_is_decided_once_and_aligns_that_axis(yaw, cable_yaw):
    q = orientation_along([np.cos(yaw), np.sin(yaw), 0.0])
    d = np.array([np.cos(cable_yaw), np.sin(cable_yaw), 0.0])
    axis = ToolAxis()
    s = axis.decide(q, d)
    x = rotate(q, [1.0, 0.0, 0.0])
    assert s * (x @ d) >= 0.0
    q2 = axis.target(q, d)
    np.testing.assert_allclose(s * rotate(q2, [1.0, 0.0, 0.0]), d, atol=1e-9)
    assert axis.angle(q2, d) < 1e-6
    assert axis.decide(q2, -d) == s  # sticky
