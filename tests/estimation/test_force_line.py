import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tautwire.errors import InvalidArgumentError
from tautwire.estimation import ContactPointFilter, contact_point_least_squares
from tautwire.estimation.force_line import line_offset, line_offset_variance, line_point

vectors = st.lists(st.floats(-1.0, 1.0), min_size=3, max_size=3).map(np.array)


@settings(max_examples=200, deadline=None)
@given(vectors, vectors, st.floats(-0.5, 0.5))
def test_offset_is_the_lines_point_nearest_the_tcp(r, f, lam):
    if np.linalg.norm(f) < 1e-3:
        return
    point = r + lam * f  # any point on the line of action
    tau = np.cross(point, f)  # torque about the tcp (origin)
    o = line_offset(f, tau)
    expected = r - f * (f @ r) / (f @ f)  # r minus its part along f
    np.testing.assert_allclose(o, expected, atol=1e-9)
    assert abs(o @ f) < 1e-9


def test_without_torque_the_line_runs_through_the_tcp():
    p = np.array([0.1, 0.2, 0.3])
    np.testing.assert_array_equal(line_point(p, [1.0, 0.0, 0.0], None), p)
    np.testing.assert_array_equal(line_offset([0.0, 0.0, 0.0], [1.0, 2.0, 3.0]), np.zeros(3))
    np.testing.assert_array_equal(line_offset([np.nan, 0.0, 0.0], [1.0, 2.0, 3.0]), np.zeros(3))


def test_offset_variance():
    assert line_offset_variance(2.0, 0.0, 0.05, 0.002) == pytest.approx((0.002 / 2.0) ** 2)
    assert line_offset_variance(2.0, 0.02, 0.05, 0.0) == pytest.approx((0.02 * 0.05 / 2.0) ** 2)
    assert line_offset_variance(0.0, 0.02, 0.05, 0.002) == 0.0


def _exit_offset_samples(rng, n=60, exit_offset=0.02, noise_f=0.05, noise_tau=0.002):
    """A cable that leaves the fingers 20 mm from the tcp, taut to a contact.

    The gripper circles the contact at 0.3 m; its tool x-axis points towards
    the contact and the cable leaves the fingertip at tcp + exit_offset along
    the tool y-axis: the force line misses the tcp by about that much.
    """
    contact = np.array([0.3, 0.0, 0.08])
    p, f, tau = [], [], []
    for a in np.linspace(0.0, np.pi, n):
        tcp = contact + 0.3 * np.array([np.cos(a), np.sin(a), 0.0])
        towards = (contact - tcp) / np.linalg.norm(contact - tcp)
        side = np.cross([0.0, 0.0, 1.0], towards)
        exit_point = tcp + exit_offset * side
        force = 3.0 * (contact - exit_point) / np.linalg.norm(contact - exit_point)
        torque = np.cross(exit_point - tcp, force)
        p.append(tcp)
        f.append(force + noise_f * rng.standard_normal(3))
        tau.append(torque + noise_tau * rng.standard_normal(3))
    return contact, np.array(p), np.array(f), np.array(tau)


def test_whole_wrench_line_removes_the_exit_offset_bias():
    errors_tcp, errors_wrench = [], []
    for seed in range(10):
        contact, p, f, tau = _exit_offset_samples(np.random.default_rng(seed))
        tcp = contact_point_least_squares(p, f, force_noise=0.05)
        wrench = contact_point_least_squares(
            p, f, force_noise=0.05, torques=tau, torque_noise=0.002
        )
        errors_tcp.append(np.linalg.norm(tcp.estimate - contact))
        errors_wrench.append(np.linalg.norm(wrench.estimate - contact))
    assert np.median(errors_tcp) > 0.015  # tcp lines are tangent to a 20 mm circle
    assert np.median(errors_wrench) < 0.002


def test_filter_with_torques_finds_the_contact_and_is_consistent():
    inside = 0
    total = 0
    for seed in range(10):
        contact, p, f, tau = _exit_offset_samples(np.random.default_rng(seed), n=120)
        kf = ContactPointFilter(force_noise=0.05, torque_noise=0.002)
        kf_tcp = ContactPointFilter(force_noise=0.05)
        for j in range(len(p)):
            r = kf.update(p[j], f[j], torque=tau[j])
            kf_tcp.update(p[j], f[j])
            if r.estimate is not None and j > 60:
                total += 3
                inside += int(np.sum(np.abs(r.estimate - contact) <= 3.0 * r.std))
        assert np.linalg.norm(kf.x - contact) < 0.002
        assert np.linalg.norm(kf_tcp.x - contact) > 0.01
    assert inside / total >= 0.9


def test_static_gripper_is_refused_without_a_prior():
    rng = np.random.default_rng(0)
    p = np.tile([0.3, 0.3, 0.1], (50, 1))
    f = np.array([0.0, -3.0, 0.0]) + 0.05 * rng.standard_normal((50, 3))
    with pytest.raises(InvalidArgumentError, match="hardly moved"):
        contact_point_least_squares(p, f)
    res = contact_point_least_squares(
        p, f, prior_mean=[0.3, 0.0, 0.1], prior_covariance=0.01**2 * np.eye(3)
    )
    assert np.isfinite(res.estimate).all()


def test_static_gripper_never_starts_the_filter():
    rng = np.random.default_rng(1)
    kf = ContactPointFilter(force_noise=0.05)
    for _ in range(300):
        kf.update([0.3, 0.3, 0.1], np.array([0.0, -0.5, 0.0]) + 0.2 * rng.standard_normal(3))
    assert kf.estimate is None


def test_nan_position_does_not_poison_the_filter():
    contact, p, f, _ = _exit_offset_samples(np.random.default_rng(3), n=80, exit_offset=0.0)
    kf = ContactPointFilter(force_noise=0.05)
    for j in range(len(p)):
        if j in (30, 50):
            res = kf.update([np.nan, 0.0, 0.0], f[j])
            assert not res.used
            kf.update(p[j], [np.inf, 0.0, 0.0])
            kf.update(p[j], f[j], torque=[np.nan, 0.0, 0.0])
        kf.update(p[j], f[j])
    assert np.all(np.isfinite(kf.x)) and np.all(np.isfinite(kf.P))
    assert np.linalg.norm(kf.x - contact) < 0.003
