"""Seeded synthetic force data with known truth: a gripper circling a contact."""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numpy.typing import NDArray

from tautwire.model.tension import GRAVITY

FloatArray = NDArray[np.float64]

CONTACT = np.array([0.5, 0.1, 0.2])


class CircleData(NamedTuple):
    """Gripper positions [m], measured forces [N] and true contacts [m], one row a sample."""

    p_gripper: FloatArray  # (N, 3)
    f_sens: FloatArray  # (N, 3)
    contact: FloatArray  # (N, 3) true contact of each sample


def circle(
    seed: int,
    n: int = 250,
    radius: float = 0.2,
    samples_per_circle: int = 125,
    tension: float = 4.0,
    force_noise: float = 0.05,
    mass_per_length: float = 0.0,
    contact: FloatArray = CONTACT,
    second_contact_at: int | None = None,
    second_offset: float = 0.1,
    peg_radius: float = 0.0,
) -> CircleData:
    """Gripper on a horizontal circle around a contact, cable taut.

    With ``second_contact_at`` the cable meets a second fixture at that sample:
    a point ``second_offset`` from the first contact on the segment towards the
    gripper, which becomes the contact from then on (the gripper keeps circling
    around the first one). With ``peg_radius`` > 0 the first contact is a round
    vertical peg: the cable leaves it at the tangent point, which moves.
    With ``mass_per_length`` > 0 the force is the chord tension plus half the
    span's weight (downwards).
    """
    rng = np.random.default_rng(seed)
    theta0 = rng.uniform(0.0, 2.0 * np.pi)
    k = np.arange(n)
    theta = theta0 + 2.0 * np.pi * k / samples_per_circle
    p = contact + radius * np.stack([np.cos(theta), np.sin(theta), np.zeros(n)], axis=1)
    c = np.repeat(contact[None, :], n, axis=0)
    if peg_radius > 0.0:
        # tangent point of a circle of radius peg_radius (cable turning counter-clockwise)
        alpha = np.arccos(peg_radius / radius)
        phi = theta - alpha
        c = contact + peg_radius * np.stack([np.cos(phi), np.sin(phi), np.zeros(n)], axis=1)
    if second_contact_at is not None:
        th = theta[second_contact_at]
        c2 = contact + second_offset * np.array([np.cos(th), np.sin(th), 0.0])
        c[second_contact_at:] = c2
    chord = c - p
    span = np.linalg.norm(chord, axis=1)
    f = tension * chord / span[:, None]
    f = f + (0.5 * mass_per_length * span)[:, None] * GRAVITY[None, :]
    f = f + rng.normal(0.0, force_noise, size=f.shape)
    return CircleData(p, f, c)
