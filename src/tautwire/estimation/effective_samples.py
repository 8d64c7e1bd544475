"""How much correlated samples are worth: the effective number and a mean's covariance."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

FloatArray = NDArray[np.float64]


def effective_samples(r: FloatArray) -> float:
    """How many independent samples the residuals ``r`` (n,) are worth (lag-1 correlation).

    Neighbouring samples err together (the tension's swing, the cable's
    wobble): for an AR(1) sequence of correlation rho, n (1 - rho) / (1 + rho).
    """
    n = len(r)
    rr = float(r @ r)
    if n < 3 or rr <= 0.0:
        return 1.0
    rho = min(max(float(r[1:] @ r[:-1]) / rr, 0.0), 0.999)
    return max(1.0, n * (1.0 - rho) / (1.0 + rho))


def mean_covariance(samples: ArrayLike) -> tuple[FloatArray, FloatArray]:
    """The mean of ``samples`` (n, 3) and its covariance, by each axis's effective samples."""
    x = np.asarray(samples, dtype=float)
    mean: FloatArray = x.mean(axis=0)
    r = x - mean
    scatter = (r.T @ r) / max(len(x) - 1, 1)
    scale = 1.0 / np.sqrt([effective_samples(r[:, i]) for i in range(x.shape[1])])
    cov: FloatArray = scatter * np.outer(scale, scale)
    return mean, cov
