"""Edge elasticity k by recursive least squares (equ:Hookes_law, equ:spring_measurement).

The paper fits k from per-step differences, |f|(t) - |f|(t-1) = k [dl(t) - dl(t-1)]
(equ:spring_measurement), so that the unknown rest length drops out. With an
exactly known length this works better than its per-step signal-to-noise
ratio suggests (the differenced noise telescopes), but the per-step length
change at 250 Hz is only micrometres, so any noise on the length (e.g. from a
jittering contact estimate) swamps the regressor and biases k towards 0.
Measured over 50 seeds, 2 s of a 0.5 Hz stretch swinging the tension by
1.5 N, sigma_f = 0.05 N (median / max relative error of k):

=================  ==========================  ===========================
length noise       differences, RLS (0.999)    affine RLS (this class)
=================  ==========================  ===========================
0                  1.2 % / 5.9 %               0.3 % / 1.3 %
20 um, k = 100     19 % / 48 %                 0.3 % / 1.3 %
20 um, k = 1000    95 % / 116 %                0.4 % / 1.2 %
=================  ==========================  ===========================

tautwire keeps the paper's idea, no dependency on the rest length, with the
statistically sound affine model, plus a slow drift:

    |f| = k (l - l_ref) + c + d (t - t_ref),
    phi = [l - l_ref, 1, t - t_ref],  theta = [k, c, d],

where c absorbs the unknown rest length (c = k (l_ref - l_rest)), l_ref is
the first length seen (centring for conditioning) and d [N per window] a
drift of the tension at constant length. Differencing the model without
drift gives back equ:spring_measurement exactly; fitting it directly uses
every sample's full length excursion instead of one step's.

Drift. Whatever changes the tension-length relation slowly, and not with
the excitation, biases a fit without it: a cable still creeping round a
peg after it was pulled taut (its length grows while the tension swings
about a constant mean), a sag still settling, a sensor bias drifting. In
primitive D on a 0.61 m, 678 N/m cable round a peg (the bench's seed 109),
the chord crept 2 mm in the first 2.5 s of the swing: the fit without
drift read 299 N/m where the simulated world presented 618 N/m. t_ref
moves to each fused window (c absorbs d times the step), so phi's third
entry is always 0 and the drift enters only through P; time counts
windows, used or skipped.

Window means. The fit sees the mean tension and length of every ``window``
samples (default 50: 0.2 s at the 250 Hz control rate), not each sample. A
real (or simulated) taut cable vibrates across its chord at several Hz, so
the chord length carries tens of micrometres of "noise" that is as large as
the length changes a stiff cable makes when the tension swings by 0.1 N;
noise on the regressor biases a least-squares k low (regression dilution).
The window mean keeps the slow length changes that carry k and averages the
vibration out (at 6 Hz a 0.2 s mean passes 16 % of it). Measured over 50
seeds, k = 1000 N/m, 4 s of a 0.5 Hz stretch swinging the tension by 0.2 N,
sigma_f = 0.05 N, a 6 Hz vibration of 30 um on the length: mean error of k
-3.8 % (median |error| 3.6 %, max 13.5 %) fitting each sample (forgetting
0.999), +0.3 % (2.0 %, 7.6 %) fitting 50-sample means. In the simulation of
Fig. 5a (primitive D's excited set point, the sag-corrected length), seeds
0-2, the 1000 N/m cable's k_hat after 6 s was 390-470 N/m fitting each
sample and 1010-1060 N/m fitting window means.

Recursive least squares with exponential forgetting lambda per window
tracks a slowly changing k or rest length (memory about 1 / (1 - lambda)
accepted windows: 20, i.e. 4 s, by default):

    theta = T theta,  P = T P T'     (t_ref to the new window, T = I + Dt e_c e_d')
    e = |f| - phi' theta
    K = P phi / (lambda sigma_f^2 / window + phi' P phi)
    theta = theta + K e
    P = (P - K phi' P) / lambda

P is scaled so that it is the covariance of theta [(N/m)^2, ...] given the
force noise sigma_f of a sample; :attr:`ElasticityEstimator.variance` is
P[0, 0].

Excitation guard: a window is used only when its mean length has moved at
least ``min_length_change`` from the last used window's, so P does not wind
up and k is not fitted to noise while the gripper stands still. The output
k_hat is clamped to [k_min, k_max] (default [1, 1e5] N/m): never negative,
never NaN.
"""

from __future__ import annotations

import math

import numpy as np

from tautwire.errors import InvalidArgumentError

#: Relative std of k below which k_hat becomes :attr:`ElasticityEstimator.k_trusted`.
TRUSTED_RELATIVE_STD = 0.2


class ElasticityEstimator:
    """Recursive least-squares estimate of an edge's spring constant k [N/m].

    Args:
        force_noise: sigma_f [N], std of the tension measurement.
        forgetting: lambda in (0, 1] per window; 1 = no forgetting.
        k_initial: Prior k [N/m] before any data.
        k_initial_std: Prior std [N/m] of k (large: the data decide).
        k_range: (k_min, k_max) [N/m] that k_hat is clamped to.
        min_length_change: Least change [m] of the mean length since the
            last used window for a window to be used (excitation guard).
        window: Number of samples whose mean tension and length make one
            least-squares sample, >= 1.
        drift: Whether to fit the drift d (else d = 0: the affine model).
    """

    def __init__(
        self,
        force_noise: float = 0.05,
        forgetting: float = 0.95,
        k_initial: float = 100.0,
        k_initial_std: float = 1e4,
        k_range: tuple[float, float] = (1.0, 1e5),
        min_length_change: float = 1e-5,
        window: int = 50,
        drift: bool = True,
    ) -> None:
        k_min, k_max = (float(v) for v in k_range)
        if not (force_noise > 0.0 and math.isfinite(force_noise)):
            raise InvalidArgumentError(f"force_noise must be > 0 N, got {force_noise}")
        if not 0.0 < forgetting <= 1.0:
            raise InvalidArgumentError(f"forgetting must be in (0, 1], got {forgetting}")
        if not (0.0 < k_min < k_max and math.isfinite(k_max)):
            raise InvalidArgumentError(
                f"k_range must be (k_min, k_max) with 0 < k_min < k_max < inf N/m, got {k_range}"
            )
        if not (k_initial_std > 0.0 and math.isfinite(k_initial_std)):
            raise InvalidArgumentError(f"k_initial_std must be > 0 N/m, got {k_initial_std}")
        if not math.isfinite(k_initial):
            raise InvalidArgumentError(f"k_initial must be finite, got {k_initial}")
        if min_length_change < 0.0 or not math.isfinite(min_length_change):
            raise InvalidArgumentError(f"min_length_change must be >= 0 m, got {min_length_change}")
        if isinstance(window, bool) or not isinstance(window, int) or window < 1:
            raise InvalidArgumentError(f"window must be an integer >= 1 sample, got {window!r}")
        self.force_noise = float(force_noise)
        self.forgetting = float(forgetting)
        self.k_min = k_min
        self.k_max = k_max
        self.min_length_change = float(min_length_change)
        self.window = window
        self.drift = bool(drift)
        self._r = self.force_noise * self.force_noise / window  # noise of a window's mean
        self._k0 = float(k_initial)
        self._k0_var = float(k_initial_std) ** 2
        self.reset()

    def reset(self, k_initial: float | None = None) -> None:
        """Forget all data, including a partial window (e.g. after a contact change: a new edge).

        Args:
            k_initial: New prior k [N/m] (clamped to [k_min, k_max]), e.g.
                the old estimate rescaled for an edge of another length;
                None keeps the prior.
        """
        if k_initial is not None:
            if not math.isfinite(k_initial):
                raise InvalidArgumentError(f"k_initial must be finite, got {k_initial}")
            self._k0 = min(max(float(k_initial), self.k_min), self.k_max)
        self._theta = np.array([self._k0, 0.0, 0.0])  # [k, c, d]
        # P = diag(var_k, var_c, var_d); c and d are unknown until the data come
        self._P = np.diag([self._k0_var, 1e6, 1e2 if self.drift else 0.0])
        self._l_ref: float | None = None
        self._l_last = 0.0
        self._gap = 0  # windows since the last fused one
        self._sum_f = 0.0
        self._sum_l = 0.0
        self._m = 0
        self.samples_used = 0
        self._k_trusted = self._k0

    @property
    def _k(self) -> float:
        return float(self._theta[0])

    @property
    def k_hat(self) -> float:
        """Spring constant estimate [N/m], clamped to [k_min, k_max]."""
        k = self._k
        if not math.isfinite(k):
            return self.k_min
        return min(max(k, self.k_min), self.k_max)

    @property
    def k_trusted(self) -> float:
        """Stiffness [N/m] for a force controller's gain lambda / k.

        k_hat once it is known to ``TRUSTED_RELATIVE_STD``; before that, the
        larger of k_hat and the latest such value (at first the prior). A fit
        that has not converged (a stiff cable barely changes length under
        the sensor's noise) can read anything from k_min up: a gain
        lambda / k_min made the controller chatter at the speed limit, while
        too large a k only makes it slower. So the gain errs on the slow side.
        """
        # once ready, the fit stored k_hat here: the max is k_hat itself
        return max(self._k_trusted, self.k_hat)

    @property
    def variance(self) -> float:
        """Variance [(N/m)^2] of k (P[0, 0])."""
        return float(self._P[0, 0])

    @property
    def std(self) -> float:
        """Std [N/m] of k."""
        return math.sqrt(max(self.variance, 0.0))

    @property
    def offset(self) -> float:
        """The offset c [N]: the tension at the reference length l_ref, now."""
        return float(self._theta[1])

    @property
    def drift_rate(self) -> float:
        """The drift d [N per window] of the tension at constant length."""
        return float(self._theta[2])

    @property
    def clamped(self) -> bool:
        """True when the fitted k lies outside [k_min, k_max] (k_hat is the bound)."""
        return not (self.k_min <= self._k <= self.k_max)

    def is_ready(self, max_relative_std: float = 0.1) -> bool:
        """True once k is known to ``max_relative_std`` of k_hat and is not clamped.

        A fit outside [k_min, k_max] (e.g. the length changed while the
        tension did not) is not a stiffness, however small its variance.
        """
        return (
            self.samples_used >= 3
            and not self.clamped
            and self.std <= max_relative_std * self.k_hat
        )

    def update(self, tension: float, length: float) -> float:
        """Add one sample; every ``window`` samples, fuse their mean (equ:spring_measurement).

        Args:
            tension: Measured tension [N] (its absolute value is used).
            length: Edge length [m] (e.g. distance from the gripper to the
                contact); only its changes matter.

        Returns:
            k_hat [N/m], clamped to [k_min, k_max].
        """
        f = abs(float(tension))
        length = float(length)
        if not (math.isfinite(f) and math.isfinite(length)):
            return self.k_hat
        self._sum_f += f
        self._sum_l += length
        self._m += 1
        if self._m < self.window:
            return self.k_hat
        f, l_now = self._sum_f / self._m, self._sum_l / self._m
        self._sum_f = self._sum_l = 0.0
        self._m = 0
        return self._fuse(f, l_now)

    def _fuse(self, f: float, l_now: float) -> float:
        """One recursive least-squares step with a window's mean tension [N] and length [m]."""
        self._gap += 1
        if self._l_ref is None:
            self._l_ref = l_now
        elif abs(l_now - self._l_last) < self.min_length_change:
            return self.k_hat  # excitation guard: no update without motion
        self._l_last = l_now
        theta, P = self._theta, self._P
        if self.drift:
            # t_ref to this window: c += d dt, P = T P T' (T = I + dt e_c e_d')
            dt = float(self._gap)
            theta[1] += dt * theta[2]
            P[1, :] += dt * P[2, :]
            P[:, 1] += dt * P[:, 2]
        self._gap = 0
        lam = self.forgetting
        phi = np.array([l_now - self._l_ref, 1.0, 0.0])  # phi = [l - l_ref, 1, t - t_ref]
        e = f - float(phi @ theta)  # e = |f| - phi' theta
        p_phi = P @ phi  # P phi
        s = lam * self._r + float(phi @ p_phi)  # lambda sigma^2 + phi' P phi
        gain = p_phi / s  # K = P phi / s
        theta += gain * e  # theta = theta + K e
        P -= np.outer(gain, p_phi)  # P = (P - K phi' P) / lambda
        P /= lam
        self._P = 0.5 * (P + P.T)  # keep it symmetric
        self.samples_used += 1
        if self.is_ready(TRUSTED_RELATIVE_STD):
            self._k_trusted = self.k_hat
        return self.k_hat
