import numpy as np
from filterpy.kalman import KalmanFilter

from tautwire.estimation import kalman_predict, kalman_update


def test_pure_functions_equal_filterpy():
    rng = np.random.default_rng(11)
    kf = KalmanFilter(dim_x=3, dim_z=2)
    x = rng.normal(size=3)
    A = rng.normal(size=(3, 3))
    P = A @ A.T + np.eye(3)
    F = np.eye(3) + 0.1 * rng.normal(size=(3, 3))
    Q = 0.01 * np.eye(3)
    kf.x, kf.P, kf.F, kf.Q = x.copy(), P.copy(), F, Q
    for _ in range(10):
        H = rng.normal(size=(2, 3))
        R = np.diag(rng.uniform(0.1, 1.0, 2))
        z = rng.normal(size=2)
        x, P = kalman_predict(x, P, F, Q)
        kf.predict()
        res = kalman_update(x, P, z, H, R)
        kf.update(z, H=H, R=R)
        x, P = res.x, res.P
        np.testing.assert_allclose(x, kf.x.reshape(3), rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(P, kf.P, rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(res.y, kf.y.reshape(2), rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(res.S, kf.S, rtol=1e-12)
        assert res.nis == float(res.y @ np.linalg.inv(res.S) @ res.y)
