import numpy as np
import pytest

from tautwire.primitives.low_pass import LowPass


def test_first_sample_then_first_order_steps() -> None:
    f: LowPass[float] = LowPass(0.048)
    assert f.update(0.0, 2.0) == 2.0
    assert f.update(0.004, 14.0) == pytest.approx(2.0 + 12.0 / 12.0)


def test_vectors_and_long_gaps() -> None:
    f: LowPass[np.ndarray] = LowPass(0.1)
    f.update(0.0, np.zeros(3))
    assert np.allclose(f.update(5.0, np.ones(3)), 1.0)  # alpha is at most 1
    f.reset()
    assert f.value is None
