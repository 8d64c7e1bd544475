"""The offline estimate's history as arrays, read as per-row entries."""

import numpy as np
import pytest

from tautwire.estimation import (
    ContactPointFilter,
    ElasticityEstimator,
    compensate_weight,
    estimate_force_log,
)
from tautwire.estimation.force_log import ForceLog
from tautwire.estimation.offline import STIFFNESS_RELATIVE_STD, ContactHistory
from tautwire.experiments.synthetic_circle import CONTACT, circle


def _log(n=400, seed=0, torque=False):
    d = circle(seed, n=n, second_contact_at=n * 2 // 3)
    tau = np.random.default_rng(seed).normal(0.0, 0.002, (n, 3)) if torque else None
    return ForceLog("", np.arange(n) / 250.0, d.p_gripper, d.f_sens, torque=tau)


@pytest.mark.parametrize("torque", [False, True])
def test_each_entry_is_the_filters_state_after_its_row(torque):
    log = _log(torque=torque)
    res = estimate_force_log(log, mass_per_length=0.03)
    flt = ContactPointFilter(force_noise=0.05, mass_per_length=0.03, torque_noise=0.002)
    taus = log.torque if log.torque is not None else [None] * len(log)
    assert len(res.history) == len(log)
    for i, (p, f, tau) in enumerate(zip(log.p_gripper, log.f_sens, taus, strict=True)):
        r = flt.update(p, f, torque=tau)
        h = res.history[i]
        assert h.t == log.t[i]
        if r.estimate is None:
            assert h.contact is None and h.std is None
        else:
            assert np.array_equal(h.contact, r.estimate) and np.array_equal(h.std, r.std)
    assert res.changes == flt.changes and res.changes
    assert np.array_equal(res.contact, flt.estimate)


def test_the_history_reads_as_a_sequence_of_copies():
    res = estimate_force_log(_log())
    h = res.history
    entries = list(h)
    assert len(entries) == len(h) == 400
    assert entries[0].contact is None  # before the directions spread
    assert h[-1].t == entries[-1].t and np.array_equal(h[-1].contact, entries[-1].contact)
    assert [e.t for e in h[10:20:3]] == [entries[i].t for i in range(10, 20, 3)]
    with pytest.raises(IndexError):
        h[400]
    with pytest.raises(IndexError):
        h[-401]
    h[-1].contact[:] = 0.0  # an entry is a copy: the history does not change
    assert np.array_equal(h[-1].contact, entries[-1].contact)
    assert isinstance(h, ContactHistory) and h.contact.shape == (400, 3)
    with pytest.raises(ValueError):
        ContactHistory(h.t, h.contact[:-1], h.std, h.known)


def test_the_stiffness_is_that_of_the_weight_compensated_rows():
    # a breathing circle (k = 50 N/m) with a 30 g/m cable: the per-row
    # compensation (compensate_weight) and the vectorised one agree
    rng = np.random.default_rng(4)
    n, k = 600, 50.0
    i = np.arange(n)
    theta = 2 * np.pi * i / 125
    radius = 0.2 + (0.75 / k) * np.sin(2 * np.pi * i / 250)
    p = CONTACT + radius[:, None] * np.stack([np.cos(theta), np.sin(theta), 0 * theta], axis=1)
    tension = 3.0 + k * (radius - 0.2)
    f = tension[:, None] * (CONTACT - p) / radius[:, None] + rng.normal(0, 0.05, (n, 3))
    f[:, 2] -= 0.5 * 0.03 * radius * 9.81
    res = estimate_force_log(ForceLog("", i / 250.0, p, f), mass_per_length=0.03)
    assert res.changes == [] and res.stiffness is not None
    est = ElasticityEstimator(force_noise=0.05)
    for pp, ff in zip(p, f, strict=True):
        length = float(np.linalg.norm(pp - res.history[-1].contact))
        est.update(float(np.linalg.norm(compensate_weight(ff, length, 0.03))), length)
    assert est.is_ready(STIFFNESS_RELATIVE_STD)
    assert res.stiffness == pytest.approx(est.k_hat, rel=1e-9)
    assert abs(res.stiffness / k - 1.0) < 0.1
