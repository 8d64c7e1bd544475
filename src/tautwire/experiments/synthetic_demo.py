"""The estimators on a synthetic run with known truth (no simulator needed).

A gripper circles a contact with the cable taut (4 N, 125 samples a circle,
0.05 N force noise); after one and a half circles a second fixture enters the
cable's path and becomes the contact. The contact filter estimates the
contact from (gripper position, force) alone; the elasticity estimator fits
k on stretch data of three cables.
"""

from __future__ import annotations

import json
import math
from dataclasses import asdict, dataclass, field
from pathlib import Path

import numpy as np

from tautwire.estimation import ContactPointFilter, ElasticityEstimator
from tautwire.experiments.synthetic_circle import circle
from tautwire.viz.contact_estimation_plot import plot_contact_estimation

SAMPLES_PER_CIRCLE = 125
CHANGE_AT = 190  # sample at which the second fixture takes over


@dataclass
class ContactRunSummary:
    """Figures of one contact-estimation run (distances in m)."""

    error_half_circle: float
    error_full_circle: float
    change_at: int
    change_declared_after: int | None
    peak_error_after_change: float  # includes the jump itself (the fixtures' distance)
    peak_error_after_declared: float | None  # once the change has been declared
    samples_to_2mm_after_change: int | None
    final_error: float
    within_3_std: float  # fraction of samples (after the first 20) with |e| <= 3 std per axis


@dataclass
class StiffnessCase:
    """Elasticity estimate of one cable after 2 s of stretch motion."""

    stiffness: float
    k_hat: float
    relative_error: float


@dataclass
class SyntheticDemoResult:
    """All figures of the synthetic demo."""

    seed: int
    contact: ContactRunSummary
    stiffness: list[StiffnessCase] = field(default_factory=list)
    plot: str = ""

    def to_json(self) -> str:
        """The result as a JSON document."""
        return json.dumps(asdict(self), indent=2)


def run_contact(seed: int, out_dir: Path | None) -> tuple[ContactRunSummary, str]:
    """Run the contact filter over the synthetic circle with a contact change."""
    n = 3 * SAMPLES_PER_CIRCLE
    data = circle(seed, n=n, samples_per_circle=SAMPLES_PER_CIRCLE, second_contact_at=CHANGE_AT)
    kf = ContactPointFilter(force_noise=0.05)
    est = np.full((n, 3), np.nan)
    std = np.full((n, 3), np.nan)
    for i in range(n):
        r = kf.update(data.p_gripper[i], data.f_sens[i])
        if r.estimate is not None and r.std is not None:
            est[i], std[i] = r.estimate, r.std
    error = est - data.contact
    norm = np.linalg.norm(error, axis=1)
    after = [c - CHANGE_AT for c in kf.changes if c >= CHANGE_AT]
    below = np.nonzero(norm[CHANGE_AT:] <= 0.002)[0]
    settled = [int(b) for b in below if np.all(norm[CHANGE_AT + b : CHANGE_AT + b + 10] <= 0.002)]
    valid = ~np.isnan(std[:, 0])
    valid[:20] = False
    inside = np.all(np.abs(error[valid]) <= 3.0 * std[valid], axis=1)
    summary = ContactRunSummary(
        error_half_circle=float(norm[SAMPLES_PER_CIRCLE // 2 - 1]),
        error_full_circle=float(norm[SAMPLES_PER_CIRCLE - 1]),
        change_at=CHANGE_AT,
        change_declared_after=after[0] if after else None,
        peak_error_after_change=float(np.nanmax(norm[CHANGE_AT:])),
        peak_error_after_declared=(
            float(np.nanmax(norm[CHANGE_AT + after[0] :])) if after else None
        ),
        samples_to_2mm_after_change=settled[0] if settled else None,
        final_error=float(norm[-1]),
        within_3_std=float(np.mean(inside)) if inside.size else math.nan,
    )
    plot = ""
    if out_dir is not None:
        plot = str(
            plot_contact_estimation(
                out_dir / "contact_estimation.png",
                np.arange(n),
                error,
                std,
                changes=[CHANGE_AT],
                title="Synthetic circle, contact change at the dashed line (0.05 N noise)",
            )
        )
    return summary, plot


def run_stiffness(seed: int) -> list[StiffnessCase]:
    """Fit k for cables of 10, 100 and 1000 N/m from 2 s of stretch at 250 Hz."""
    rng = np.random.default_rng(seed)
    cases = []
    t = np.arange(500) / 250.0
    for k in (10.0, 100.0, 1000.0):
        length = 0.3 + (0.75 / k) * np.sin(2 * np.pi * 0.5 * t + rng.uniform(0, 2 * np.pi))
        tension = 3.0 + k * (length - 0.3) + rng.normal(0.0, 0.05, t.size)
        est = ElasticityEstimator(force_noise=0.05, k_initial=k / 10.0)
        for f, l_ in zip(tension, length, strict=True):
            est.update(float(f), float(l_))
        cases.append(StiffnessCase(k, est.k_hat, est.k_hat / k - 1.0))
    return cases


def run_synthetic_demo(seed: int = 0, out_dir: str | Path | None = None) -> SyntheticDemoResult:
    """Run both parts; write the plot and ``result.json`` under ``out_dir``."""
    out = Path(out_dir) if out_dir is not None else None
    contact, plot = run_contact(seed, out)
    result = SyntheticDemoResult(seed, contact, run_stiffness(seed), plot)
    if out is not None:
        out.mkdir(parents=True, exist_ok=True)
        (out / "result.json").write_text(result.to_json() + "\n")
    return result
