"""Which estimates the model trusts (primitives/model_estimator.py, trust_limit)."""

from __future__ import annotations

import numpy as np
import pytest

from tautwire.estimation.contact_point_filter import FilterState
from tautwire.primitives.model_estimator import (
    CONTACT_TOLERANCE,
    POINT_TRUST_FRACTION,
    SYSTEMATIC_LINE_ERROR,
    TRUST_FRACTION,
)
from tests.primitives.conftest import CONTACT, context


def _state(std: float) -> FilterState:
    return FilterState(True, CONTACT.copy(), std**2 * np.eye(3), None, np.zeros(3), 0.0)


def test_a_point_is_trusted_on_the_std_it_reports() -> None:
    est = context().estimator
    est._track(0)  # the filter estimates A1, a point contact
    limit = est.trust_limit()
    assert limit == pytest.approx(POINT_TRUST_FRACTION * CONTACT_TOLERANCE)
    # the filter's std plus the line model's systematic error, against half the tolerance
    inside = np.sqrt(limit**2 - SYSTEMATIC_LINE_ERROR**2)
    assert est._trusted_variance(_state(0.99 * inside))
    # robustness trial 130: 1.3 mm of filter std, 1.65 mm reported, 3.5 mm off: not trusted
    assert not est._trusted_variance(_state(1.31e-3))
    assert not est._trusted_variance(_state(1.01 * inside))


def test_a_peg_keeps_its_own_fraction_of_its_wider_tolerance() -> None:
    est = context(round_fixtures={"A1": (CONTACT, 0.0085)}).estimator
    est._track(0)
    tolerance = CONTACT_TOLERANCE + 0.0085 - 0.003
    assert est.trust_limit() == pytest.approx(min(est.trusted_std, TRUST_FRACTION * tolerance))
