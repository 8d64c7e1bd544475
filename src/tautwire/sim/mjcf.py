"""The MJCF text of a world, generated in code (nothing is downloaded).

Layout: a table plane; fixtures (anchors, pegs, clips); each cable as a 1-D
flex over one body per vertex (three slide joints, a site) with one spatial
tendon per segment carrying the axial spring; two floating parallel grippers
(a free joint with large armature, driven kinematically) whose finger pads
close along the tool y-axis under force actuators; for every gripper and
cable vertex an inactive ``connect`` equality that a grasp activates.

Collision groups: the cable collides with fixtures, the table and the finger
pads; fixtures and pads do not collide with each other, cables not with each
other.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from tautwire.robot.arm import ARMS, Arm
from tautwire.sim.clip_design import ClipDesign, design_clip
from tautwire.sim.discretization import CableDiscretization, discretize_cable
from tautwire.sim.options import SimOptions
from tautwire.sim.route import initial_vertices
from tautwire.sim.spec import AnchorSpec, ClipSpec, PegSpec, WorldSpec

FloatArray = NDArray[np.float64]

# collision bits
_CABLE, _FIXTURE, _PAD = 1, 2, 4
_STIFF_CONTACT = 'solref="0.002 1"'
#: Thickness [m] of a clip's channel walls. A cable pressed sideways sinks
#: into a wall (a contact's stiffness scales with the light cable vertices'
#: mass), and through a thin box MuJoCo's capsule-box contact finds the way
#: out by the far face: 2 and 3 mm walls let a cable kinked 53 deg at 8.4 N
#: through (tests/sim/test_mjcf.py); with 4 mm it stayed
#: against the wall, its centre 0.9 mm in (the truth: not in the channel).
#: Random board 1646371135's W1, kinked 27 deg at F2 while F pushed it into
#: F3 at 8.5 N, went through F2's 2 mm wall and the model kept F2: a false
#: success. 5 mm walls hold all of these (the centre 2.8 mm off the slot at
#: most, inside the channel).
WALL_THICKNESS = 0.005
_HOLD_SOLREF = "0.0005 1"
_HOLD_SOLIMP = "0.9999 0.9999 0.001"

#: Deepest floor [m] of a clip's channel (a solid block under its seat).
BASE_DEPTH = 0.012
#: Gripper finger pad half sizes [m]: along the cable, thickness, height.
PAD_HALF = (0.01, 0.003, 0.008)
FINGER_MASS = 0.02  # kg
FINGER_DAMPING = 2.0  # N s/m
GRIPPER_ARMATURE = 1.0e4  # kg, kg m^2


def _v(x: FloatArray | list[float] | tuple[float, ...]) -> str:
    return " ".join(f"{float(c):.9g}" for c in x)


def vertex_body(cable: str, i: int) -> str:
    """Name of the body of vertex ``i`` of ``cable``."""
    return f"{cable}_v{i}"


def hold_equality(arm: str, cable: str, i: int) -> str:
    """Name of the equality by which gripper ``arm`` holds vertex ``i`` of ``cable``."""
    return f"hold_{arm}_{cable}_{i}"


@dataclass
class SceneModel:
    """The generated MJCF and what the world needs to interpret it.

    Attributes:
        xml: The MJCF text.
        discretizations: Per cable name.
        vertices: Initial vertex positions per cable name.  # (N + 1, 3) each
        clips: Clip designs per clip name.
        anchored: Names of cables whose vertex 0 is fixed to an anchor.
    """

    xml: str
    discretizations: dict[str, CableDiscretization]
    vertices: dict[str, FloatArray]
    clips: dict[str, ClipDesign] = field(default_factory=dict)
    anchored: set[str] = field(default_factory=set)


def _gripper_xml(arm: Arm, world: WorldSpec, options: SimOptions) -> str:
    """A floating parallel gripper; its pads have lips that keep the cable in the channel.

    Each pad carries a thin lip along its top and bottom edge that protrudes
    towards the other finger by 0.7 cable radii, so that a cable sliding
    through the closed fingers cannot be pulled out of them vertically by a
    hanging tail (on flat pads Coulomb friction lets it drift out: while the
    cable slips along the pads, any sideways load makes it slip sideways too).
    """
    g = world.gripper(arm)
    px, ty, pz = PAD_HALF
    radius = max((c.radius for c in world.cables), default=0.0025)
    depth = 0.7 * radius
    lip_h = 5e-4
    half_open = 0.5 * options.max_opening
    colour = "0.20 0.35 0.75 1" if arm == "left" else "0.75 0.30 0.20 1"
    fingers = []
    for side, sign in (("a", 1.0), ("b", -1.0)):
        fingers.append(
            f'<body name="{arm}_finger_{side}" pos="0 {sign * ty:.6g} 0" gravcomp="1">'
            f'<joint name="{arm}_finger_{side}" type="slide" axis="0 {sign:g} 0" limited="true"'
            f' range="0 {half_open:.6g}" damping="{FINGER_DAMPING}" armature="0.01"'
            f' solreflimit="0.002 1"/>'
            f'<inertial pos="0 0 0" mass="{FINGER_MASS}" diaginertia="1e-6 1e-6 1e-6"/>'
            f'<geom name="{arm}_pad_{side}" type="box" size="{px} {ty} {pz}"'
            f' contype="{_PAD}" conaffinity="{_CABLE}" condim="3"'
            f' friction="{options.pad_friction} 0.005 0.0001"'
            f' {_STIFF_CONTACT} rgba="0.15 0.15 0.15 1"/>'
            + "".join(
                f'<geom name="{arm}_lip_{side}{k}" type="box"'
                f' pos="0 {-sign * (ty + 0.5 * depth):.6g} {zsign * (pz - lip_h):.6g}"'
                f' size="{px} {0.5 * depth:.6g} {lip_h:.6g}" contype="{_PAD}"'
                f' conaffinity="{_CABLE}" condim="3" friction="{options.pad_friction} 0.005 0.0001"'
                f' {_STIFF_CONTACT} rgba="0.15 0.15 0.15 1"/>'
                for k, zsign in (("_top", 1.0), ("_bottom", -1.0))
            )
            + f'<geom type="box" pos="0 {sign * 0.5 * ty:.6g} 0.026"'
            f' size="{px} {0.5 * ty:.6g} 0.018"'
            f' contype="0" conaffinity="0" rgba="{colour}"/>'
            "</body>"
        )
    return (
        f'<body name="{arm}_gripper" pos="{_v(g.position)}" quat="{_v(g.orientation)}"'
        ' gravcomp="1">'
        f'<joint name="{arm}_free" type="free" armature="{GRIPPER_ARMATURE}" damping="0"/>'
        '<inertial pos="0 0 0" mass="1" diaginertia="1e-3 1e-3 1e-3"/>'
        f'<site name="{arm}_tcp" size="0.002" rgba="1 1 0 1"/>'
        f'<geom type="box" pos="0 0 0.05" size="0.014 {half_open + 2 * ty:.6g} 0.006"'
        f' contype="0" conaffinity="0" rgba="{colour}"/>'
        f'<geom type="cylinder" pos="0 0 0.075" size="0.02 0.02" contype="0" conaffinity="0"'
        ' rgba="0.6 0.6 0.65 1"/>' + "".join(fingers) + "</body>"
    )


def _peg_xml(peg: PegSpec, options: SimOptions) -> str:
    """A peg, and below its base a collidable stand of the same radius down to the table.

    A post is mounted on the board: a cable that sags below the post's base
    must not slip underneath it.
    """
    p = peg.position
    bottom = min(p[2], options.table_height)
    top = p[2] + peg.height
    centre = np.array([p[0], p[1], 0.5 * (bottom + top)])
    return (
        f'<geom name="{peg.name}" type="cylinder" pos="{_v(centre)}" size="{peg.radius:.6g}'
        f' {0.5 * (top - bottom):.6g}" contype="{_FIXTURE}" conaffinity="{_CABLE}" condim="3"'
        f' friction="{options.peg_friction} 0.005 0.0001" {_STIFF_CONTACT} rgba="0.55 0.55 0.6 1"/>'
    )


def _anchor_xml(anchor: AnchorSpec, options: SimOptions) -> str:
    p = anchor.position
    out = (
        f'<geom name="{anchor.name}" type="sphere" pos="{_v(p)}" size="0.005" contype="0"'
        ' conaffinity="0" rgba="0.1 0.6 0.2 1"/>'
    )
    stand = p[2] - options.table_height
    if stand > 1e-4:
        out += (
            f'<geom type="box" pos="{_v([p[0], p[1], options.table_height + 0.5 * stand])}"'
            f' size="0.004 0.004 {0.5 * stand:.6g}" contype="0" conaffinity="0"'
            ' rgba="0.1 0.45 0.15 1"/>'
        )
    return out


def _clip_xml(clip: ClipSpec, design: ClipDesign, options: SimOptions) -> str:
    half_len = 0.5 * options.clip_length
    r = design.cable_radius
    wall_t = WALL_THICKNESS
    # the channel's floor: a solid block, as deep as the clip stands above
    # the table allows (up to 12 mm), so that a cable snapping in through the
    # jaws cannot pass through it in a time step (a 2 mm floor let W2's
    # cable of the shipped harness through C5, 35 mm below the seat)
    base_h = float(np.clip(clip.position[2] - r - options.table_height, 0.002, BASE_DEPTH))
    wall_top = design.jaw_height - design.jaw_radius - 3e-4
    wall_bottom = -r - base_h
    quat = [np.cos(0.5 * clip.yaw), 0.0, 0.0, np.sin(0.5 * clip.yaw)]
    common = (
        f'contype="{_FIXTURE}" conaffinity="{_CABLE}" condim="3"'
        f' friction="{design.friction} 0.005 0.0001" {_STIFF_CONTACT}'
    )
    outer = design.wall_gap + wall_t
    parts = [
        f'<geom name="{clip.name}_base" type="box" pos="0 0 {-r - 0.5 * base_h:.6g}"'
        f' size="{half_len:.6g} {outer:.6g} {0.5 * base_h:.6g}" {common} rgba="0.3 0.3 0.3 1"/>'
    ]
    for side, sign in (("a", 1.0), ("b", -1.0)):
        zc = 0.5 * (wall_top + wall_bottom)
        parts.append(
            f'<geom name="{clip.name}_wall_{side}" type="box"'
            f' pos="0 {sign * (design.wall_gap + 0.5 * wall_t):.6g} {zc:.6g}"'
            f' size="{half_len:.6g} {0.5 * wall_t:.6g} {0.5 * (wall_top - wall_bottom):.6g}"'
            f' {common} rgba="0.3 0.3 0.3 1"/>'
        )
        damping = float(np.sqrt(design.jaw_stiffness * 0.005))
        parts.append(
            f'<body name="{clip.name}_jaw_{side}" pos="0 {sign * design.jaw_offset:.6g}'
            f' {design.jaw_height:.6g}">'
            f'<joint name="{clip.name}_jaw_{side}" type="slide" axis="0 {sign:g} 0" limited="true"'
            f' range="0 {design.jaw_travel:.6g}" stiffness="{design.jaw_stiffness:.6g}"'
            f' springref="{-design.preload:.6g}" damping="{damping:.6g}" solreflimit="0.002 1"/>'
            '<inertial pos="0 0 0" mass="0.005" diaginertia="1e-7 1e-7 1e-7"/>'
            f'<geom name="{clip.name}_jaw_{side}" type="capsule"'
            f' fromto="{-half_len:.6g} 0 0 {half_len:.6g} 0 0" size="{design.jaw_radius:.6g}"'
            f' {common} rgba="0.85 0.75 0.2 1"/>'
            "</body>"
        )
    stand = clip.position[2] + wall_bottom - options.table_height
    if stand > 1e-4:
        # seen, not felt: a free tail dragged over the board slides under it
        # (felt, the tails of the shipped harness caught on the stands)
        parts.append(
            f'<geom type="box" pos="0 0 {wall_bottom - 0.5 * stand:.6g}"'
            f' size="{0.6 * half_len:.6g} {0.6 * outer:.6g} {0.5 * stand:.6g}" contype="0"'
            ' conaffinity="0" rgba="0.3 0.3 0.3 1"/>'
        )
    return (
        f'<body name="{clip.name}" pos="{_v(clip.position)}" quat="{_v(quat)}">'
        + "".join(parts)
        + "</body>"
    )


def _camera_xml(points: FloatArray) -> str:
    lo, hi = points.min(axis=0), points.max(axis=0)
    centre = 0.5 * (lo + hi)
    extent = max(float(np.max(hi - lo)), 0.2)
    eye = centre + extent * np.array([0.1, -1.1, 0.9])
    forward = centre - eye
    forward /= np.linalg.norm(forward)
    x_axis = np.cross(forward, [0.0, 0.0, 1.0])
    x_axis /= np.linalg.norm(x_axis)
    y_axis = np.cross(x_axis, forward)
    top = centre + np.array([0.0, 0.0, 1.5 * extent])
    return (
        f'<camera name="overview" pos="{_v(eye)}" xyaxes="{_v(x_axis)} {_v(y_axis)}" fovy="45"/>'
        f'<light name="key" pos="{_v(top)}" dir="0 0.3 -1" diffuse="0.8 0.8 0.8"'
        ' castshadow="true"/>'
    )


def scene_model(world: WorldSpec, options: SimOptions) -> SceneModel:
    """Generate the MJCF of ``world``.

    Raises:
        SimulationError: where the wave-speed guard refuses a cable or a
            route would start over-stretched.
    """
    discs: dict[str, CableDiscretization] = {}
    verts: dict[str, FloatArray] = {}
    anchored: set[str] = set()
    for cable in world.cables:
        disc = discretize_cable(cable, world.force_limit, options)
        discs[cable.name] = disc
        verts[cable.name] = initial_vertices(
            world, cable, disc, options.clip_length, options.table_height, options.pad_exit
        )
        if cable.start is not None:
            anchored.add(cable.name)
    radius_by_clip: dict[str, float] = {}
    for cable in world.cables:
        for name in cable.via:
            radius_by_clip[name] = max(radius_by_clip.get(name, 0.0), cable.radius)
    default_radius = max((c.radius for c in world.cables), default=0.0025)
    clips = {
        f.name: design_clip(
            f.push_force, radius_by_clip.get(f.name, default_radius), options.peg_friction
        )
        for f in world.fixtures
        if isinstance(f, ClipSpec)
    }

    body: list[str] = [
        f'<geom name="table" type="plane" pos="0 0 {options.table_height:.6g}" size="2 2 0.01"'
        f' contype="{_FIXTURE}" conaffinity="{_CABLE}" condim="3"'
        f' friction="{options.table_friction} 0.005 0.0001" {_STIFF_CONTACT} material="table"/>'
    ]
    for f in world.fixtures:
        if isinstance(f, PegSpec):
            body.append(_peg_xml(f, options))
        elif isinstance(f, ClipSpec):
            body.append(_clip_xml(f, clips[f.name], options))
        else:
            body.append(_anchor_xml(f, options))
    deformable: list[str] = []
    tendons: list[str] = []
    equalities: list[str] = []
    for cable in world.cables:
        disc = discs[cable.name]
        x = verts[cable.name]
        for i, (p, m, alpha) in enumerate(zip(x, disc.masses, disc.mass_scaling, strict=True)):
            gravcomp = 1.0 - 1.0 / alpha
            name = vertex_body(cable.name, i)
            if i == 0 and cable.name in anchored:
                body.append(
                    f'<body name="{name}" pos="{_v(p)}"><site name="{name}" group="4"/></body>'
                )
                continue
            scaled = alpha * m
            joints = "".join(
                f'<joint name="{name}_{ax}" type="slide" axis="{axis}"/>'
                for ax, axis in (("x", "1 0 0"), ("y", "0 1 0"), ("z", "0 0 1"))
            )
            body.append(
                f'<body name="{name}" pos="{_v(p)}" gravcomp="{gravcomp:.9g}">{joints}'
                f'<inertial pos="0 0 0" mass="{scaled:.9g}" diaginertia="1e-9 1e-9 1e-9"/>'
                f'<site name="{name}" group="4"/></body>'
            )
        n = disc.segments
        names = " ".join(vertex_body(cable.name, i) for i in range(n + 1))
        deformable.append(
            f'<flex name="{cable.name}" dim="1" radius="{cable.radius:.6g}" body="{names}"'
            f' vertex="{" ".join(["0 0 0"] * (n + 1))}"'
            f' element="{" ".join(f"{i} {i + 1}" for i in range(n))}" rgba="0.95 0.55 0.1 1">'
            f'<contact contype="{_CABLE}" conaffinity="{_FIXTURE | _PAD}" condim="3"'
            f' friction="0.001 0.005 0.0001" {_STIFF_CONTACT} selfcollide="none"/>'
            "</flex>"
        )
        for i in range(n):
            k = disc.segment_stiffness[i]
            l0 = disc.rest_lengths[i]
            tendons.append(
                f'<spatial name="{cable.name}_t{i}" stiffness="{k:.9g}" springlength="0 {l0:.9g}"'
                f' damping="{options.tendon_damping_ratio * k:.9g}" width="0.0005" rgba="0 0 0 0">'
                f'<site site="{vertex_body(cable.name, i)}"/>'
                f'<site site="{vertex_body(cable.name, i + 1)}"/></spatial>'
            )
        for arm in ARMS:
            for i in range(n + 1):
                if i == 0 and cable.name in anchored:
                    continue
                equalities.append(
                    f'<connect name="{hold_equality(arm, cable.name, i)}" body1="{arm}_gripper"'
                    f' body2="{vertex_body(cable.name, i)}" anchor="0 0 0" active="false"'
                    f' solref="{_HOLD_SOLREF}" solimp="{_HOLD_SOLIMP}"/>'
                )
    for arm in ARMS:
        body.append(_gripper_xml(arm, world, options))
    actuators = "".join(
        f'<motor name="{arm}_finger_{side}" joint="{arm}_finger_{side}" ctrllimited="true"'
        ' ctrlrange="-1000 1000"/>'
        for arm in ARMS
        for side in ("a", "b")
    )
    pts = [f.position for f in world.fixtures] + [world.left.position, world.right.position]
    pts += [v for arr in verts.values() for v in arr]
    body.append(_camera_xml(np.array(pts)))
    xml = (
        '<mujoco model="tautwire">'
        f'<option timestep="{options.timestep:.9g}" integrator="discrete" cone="elliptic"'
        f' tolerance="{options.solver_tolerance:.3g}" impratio="10" gravity="0 0 -9.81"/>'
        '<visual><global offwidth="1280" offheight="960"/><quality shadowsize="2048"/></visual>'
        '<asset><texture name="grid" type="2d" builtin="checker" width="256" height="256"'
        ' rgb1="0.82 0.74 0.6" rgb2="0.78 0.7 0.56"/>'
        '<material name="table" texture="grid" texrepeat="20 20" reflectance="0"/></asset>'
        f"<worldbody>{''.join(body)}</worldbody>"
        f"<deformable>{''.join(deformable)}</deformable>"
        f"<tendon>{''.join(tendons)}</tendon>"
        f"<equality>{''.join(equalities)}</equality>"
        f"<actuator>{actuators}</actuator>"
        "</mujoco>"
    )
    return SceneModel(xml, discs, verts, clips, anchored)
