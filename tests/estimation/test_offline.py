import numpy as np

from tautwire.estimation import estimate_force_log, read_force_log, write_force_log
from tautwire.experiments.synthetic_circle import CONTACT, circle


def breathing_circle(k, seed, n=500):
    """Gripper circles the contact while the radius swings, tension by Hooke's law."""
    rng = np.random.default_rng(seed)
    i = np.arange(n)
    theta = 2 * np.pi * i / 125
    radius = 0.2 + (0.75 / k) * np.sin(2 * np.pi * i / 250)
    p = CONTACT + radius[:, None] * np.stack([np.cos(theta), np.sin(theta), 0 * theta], axis=1)
    tension = 3.0 + k * (radius - 0.2)
    f = tension[:, None] * (CONTACT - p) / radius[:, None] + rng.normal(0, 0.05, (n, 3))
    return i / 250.0, p, f


def test_offline_contact_changes_and_history(tmp_path):
    d = circle(0, n=260, second_contact_at=190)
    t = np.arange(260) / 250.0
    path = tmp_path / "log.csv"
    write_force_log(path, t, d.p_gripper, d.f_sens)
    res = estimate_force_log(read_force_log(path))
    assert len(res.history) == 260
    assert res.history[0].contact is None and res.history[0].std is None
    assert [h.t for h in res.history] == list(t)
    assert len(res.changes) == 1 and 190 <= res.changes[0] <= 195
    assert np.linalg.norm(res.contact - d.contact[-1]) < 2e-3
    assert res.covariance.shape == (3, 3)
    # a circle at constant tension and radius does not excite the stiffness
    assert res.stiffness is None


def test_offline_stiffness_from_a_breathing_circle(tmp_path):
    # k = 1000 N/m swings the length by only 0.75 mm, comparable to the contact
    # error; the length error then biases k (measured about -23 %, see the report)
    for k in (10.0, 100.0):
        t, p, f = breathing_circle(k, seed=int(k))
        path = tmp_path / f"k{int(k)}.csv"
        write_force_log(path, t, p, f)
        res = estimate_force_log(read_force_log(path))
        assert res.changes == []
        assert np.linalg.norm(res.contact - CONTACT) < 1e-3
        assert res.stiffness is not None
        assert abs(res.stiffness / k - 1.0) <= 0.05


def test_offline_uses_the_logged_torques(tmp_path):
    # the cable leaves the fingers 20 mm to the side of the logged gripper point
    rng = np.random.default_rng(7)
    n = 200
    theta = np.linspace(0.0, np.pi, n)
    p = CONTACT + 0.25 * np.stack([np.cos(theta), np.sin(theta), 0 * theta], axis=1)
    towards = (CONTACT - p) / np.linalg.norm(CONTACT - p, axis=1)[:, None]
    exit_point = p + 0.02 * np.cross([0.0, 0.0, 1.0], towards)
    chord = CONTACT - exit_point
    f = 3.0 * chord / np.linalg.norm(chord, axis=1)[:, None]
    tau = np.cross(exit_point - p, f) + rng.normal(0, 0.002, (n, 3))
    f = f + rng.normal(0, 0.05, (n, 3))
    t = np.arange(n) / 250.0
    q = np.tile([1.0, 0.0, 0.0, 0.0], (n, 1))
    with_torque = tmp_path / "with.csv"
    without = tmp_path / "without.csv"
    write_force_log(with_torque, t, p, f, q, tau)
    write_force_log(without, t, p, f)
    good = estimate_force_log(read_force_log(with_torque))
    biased = estimate_force_log(read_force_log(without))
    assert np.linalg.norm(good.contact - CONTACT) < 2e-3
    assert np.linalg.norm(biased.contact - CONTACT) > 1e-2
