import numpy as np

from tautwire.primitives.tension_judge import TensionJudge


def test_held_only_after_hold_time_within_band() -> None:
    rng = np.random.default_rng(0)
    judge = TensionJudge(2.0, 0.1, 0.5)
    held = [judge.update(0.004 * k, 2.0 + 0.05 * rng.standard_normal()) for k in range(200)]
    assert not any(held[:120]) and held[-1]


def test_not_held_off_the_set_point() -> None:
    judge = TensionJudge(2.0, 0.1, 0.5)
    assert not any(judge.update(0.004 * k, 2.5) for k in range(500))
