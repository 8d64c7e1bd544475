"""Dimensions and jaw springs of a snap-in clip, sized from its push force.

The clip is a U-channel whose slot runs along its x-axis and opens upwards,
with two capsule jaws on preloaded slide joints above the seat. A cable of
radius r pressed down onto jaws of radius R_j whose centres sit c' off the
slot centre line touches each along a normal at angle phi above horizontal,
cos(phi) = c' / (r + R_j). With a jaw spring force H = k_j (delta + x)
(preload delta, opening x) and Coulomb friction mu on the jaws, the vertical
push the cable needs is

    P(x) = 2 H (sin(phi) + mu cos(phi)) / (cos(phi) - mu sin(phi)).

The jaw stiffness k_j is chosen so that the peak of P over the jaw travel is
the clip's ``push_force``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from tautwire.errors import InvalidArgumentError


@dataclass(frozen=True)
class ClipDesign:
    """A clip's geometry in its own frame (x along the slot, z up, origin at the seat).

    Attributes:
        cable_radius: r [m], the cable it is made for.
        jaw_radius: R_j [m].
        jaw_offset: c_0 [m], horizontal distance of each jaw axis from the
            slot centre line when closed.
        jaw_height: Height [m] of the jaw axes above the seat.
        jaw_travel: Largest opening x [m] of each jaw.
        preload: delta [m], spring compression when closed.
        jaw_stiffness: k_j [N/m].
        wall_gap: Half the inner width of the channel [m].
        friction: mu of the jaws on the cable.
        push_force: Peak of P(x) [N] (equals the requested push force).
    """

    cable_radius: float
    jaw_radius: float
    jaw_offset: float
    jaw_height: float
    jaw_travel: float
    preload: float
    jaw_stiffness: float
    wall_gap: float
    friction: float
    push_force: float

    def push_force_at(self, opening: float) -> float:
        """P(x) [N] for a jaw opening x [m] (0 when the jaws are fully open)."""
        reach = self.cable_radius + self.jaw_radius
        c = min(self.jaw_offset + opening, reach)
        phi = float(np.arccos(c / reach))
        h = self.jaw_stiffness * (self.preload + opening)
        s, co = np.sin(phi), np.cos(phi)
        return float(2.0 * h * (s + self.friction * co) / (co - self.friction * s))


def design_clip(
    push_force: float,
    cable_radius: float,
    friction: float,
    contact_angle: float = np.deg2rad(50.0),
    preload: float = 0.002,
) -> ClipDesign:
    """Size a clip for a cable of ``cable_radius`` that needs ``push_force``.

    Args:
        push_force: Peak push-in force [N].
        cable_radius: r [m].
        friction: mu of the jaws on the cable.
        contact_angle: phi [rad] at first contact (sets c_0).
        preload: delta [m].

    Raises:
        InvalidArgumentError: for non-positive sizes or a self-locking
            contact angle (cos(phi) <= mu sin(phi)).
    """
    if push_force <= 0.0 or cable_radius <= 0.0 or preload < 0.0 or friction < 0.0:
        raise InvalidArgumentError(
            "push_force and cable_radius must be > 0, preload and friction >= 0"
        )
    if np.cos(contact_angle) <= friction * np.sin(contact_angle):
        raise InvalidArgumentError(
            f"contact angle {contact_angle} rad with friction {friction} self-locks the clip"
        )
    r = cable_radius
    rj = 0.6 * r
    reach = r + rj
    c0 = reach * float(np.cos(contact_angle))
    travel = reach - c0
    unit = ClipDesign(r, rj, c0, reach + 3e-4, travel, preload, 1.0, r + 5e-4, friction, 0.0)
    xs = np.linspace(0.0, travel, 201)
    peak_per_stiffness = max(unit.push_force_at(float(x)) for x in xs)
    k = push_force / peak_per_stiffness
    return ClipDesign(
        r, rj, c0, reach + 3e-4, travel + 5e-4, preload, k, r + 5e-4, friction, push_force
    )
