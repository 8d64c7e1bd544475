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
0                  1.2 % / 5.9 %               0.3-0.6 % / 1.2-2.2 %
20 um, k = 100     19 % / 48 %                 0.3 % / 1.4 %
20 um, k = 1000    95 % / 116 %                0.4 % / 1.3 %
=================  ==========================  ===========================

tautwire keeps the paper's idea, no dependency on the rest length, with the
statistically sound affine model

    |f| = k (l - l_ref) + c,      phi = [l - l_ref, 1],  theta = [k, c],

where c absorbs the unknown rest length (c = k (l_ref - l_rest)) and l_ref is
the first length seen (centring for conditioning). Differencing this model
gives back equ:spring_measurement exactly; fitting it directly uses every
sample's full length excursion instead of one step's. Recursive least squares
with exponential forgetting lambda tracks a slowly changing k or rest length
(memory about 1 / (1 - lambda) accepted samples):

    e = |f| - phi' theta
    K = P phi / (lambda sigma_f^2 + phi' P phi)
    theta = theta + K e
    P = (P - K phi' P) / lambda

P is scaled so that it is the covariance of theta [(N/m)^2, ...] given the
force noise sigma_f; :attr:`ElasticityEstimator.variance` is P[0, 0].

Excitation guard: a sample is used only when the length has moved at least
``min_length_change`` from the last used sample, so P does not wind up and
k is not fitted to noise while the gripper stands still. The output k_hat is
clamped to [k_min, k_max] (default [1, 1e5] N/m): never negative, never NaN.
"""

from __future__ import annotations

import math

from tautwire.errors import InvalidArgumentError


class ElasticityEstimator:
    """Recursive least-squares estimate of an edge's spring constant k [N/m].

    Args:
        force_noise: sigma_f [N], std of the tension measurement.
        forgetting: lambda in (0, 1]; 1 = no forgetting.
        k_initial: Prior k [N/m] before any data.
        k_initial_std: Prior std [N/m] of k (large: the data decide).
        k_range: (k_min, k_max) [N/m] that k_hat is clamped to.
        min_length_change: Least length change [m] since the last used
            sample for a sample to be used (excitation guard).
    """

    def __init__(
        self,
        force_noise: float = 0.05,
        forgetting: float = 0.999,
        k_initial: float = 100.0,
        k_initial_std: float = 1e4,
        k_range: tuple[float, float] = (1.0, 1e5),
        min_length_change: float = 1e-5,
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
        self.force_noise = float(force_noise)
        self.forgetting = float(forgetting)
        self.k_min = k_min
        self.k_max = k_max
        self.min_length_change = float(min_length_change)
        self._r = self.force_noise * self.force_noise
        self._k0 = float(k_initial)
        self._k0_var = float(k_initial_std) ** 2
        self.reset()

    def reset(self) -> None:
        """Forget all data (e.g. after a contact change: a new edge)."""
        self._k = self._k0
        self._c = 0.0
        # P = diag(var_k, var_c); c is unknown until the first sample.
        self._p00 = self._k0_var
        self._p01 = 0.0
        self._p11 = 1e6
        self._l_ref: float | None = None
        self._l_last = 0.0
        self.samples_used = 0

    @property
    def k_hat(self) -> float:
        """Spring constant estimate [N/m], clamped to [k_min, k_max]."""
        k = self._k
        if not math.isfinite(k):
            return self.k_min
        return min(max(k, self.k_min), self.k_max)

    @property
    def variance(self) -> float:
        """Variance [(N/m)^2] of k (P[0, 0])."""
        return self._p00

    @property
    def std(self) -> float:
        """Std [N/m] of k."""
        return math.sqrt(max(self._p00, 0.0))

    @property
    def offset(self) -> float:
        """The offset c [N]: the tension at the reference length l_ref."""
        return self._c

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
        """Fuse one sample (equ:spring_measurement in affine form).

        Args:
            tension: Measured tension [N] (its absolute value is used).
            length: Edge length [m] (e.g. distance from the gripper to the
                contact); only its changes matter.

        Returns:
            k_hat [N/m], clamped to [k_min, k_max].
        """
        f = abs(float(tension))
        l_now = float(length)
        if not (math.isfinite(f) and math.isfinite(l_now)):
            return self.k_hat
        if self._l_ref is None:
            self._l_ref = l_now
        elif abs(l_now - self._l_last) < self.min_length_change:
            return self.k_hat  # excitation guard: no update without motion
        self._l_last = l_now
        lam = self.forgetting
        phi0 = l_now - self._l_ref  # phi = [l - l_ref, 1]
        e = f - (self._k * phi0 + self._c)  # e = |f| - phi' theta
        pphi0 = self._p00 * phi0 + self._p01  # P phi
        pphi1 = self._p01 * phi0 + self._p11
        s = lam * self._r + phi0 * pphi0 + pphi1  # lambda sigma^2 + phi' P phi
        k0 = pphi0 / s  # K = P phi / s
        k1 = pphi1 / s
        self._k += k0 * e  # theta = theta + K e
        self._c += k1 * e
        self._p00 = (self._p00 - k0 * pphi0) / lam  # P = (P - K phi' P) / lambda
        self._p01 = (self._p01 - k0 * pphi1) / lam
        self._p11 = (self._p11 - k1 * pphi1) / lam
        self.samples_used += 1
        return self.k_hat
