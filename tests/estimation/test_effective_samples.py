import numpy as np

from tautwire.estimation.effective_samples import effective_samples, mean_covariance


def test_white_noise_counts_every_sample() -> None:
    r = np.random.default_rng(0).normal(size=4000)
    assert 0.9 * 4000 < effective_samples(r) <= 4000


def test_ar1_noise_counts_fewer() -> None:
    rng = np.random.default_rng(1)
    rho, n = 0.8, 20000
    r = np.zeros(n)
    for i in range(1, n):
        r[i] = rho * r[i - 1] + rng.normal()
    expected = n * (1 - rho) / (1 + rho)
    assert 0.8 * expected < effective_samples(r) < 1.2 * expected


def test_degenerate_residuals_count_one() -> None:
    assert effective_samples(np.zeros(10)) == 1.0
    assert effective_samples(np.array([1.0, 2.0])) == 1.0


def test_mean_covariance_is_honest_for_correlated_samples() -> None:
    """Over seeded AR(1) runs the mean's error is within 3 std in >= 90 % per axis."""
    rng = np.random.default_rng(2)
    within = 0
    runs = 200
    for _ in range(runs):
        x = np.zeros((300, 3))
        for i in range(1, 300):
            x[i] = 0.7 * x[i - 1] + rng.normal(scale=0.1, size=3)
        mean, cov = mean_covariance(x + np.array([1.0, 2.0, 3.0]))
        err = mean - np.array([1.0, 2.0, 3.0])
        within += int(np.all(np.abs(err) <= 3.0 * np.sqrt(np.diag(cov))))
    assert within >= 0.9 * runs
