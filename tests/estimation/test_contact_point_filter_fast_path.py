"""The float fast path of ContactPointFilter.update against the numpy reference.

``_ReferenceFilter`` is the update, ``_result`` and ``_try_initialise`` as
they were written with numpy arrays before the fast path (kept here verbatim
as the reference): on random sample sequences, both must give the same
estimate, covariance, change indices and NIS to floating-point rounding.
"""

import copy
import math

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tautwire.errors import InvalidArgumentError
from tautwire.estimation import ContactPointFilter, ContactPointUpdate
from tautwire.estimation.force_line import line_offset, line_offset_variance
from tautwire.model.tension import G as GRAVITY_ABS


class _ReferenceFilter(ContactPointFilter):
    """ContactPointFilter with the numpy update (the reference)."""

    def _result(self, changed, nis, used):
        if not self.running:
            return ContactPointUpdate(None, None, None, changed, nis, used)
        P = self.P.copy()
        return ContactPointUpdate(self.x.copy(), P, np.sqrt(np.diag(P)), changed, nis, used)

    def _try_initialise(self):
        if len(self._buffer) < 3:
            return False
        u = np.array([f / np.linalg.norm(f) for _, f, _ in self._buffer])  # (N, 3)
        lam = float(np.linalg.eigvalsh(np.eye(3) - (u.T @ u) / u.shape[0])[0])
        spread = 2.0 * math.asin(math.sqrt(min(max(lam, 0.0), 1.0)))
        if spread < self.init_spread:
            return False
        p = np.array([s[0] for s in self._buffer])
        f = np.array([s[1] for s in self._buffer])
        try:
            res = self.batch(p, f, offset_variances=np.array([s[2] for s in self._buffer]))
        except InvalidArgumentError:
            return False  # lines through one point (the gripper did not move): wait
        # variance of unit weight: unmodelled effects (dynamics, sag, a round
        # peg) show as chi2 above its degrees of freedom and widen P
        # (only when chi2 exceeds dof by more than three of its std)
        dof = max(2 * len(p) - 3, 1)
        significant = res.chi2 > dof + 3.0 * math.sqrt(2.0 * dof)
        P0 = res.covariance * (res.chi2 / dof if significant else 1.0)
        if float(np.max(np.diag(P0))) > self.init_max_std**2:
            return False  # the spread is noise (e.g. a nearly slack cable): wait
        u = f[-1] / np.linalg.norm(f[-1])
        if float(u @ (res.estimate - p[-1])) < self.min_distance:
            return False  # the cable pulls towards its contact: not behind the gripper
        self.x = res.estimate.copy()
        self.P = P0
        self.running = True
        self._buffer.clear()
        return True

    def update(self, p_gripper, f_sens, side=None, torque=None):
        """The numpy update as it was before the float fast path."""
        index = self._count
        self._count += 1
        p = np.array(p_gripper, dtype=float).reshape(3)
        f_raw = np.array(f_sens, dtype=float).reshape(3)
        v_offset = 0.0  # variance [m^2] of the line's offset from p_g
        finite = bool(np.all(np.isfinite(p)) and np.all(np.isfinite(f_raw)))
        if torque is not None and finite:
            tau = np.asarray(torque, dtype=float).reshape(3)
            if np.all(np.isfinite(tau)):
                offset = line_offset(f_raw, tau)
                p = p + offset
                v_offset = line_offset_variance(
                    float(np.linalg.norm(f_raw)),
                    float(np.linalg.norm(offset)),
                    self.force_noise,
                    self.torque_noise,
                )
            else:
                finite = False
        if not finite:
            if self.running:
                self.P += self.Q  # P = F P F' + Q (time passes, nothing measured)
            return self._result(False, None, False)
        fx, fy, fz = f_raw.tolist()
        if self.mass_per_length > 0.0 and self.running:
            # f = f_sens - m_g g with m_g = rho d / 2 (eq:mass, equ:edge_tension)
            fz += 0.5 * self.mass_per_length * self._span(p) * GRAVITY_ABS
        fn = math.sqrt(fx * fx + fy * fy + fz * fz)
        if not self.running:
            if fn >= self.min_tension and math.isfinite(fn):
                self._buffer.append((p, f_raw, v_offset))
                self._try_initialise()
            return self._result(False, None, False)
        if fn < self.min_tension or not math.isfinite(fn):
            self.P += self.Q  # P = F P F' + Q (time passes, nothing measured)
            return self._result(False, None, False)

        # observation model (equ:ls_observation_model), normalised, see contact_observation
        x_, y_, z_ = fx / fn, fy / fn, fz / fn
        sign = 1.0 if z_ >= 0.0 else -1.0
        a = -1.0 / (sign + z_)
        b = x_ * y_ * a
        H = np.array(
            [[1.0 + sign * x_ * x_ * a, sign * b, -sign * x_], [b, sign + y_ * y_ * a, -y_]]
        )
        d = max(self._span(p), self.min_distance)
        r = d * self.force_noise / fn
        r2 = r * r + self.position_noise * self.position_noise + v_offset  # R = r^2 I

        if side is not None and self.radius is not None:
            f_chord = np.array([fx, fy, fz])
            return self._update_round(index, p, f_raw, f_chord, H, r2, side, v_offset)
        P = self.P + self.Q  # P = F P F' + Q  (F = I: x = F x is x)
        y = H @ (p - self.x)  # y = z - H x,  z = H p_g
        PHt = P @ H.T  # (3, 2)
        S = H @ PHt  # S = H P H' + R  (R added on the diagonal below)
        s00 = float(S[0, 0]) + r2
        s01 = float(S[0, 1])
        s11 = float(S[1, 1]) + r2
        det = s00 * s11 - s01 * s01
        y0, y1 = float(y[0]), float(y[1])
        nis = (s11 * y0 * y0 - 2.0 * s01 * y0 * y1 + s00 * y1 * y1) / det  # NIS = y' S^-1 y

        if self.detect_changes:
            test = self.detector.test(index, nis, math.hypot(y0, y1))
            if test.gated:
                self.P = P
                self._recent.append((index, p, f_raw, v_offset))
                if test.changed and test.first_gated is not None:
                    f_chord = np.array([fx, fy, fz])
                    self._restart(test.first_gated, p, f_chord)
                    self.changes.append(index)
                    return self._result(True, nis, True)
                return self._result(False, nis, False)
            self._recent.clear()

        SI = np.array([[s11, -s01], [-s01, s00]]) / det  # S^-1
        K = PHt @ SI  # K = P H' S^-1
        self.x = self.x + K @ y  # x = x + K y
        I_KH = np.eye(3) - K @ H
        self.P = I_KH @ P @ I_KH.T + r2 * (K @ K.T)  # P = (I - K H) P (I - K H)' + K R K'
        return self._result(False, nis, True)


def _sequence(rng, n, torque, nan_rate, weak_rate, switch, rho):
    """Samples of a gripper circling a contact (that moves at n / 2 with ``switch``)."""
    c1 = rng.uniform(-0.3, 0.3, 3)
    c2 = c1 + rng.normal(0.0, 0.06, 3)
    radius = rng.uniform(0.08, 0.4)
    theta0, omega = rng.uniform(0.0, 2.0 * math.pi), rng.uniform(0.01, 0.08)
    height = rng.uniform(-0.5, 0.5)
    tension = rng.uniform(0.5, 8.0)
    rows = []
    for i in range(n):
        c = c2 if switch and i >= n // 2 else c1
        th = theta0 + omega * i
        p = c1 + radius * np.array([math.cos(th), math.sin(th), height])
        u = (c - p) / np.linalg.norm(c - p)
        f = tension * u + rng.normal(0.0, 0.05, 3)
        f[2] -= 0.5 * rho * float(np.linalg.norm(c - p)) * GRAVITY_ABS
        tau = None
        if torque:
            r = rng.normal(0.0, 0.005, 3)  # where the cable leaves the fingers
            tau = np.cross(r, f) + rng.normal(0.0, 0.002, 3)
        if rng.random() < weak_rate:
            f = f * (0.05 / np.linalg.norm(f))
        if rng.random() < nan_rate:
            bad = rng.choice([math.nan, math.inf, -math.inf])
            target = [p, f] if tau is None else [p, f, tau]
            target[rng.integers(len(target))][rng.integers(3)] = bad
        rows.append((p, f, tau))
    return rows


def _close(a, b, rel=1e-12):
    """Equal to ``rel`` relative to the largest magnitude of ``b``."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    scale = max(float(np.max(np.abs(b))), 1e-300)
    return bool(np.all(np.abs(a - b) <= rel * scale))


def _same(fast: ContactPointUpdate, ref: ContactPointUpdate, rel=1e-12, nis_rel=1e-12) -> None:
    assert fast.used == ref.used and fast.changed == ref.changed
    assert (fast.nis is None) == (ref.nis is None)
    if ref.nis is not None:
        assert fast.nis is not None
        assert abs(fast.nis - ref.nis) <= nis_rel * max(abs(ref.nis), 1.0)
    assert (fast.estimate is None) == (ref.estimate is None)
    if ref.estimate is not None:
        assert _close(fast.estimate, ref.estimate, rel)
        assert _close(fast.covariance, ref.covariance, rel)
        assert _close(fast.std, ref.std, rel)


def _as_reference(flt: ContactPointFilter) -> _ReferenceFilter:
    """A copy of a filter's whole state that updates with the numpy reference."""
    ref = copy.deepcopy(flt)
    ref.__class__ = _ReferenceFilter
    return ref


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    seed=st.integers(0, 2**32 - 1),
    n=st.integers(1, 160),
    torque=st.booleans(),
    nan_rate=st.sampled_from([0.0, 0.05, 0.3]),
    weak_rate=st.sampled_from([0.0, 0.05, 0.3]),
    switch=st.booleans(),
    detect_changes=st.booleans(),
    rho=st.sampled_from([0.0, 0.03]),
    edge_length=st.sampled_from([None, 0.25]),
    position_noise=st.sampled_from([0.0, 0.001]),
    init_max_samples=st.sampled_from([3, 7, 250]),
    round_after=st.sampled_from([None, 40]),
)
def test_the_fast_path_agrees_with_the_numpy_reference(
    seed,
    n,
    torque,
    nan_rate,
    weak_rate,
    switch,
    detect_changes,
    rho,
    edge_length,
    position_noise,
    init_max_samples,
    round_after,
):
    rng = np.random.default_rng(seed)
    rows = _sequence(rng, n, torque, nan_rate, weak_rate, switch, rho)
    kwargs = dict(
        force_noise=0.05,
        process_noise=float(rng.choice([0.0, 1e-9, 1e-7])),
        position_noise=position_noise,
        mass_per_length=rho,
        torque_noise=0.002,
        edge_length=edge_length,
        detect_changes=detect_changes,
        init_max_samples=init_max_samples,
    )
    fast, ref = ContactPointFilter(**kwargs), _ReferenceFilter(**kwargs)
    side = None
    for i, (p, f, tau) in enumerate(rows):
        if round_after is not None and i == round_after and ref.running:
            fast.make_round(0.012, 0.003)
            ref.make_round(0.012, 0.003)
            side = np.array([0.0, 0.0, 1.0])
        # one step from the same state: the same equations to rounding
        step = _as_reference(fast)
        r_fast = fast.update(p, f, side=side, torque=tau)
        _same(r_fast, step.update(p, f, side=side, torque=tau))
        assert fast.running == step.running
        if step.running:
            assert _close(fast.x, step.x) and _close(fast.P, step.P)
        assert fast.changes == step.changes
        # the whole sequence from the start: the rounding differences stay
        # rounding (the innovation y ~ 1 mm is a difference of positions
        # ~ 0.3 m, and a restart on three nearly parallel lines amplifies the
        # last bits of x a hundredfold, hence the NIS's looser bound)
        _same(r_fast, ref.update(p, f, side=side, torque=tau), rel=1e-11, nis_rel=1e-9)
    assert fast.changes == ref.changes


def test_changes_are_declared_alike_on_a_moving_contact():
    rng = np.random.default_rng(3)
    rows = _sequence(rng, 400, False, 0.0, 0.0, True, 0.0)
    fast, ref = ContactPointFilter(), _ReferenceFilter()
    for p, f, _ in rows:
        _same(fast.update(p, f), ref.update(p, f))
    assert ref.changes and fast.changes == ref.changes  # the case is not vacuous


def test_the_running_direction_sum_stays_the_buffers_sum():
    rng = np.random.default_rng(5)
    flt = ContactPointFilter(init_max_samples=4, init_spread=3.0)  # never starts
    for _ in range(1000):
        flt.update(rng.normal(size=3), rng.normal(size=3) * 4.0)
        assert not flt.running
        u = np.array([f / np.linalg.norm(f) for _, f, _ in flt._buffer])
        uu = u.T @ u
        expected = [uu[0, 0], uu[0, 1], uu[0, 2], uu[1, 1], uu[1, 2], uu[2, 2]]
        assert np.allclose(flt._uu_sum, expected, rtol=0.0, atol=1e-12)
    flt.reset()
    d = rng.normal(size=3)
    for k in range(3):  # after a reset the sum is that of the new samples only
        flt.update(rng.normal(size=3), d + 1e-3 * k)
    assert len(flt._uu) == len(flt._buffer) == 3
