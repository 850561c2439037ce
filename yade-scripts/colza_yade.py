# Shared helpers of the YADE cross-check scripts (run_scene.py, run_oedometer.py).
#
# YADE is the independent referee of colza's physics (shared/design/physics.md sections 2,
# 3 and 6). These helpers read a colza TOML config with tomllib, fill in colza's defaults
# (src/config/run_config.hpp) for absent keys, and build a YADE scene that computes the
# same contact law, integration and geometry as colza:
#
#   * sphere-sphere: CohFrictMat, one material per distinct radius with young = Kn / R and
#     poisson = Ks / Kn, so YADE's 2 E1R1 E2R2 / (E1R1 + E2R2) is the contact Kn exactly;
#     Ig2_Sphere_Sphere_ScGeom6D(avoidGranularRatcheting=False) (contact point in the middle
#     of the overlap, lever arms c - x_i), Law2_ScGeom6D_CohFrictPhys_CohesionMoment;
#     contact bonds written per interaction with cohesionDisablesFriction = True.
#   * sphere-wall: FrictMat walls, Ip2_FrictMat_FrictMat_FrictPhys with MatchMaker(algo='val')
#     for Kn_w, Ks_w, atan(mu_pw); Law2_ScGeom_FrictPhys_CundallStrack.
#   * geometry of the walls (see wall_geometry_note below):
#       plane     -> a zero-thickness Box (utils.box, extents (L, L, 0)) oriented with its
#                    local z along the plane normal; Ig2_Box_Sphere_ScGeom puts the contact
#                    point in the middle of the overlap (lever arm R - un/2, as colza), unlike
#                    utils.wall (R - un). L is large (PLANE_HALF_SIZE); colza's plane is
#                    infinite and one-sided, the box is finite and two-sided: identical for
#                    every sphere in front of the plane and within L of its point.
#       rectangle -> the same zero-thickness Box with extents (half_u, half_v, 0): YADE's
#                    closest-point-on-box geometry is colza's rectangle geometry (face, edges
#                    and corners), so this is exact.
#       cylinder  -> exact "contact patches": every sphere that can reach the inner surface
#                    gets its own kinematic point body (Box with zero extents) that a
#                    PyRunner, before the collider, places each step on the cylinder surface
#                    at the sphere's azimuth and height: p = axis point + axial a + Rc e_r.
#                    For a point, Ig2_Box_Sphere_ScGeom gives normal (x - p)/|x - p| = -e_r,
#                    overlap R - (Rc - rho) and contact point in the middle of the overlap:
#                    exactly colza's cylinder contact. The patch carries the cylinder's
#                    velocity (zero for the oedometer) and no spin, so the shear increment and
#                    the tangent-plane rotation are colza's too. A patch can only touch its
#                    own sphere (another sphere would have to overlap that sphere by about R
#                    to reach it); patches of spheres farther than PATCH_RANGE_FACTOR R from
#                    the surface, or from the cylinder's axial range, are parked far away.
#                    An active patch whose sphere is beyond an end waits at that end, at the
#                    sphere's azimuth, PATCH_RIM_GAP_FACTOR R outside the surface (or outside
#                    the sphere, if it pokes through the surface's extension): at least
#                    1.25 R from the centre, out of the sphere's reach, but close enough that
#                    the collider's bounds (grown by verletDist, 0.5 R_min by default: so for
#                    R < 2 R_min) keep the pair, so the contact starts in the step the
#                    centre enters the range. (Teleported there from the far parking place,
#                    the patch was only seen at the collider's next run: one step late.)
#                    geom.facetCylinder is not used: a polygon of triangles changes the
#                    surface by Rc (1/cos(pi/N) - 1) and gives spheres extra edge contacts at
#                    every facet edge under their footprint.
#   * rolling resistance (contact.rolling = "elastic_plastic", physics.md 7.1, form "yade", not
#     at walls): the same per-radius CohFrictMat with momentRotationLaw = True, alphaKr = beta
#     (the Ip2's harmonic mean of two equal values: kr = beta Ks R1 R2 with the exact contact
#     Ks), etaRoll = mu_r (maxRollPl = min(etaRoll R1, etaRoll R2)), alphaKtw = 0 (no twist
#     moment), etaTwist = -1; the Law2 with useIncrementalForm = always_use_moment_law = True.
#   * Hertz-Mindlin (contact.normal = "hertz", tangential = "mindlin", physics.md 7.2):
#     FrictMat(young = E, poisson = nu), Ig2_Sphere_Sphere_ScGeom(avoidGranularRatcheting=False),
#     Ip2_FrictMat_FrictMat_MindlinPhys (no damping, no adhesion), Law2_ScGeom_MindlinPhys_Mindlin;
#     sphere-sphere only (YADE gives a wall the sphere's radius: R* = R/2, colza R).
#   * Refused, with a message: viscous contact damping, walton_braun, load_induced bonds,
#     hertz with linear shear or walls or bonds or rolling, rolling in the "pfc" form, at
#     walls or with bonds (crosscheck/YADE_MECHANISMS.md says why).
#   * NewtonIntegrator(damping=alpha, gravity=g) is colza's damping_form = "yade"; fixed O.dt.
#   * The recorder runs in a PyRunner placed after InteractionLoop and before
#     NewtonIntegrator: it sees x(t_n), v(t_n - dt/2) and the contact forces of step n,
#     exactly like colza's observer (no gravity in the forces).
#
# Only single-threaded YADE (-j 1) repeats itself bit for bit.
#
# Differences found by the cross-check (crosscheck/README.md): YADE turns the stored shear
# force about the previous normal (dt/2 (w1 + w2) . n_old), and a bond broken in shear while
# in tension gets no normal force in that step; colza now does both the same way. The micro
# scenes agree to rounding.
import math
import os
import sys
import time
import tomllib

import colza_packing  # noqa: E402  (same folder; the scripts put it on sys.path)

from yade import utils
from yade.minieigenHP import Matrix3, Quaternion, Vector3
from yade.wrapper import *  # noqa: F401,F403  (O and the engine, material and shape classes)

PLANE_HALF_SIZE = 10.0        # m, half extent of the box that stands in for an infinite plane
PATCH_RANGE_FACTOR = 1.0      # a sphere gets an active cylinder patch when its gap to the surface < this x R
PATCH_REFRESH_STEPS = 20      # steps between re-evaluations of which spheres have an active patch
PARK_DISTANCE = 1.0e3         # m, where inactive patches wait (each at its own spot)
PATCH_RIM_GAP_FACTOR = 0.25   # an active patch of a sphere beyond an end waits this x R outside
                              # the surface (or the sphere): within verletDist (0.5 R_min by
                              # default) of where it goes when the sphere enters the range

# Group masks: spheres collide with spheres, walls and patches; patches only with spheres;
# walls only with spheres (avoidSelfInteractionMask stops wall-wall and patch-patch pairs).
MASK_SPHERE = 1 | 4
MASK_PATCH = 2 | 4
MASK_WALL = 1 | 8
AVOID_SELF = 2 | 8


class ConfigError(Exception):
    pass


# Ig2_Box_Sphere_ScGeom (and Ig2_Wall_Sphere_ScGeom unless hertzian) give a wall the sphere's
# radius, so Ip2_FrictMat_FrictMat_MindlinPhys's R* = R1 R2 / (R1 + R2) is R/2 at a wall,
# where physics.md 7.2 (and colza) take R.
HERTZ_WALLS = ('contact.normal = "hertz" with walls: YADE gives a wall the sphere\'s radius '
               "(R* = R/2 where colza has R* = R); Hertz-Mindlin is cross-checked between spheres only")


# ---------------------------------------------------------------------------------------
# Config: colza's keys and defaults (src/config/run_config.hpp, slot_registry.cpp)
# ---------------------------------------------------------------------------------------

def _vec3(table, key, fallback):
    v = table.get(key, fallback)
    if len(v) != 3:
        raise ConfigError(f"{key} must have 3 components")
    return [float(c) for c in v]


def _normalized(v):
    n = math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
    if n == 0.0:
        raise ConfigError("zero vector")
    return [v[0] / n, v[1] / n, v[2] / n]


def combine_stiffness(k1, k2, rule):
    """colza's core/materials.cpp combine_stiffness, same floating-point expression."""
    if rule == "series":
        return k1 * k2 / (k1 + k2)
    return min(k1, k2)


def read_config(path, scenario):
    """Reads a colza TOML file into a plain dict with every default filled in."""
    with open(path, "rb") as f:
        doc = tomllib.load(f)
    base = os.path.dirname(os.path.abspath(path))
    declared = doc.get("scenario", scenario)
    if declared != scenario:
        raise ConfigError(f'{path}: this file is for scenario "{declared}", not "{scenario}"')
    c = {"source": path, "title": doc.get("title", "")}
    p = doc.get("particle", {})
    c["particle"] = {
        "density": float(p.get("density", 1250.0)),
        "normal_stiffness": float(p.get("normal_stiffness", 437e3)),
        "shear_stiffness": float(p.get("shear_stiffness", 100e3)),
        "friction": float(p.get("friction", 0.20)),
        "diameter_min": float(p.get("diameter_min", 6e-3)),
        "diameter_max": float(p.get("diameter_max", 7e-3)),
        # Hertz-Mindlin (physics.md 7.2); None when absent (read_contact_model requires them)
        "young_modulus": _optional_float(p, "young_modulus"),
        "poisson_ratio": _optional_float(p, "poisson_ratio"),
    }
    w = doc.get("wall", {})
    c["wall"] = {
        "normal_stiffness": float(w.get("normal_stiffness", 4000e3)),
        "shear_stiffness": float(w.get("shear_stiffness", 1000e3)),
        "friction": float(w.get("friction", 0.23)),
        "young_modulus": _optional_float(w, "young_modulus"),
        "poisson_ratio": _optional_float(w, "poisson_ratio"),
    }
    k = doc.get("contact", {})
    bond = k.get("bond", "none")
    cb = k.get("contact_bond", {})
    c["contact"] = {
        "stiffness_rule": k.get("stiffness_rule", "series"),
        "wall_friction": k.get("wall_friction", "own"),
        "normal": k.get("normal", "linear"),
        "tangential": k.get("tangential", "coulomb"),
        "damping": k.get("damping", "none"),
        "rolling": k.get("rolling", "none"),
        "bond": bond,
        "bond_install": "never" if bond == "none" else k.get("bond_install", "before_loading"),
        "bond_gap": float(k.get("bond_gap", 0.0)),
        "normal_strength": float(cb.get("normal_strength", 0.0)),
        "shear_strength": float(cb.get("shear_strength", 0.0)),
    }
    read_contact_model(c, k)
    i = doc.get("integration", {})
    ts = i.get("time_step", "auto")
    c["integration"] = {
        "damping": float(i.get("damping", 0.7)),
        "damping_form": i.get("damping_form", "pfc"),
        "gravity": _vec3(i, "gravity", [0.0, 0.0, -9.81]),
        "time_step": ts,
    }
    if isinstance(ts, str):
        raise ConfigError("the YADE cross-check needs a fixed integration.time_step (s), not \"auto\"")
    c["integration"]["time_step"] = float(ts)
    if c["integration"]["damping"] != 0.0 and c["integration"]["damping_form"] != "yade":
        raise ConfigError('YADE computes local damping in the "yade" form only: set integration.damping_form = "yade"')
    if scenario == "oedometer":
        o = doc.get("oedometer", {})
        c["oedometer"] = {
            "cylinder_diameter": float(o.get("cylinder_diameter", 0.100)),
            "cylinder_height": float(o.get("cylinder_height", 0.080)),
            "generation_height": float(o.get("generation_height", 0.200)),
            "piston_speed": float(o.get("piston_speed", 0.5 / 60.0)),
            "stop_force": float(o.get("stop_force", 30e3)),
            "max_piston_travel": float(o.get("max_piston_travel", 0.040)),
            "record_interval": int(o.get("record_interval", 50)),
            "fit_force_min": float(o.get("fit_force_min", 150.0)),
            "fit_force_max": float(o.get("fit_force_max", 29.3e3)),
            "packing_file": o.get("packing_file", ""),
        }
        # Load-unload cycles (oedometer.cycles) are colza's alone: YADE's script runs one
        # loading, so a config asking for cycles is refused rather than run as something else.
        for key in ("cycles", "modulus_stresses"):
            if key in o:
                raise ConfigError(f"oedometer.{key}: load-unload cycles are not in the YADE oedometer script "
                                  "(yade-scripts/run_oedometer.py runs a single loading)")
        pf = c["oedometer"]["packing_file"]
        if not pf:
            raise ConfigError("the YADE oedometer starts from a settled packing: set oedometer.packing_file")
        c["oedometer"]["packing_file"] = pf if os.path.isabs(pf) else os.path.join(base, pf)
    else:
        s = doc.get("scene", {})
        if "steps" not in s:
            raise ConfigError("scene.steps is required")
        scene = {
            "steps": int(s["steps"]),
            "record_interval": int(s.get("record_interval", 1)),
            "record_particles": [int(x) for x in s.get("record_particles", [])],
            "particles": [],
            "walls": [],
        }
        for sp in s.get("particles", []):
            scene["particles"].append({
                "position": _vec3(sp, "position", [0.0, 0.0, 0.0]),
                "radius": float(sp["radius"]),
                "velocity": _vec3(sp, "velocity", [0.0, 0.0, 0.0]),
                "angular_velocity": _vec3(sp, "angular_velocity", [0.0, 0.0, 0.0]),
                "fixed": bool(sp.get("fixed", False)),
            })
        pf = s.get("packing_file", "")
        if pf:
            pf = pf if os.path.isabs(pf) else os.path.join(base, pf)
            for (x, r) in read_packing(pf):
                scene["particles"].append({"position": x, "radius": r, "velocity": [0.0] * 3,
                                           "angular_velocity": [0.0] * 3, "fixed": False})
        for wt in s.get("walls", []):
            scene["walls"].append(read_wall(wt))
        c["scene"] = scene
    if c["contact"]["hertz"] and (scenario == "oedometer" or c["scene"]["walls"]):
        raise ConfigError(HERTZ_WALLS)
    return c


def _optional_float(table, key):
    v = table.get(key)
    return None if v is None else float(v)


def read_contact_model(c, k):
    """The contact-law slots YADE can compute as colza does (physics.md section 7,
    crosscheck/YADE_MECHANISMS.md); every other choice is refused, not approximated.

      normal/tangential  linear/coulomb  CohFrict law (section 6)
                         hertz/mindlin   Ip2_FrictMat_FrictMat_MindlinPhys +
                                         Law2_ScGeom_MindlinPhys_Mindlin, sphere-sphere only
      rolling            elastic_plastic CohFrict law with momentRotationLaw, form "yade",
                                         not at walls, linear law, no bonds
    """
    ct = c["contact"]
    normal, tangential = ct["normal"], ct["tangential"]
    if (normal, tangential) not in (("linear", "coulomb"), ("hertz", "mindlin")):
        if normal == "walton_braun":
            raise ConfigError('contact.normal = "walton_braun": the YADE cross-check has no elasto-plastic '
                              'normal law (not mapped to any YADE law)')
        raise ConfigError(f'contact.normal = "{normal}" with contact.tangential = "{tangential}": the YADE '
                          'cross-check knows only linear + coulomb (CohFrict law) and hertz + mindlin '
                          '(Law2_ScGeom_MindlinPhys_Mindlin)')
    if ct["damping"] != "none":
        raise ConfigError(f'contact.damping = "{ct["damping"]}": the YADE cross-check has no viscous contact '
                          'damping (not mapped; only "none")')
    if ct["bond"] not in ("none", "contact_bond"):
        raise ConfigError(f'contact.bond = "{ct["bond"]}": the YADE cross-check knows only "none" and '
                          '"contact_bond" (load_induced is not mapped)')
    ct["hertz"] = normal == "hertz"
    if ct["hertz"]:
        part = c["particle"]
        for key in ("young_modulus", "poisson_ratio"):
            if part[key] is None:
                raise ConfigError(f"contact.normal = \"hertz\" needs particle.{key} given explicitly "
                                  "(the YADE cross-check does not guess colza's default)")
        if part["young_modulus"] <= 0.0 or not (-1.0 < part["poisson_ratio"] <= 0.5):
            raise ConfigError("particle.young_modulus must be > 0 and particle.poisson_ratio in (-1, 0.5]")
        if ct["bond"] != "none":
            raise ConfigError('contact.normal = "hertz" with a bond: YADE\'s Mindlin law has no bonds')
    rolling = ct["rolling"]
    ct["rolling_enabled"] = False
    if rolling == "none":
        return
    if rolling != "elastic_plastic":
        raise ConfigError(f'unknown contact.rolling = "{rolling}"')
    ep = k.get("elastic_plastic", {})
    form = ep.get("form", "yade")
    at_walls = ep.get("at_walls", False)
    if form != "yade":
        raise ConfigError(f'contact.elastic_plastic.form = "{form}": YADE\'s CohFrict law computes only the '
                          '"yade" form (kr = beta Ks R1 R2, cap mu_r min(R1, R2) Fn); "pfc" (R*) is not mapped')
    if at_walls:
        raise ConfigError("contact.elastic_plastic.at_walls = true: YADE's sphere-wall law "
                          "(Law2_ScGeom_FrictPhys_CundallStrack) has no rolling moment")
    if ep.get("damping_ratio", 0.0) != 0.0:
        raise ConfigError(f'contact.elastic_plastic.damping_ratio = {ep["damping_ratio"]}: YADE\'s CohFrict law '
                          "has a rolling spring and its cap, no rolling dashpot")
    if ct["hertz"]:
        raise ConfigError('contact.rolling = "elastic_plastic" with contact.normal = "hertz": not mapped '
                          "(YADE's Mindlin law has its own rolling moment, krot constant and cap eta (R1 + R2)/2 |Fn|)")
    if ct["bond"] != "none":
        raise ConfigError('contact.rolling = "elastic_plastic" with a bond: not mapped (YADE caps the moment of a '
                          "bonded contact in tension at etaRoll min(R) |Fn|, colza at mu_r min(R) max(Fn, 0) = 0)")
    for key in ("stiffness_factor", "friction"):
        if key not in ep:
            raise ConfigError(f"contact.rolling = \"elastic_plastic\" needs contact.elastic_plastic.{key} given "
                              "explicitly (the YADE cross-check does not guess colza's default)")
    beta, mu_r = float(ep["stiffness_factor"]), float(ep["friction"])
    if beta <= 0.0 or mu_r < 0.0:
        raise ConfigError("contact.elastic_plastic.stiffness_factor must be > 0 and friction >= 0")
    ct["rolling_enabled"] = True
    ct["rolling_stiffness_factor"] = beta
    ct["rolling_friction"] = mu_r


def read_wall(t):
    shape = t.get("shape", "plane")
    w = {"shape": shape, "name": t.get("name", shape), "velocity": _vec3(t, "velocity", [0.0, 0.0, 0.0])}
    if shape == "plane":
        w["origin"] = _vec3(t, "point", [0.0, 0.0, 0.0])
        w["normal"] = _normalized(_vec3(t, "normal", [0.0, 0.0, 1.0]))
    elif shape == "cylinder":
        w["origin"] = _vec3(t, "point", [0.0, 0.0, 0.0])
        w["axis"] = _normalized(_vec3(t, "axis", [0.0, 0.0, 1.0]))
        w["radius"] = float(t["radius"])
        w["axial_min"] = float(t.get("axial_min", -1e300))
        w["axial_max"] = float(t.get("axial_max", 1e300))
    elif shape == "rectangle":
        w["origin"] = _vec3(t, "center", [0.0, 0.0, 0.0])
        n = _normalized(_vec3(t, "normal", [0.0, 0.0, 1.0]))
        u = _vec3(t, "axis_u", [1.0, 0.0, 0.0])
        d = u[0] * n[0] + u[1] * n[1] + u[2] * n[2]
        u = _normalized([u[0] - d * n[0], u[1] - d * n[1], u[2] - d * n[2]])
        w["normal"] = n
        w["axis_u"] = u
        w["half_u"] = float(t["half_u"])
        w["half_v"] = float(t["half_v"])
    else:
        raise ConfigError(f"unknown wall shape {shape}")
    return w


def read_packing(path):
    """colza packing file as ([x, y, z], r) pairs (colza_packing.py reads the format)."""
    return [([x, y, z], r) for (x, y, z, r) in colza_packing.read_packing(path)]


# ---------------------------------------------------------------------------------------
# Scene building
# ---------------------------------------------------------------------------------------

class Model:
    """A YADE scene built from a colza config: bodies, engines, and the bookkeeping the
    recorders need (particle ids, wall bodies, cylinder patches)."""

    def __init__(self, config):
        self.c = config
        part, wall, contact = config["particle"], config["wall"], config["contact"]
        rule = contact["stiffness_rule"]
        self.kn_pp = combine_stiffness(part["normal_stiffness"], part["normal_stiffness"], rule)
        self.ks_pp = combine_stiffness(part["shear_stiffness"], part["shear_stiffness"], rule)
        self.mu_pp = part["friction"]
        if rule == "series":
            self.kn_pw = combine_stiffness(part["normal_stiffness"], wall["normal_stiffness"], rule)
            self.ks_pw = combine_stiffness(part["shear_stiffness"], wall["shear_stiffness"], rule)
        else:  # colza: the wall's numbers are the contact's
            self.kn_pw, self.ks_pw = wall["normal_stiffness"], wall["shear_stiffness"]
        # contact.wall_friction: "own" uses mu_pw as is (physics.md), "min" takes
        # min(mu_pp, mu_pw), PFC3D 4's rule (colza's WallFrictionRule).
        self.mu_pw = wall["friction"] if contact["wall_friction"] == "own" else min(part["friction"], wall["friction"])
        self.density = part["density"]
        self.materials = {}   # radius -> material id
        self.particles = []   # body ids, in colza's order
        self.walls = []       # per colza wall: dict(kind, body / patches, ...)
        self.patch_walls = []
        self.bonded_at_start = 0
        O.reset()
        O.dt = config["integration"]["time_step"]
        self.wall_material = O.materials.append(FrictMat(young=1.0, poisson=1.0, density=1.0,
                                                         frictionAngle=math.atan(self.mu_pw), label="wall"))

    # ---- particles -------------------------------------------------------------------
    def material_for(self, radius):
        m = self.materials.get(radius)
        if m is None:
            ct = self.c["contact"]
            if ct["hertz"]:
                # Ip2_FrictMat_FrictMat_MindlinPhys takes Young's modulus and Poisson's ratio as
                # they are (E*, G* of physics.md 7.2) and the radii from the geometry: one
                # material would do, one per radius keeps the bookkeeping of the linear law.
                part = self.c["particle"]
                m = O.materials.append(FrictMat(
                    young=part["young_modulus"], poisson=part["poisson_ratio"], density=self.density,
                    frictionAngle=math.atan(self.mu_pp)))
            elif ct["rolling_enabled"]:
                # Rolling resistance (physics.md 7.1, form "yade"): the Ip2 makes
                # kr = R1 R2 Ks alphaKr with alphaKr the harmonic mean of the two materials'
                # values (= beta for equal values) and Ks the contact Ks (young/poisson below),
                # and maxRollPl = min(etaRoll R1, etaRoll R2) = mu_r min(R1, R2); the Law2 caps
                # |Mr| at maxRollPl |Fn|. alphaKtw = 0: no twist moment (ktw = 0); etaTwist < 0:
                # no twist cap.
                m = O.materials.append(CohFrictMat(
                    young=self.kn_pp / radius, poisson=self.ks_pp / self.kn_pp, density=self.density,
                    frictionAngle=math.atan(self.mu_pp), isCohesive=True, momentRotationLaw=True,
                    alphaKr=ct["rolling_stiffness_factor"], alphaKtw=0.0, etaRoll=ct["rolling_friction"],
                    etaTwist=-1.0, fragile=True))
            else:
                m = O.materials.append(CohFrictMat(
                    young=self.kn_pp / radius, poisson=self.ks_pp / self.kn_pp, density=self.density,
                    frictionAngle=math.atan(self.mu_pp), isCohesive=True, momentRotationLaw=False,
                    alphaKr=0.0, alphaKtw=0.0, etaRoll=-1.0, etaTwist=-1.0, fragile=True))
            self.materials[radius] = m
        return m

    def add_particle(self, position, radius, velocity=(0, 0, 0), angular_velocity=(0, 0, 0), fixed=False):
        b = utils.sphere(Vector3(*position), radius, material=self.material_for(radius), fixed=fixed)
        # colza's mass and inertia, same floating-point expressions (core/particles.cpp)
        mass = self.density * 4.0 / 3.0 * math.pi * radius * radius * radius
        inertia = 0.4 * mass * radius * radius
        b.state.mass = mass
        b.state.inertia = Vector3(inertia, inertia, inertia)
        b.state.vel = Vector3(*velocity)
        b.state.angVel = Vector3(*angular_velocity)
        b.groupMask = MASK_SPHERE
        i = O.bodies.append(b)
        self.particles.append(i)
        return i

    # ---- walls -----------------------------------------------------------------------
    def _box(self, center, normal, axis_u, half_u, half_v, velocity):
        n = Vector3(*normal)
        u = Vector3(*axis_u)
        v = n.cross(u)
        rot = Matrix3(u[0], v[0], n[0], u[1], v[1], n[1], u[2], v[2], n[2])  # columns u, v, n
        b = utils.box(center=Vector3(*center), extents=Vector3(half_u, half_v, 0.0),
                      orientation=Quaternion(rot), fixed=True, material=self.wall_material)
        b.state.mass = 1.0
        b.state.inertia = Vector3(1.0, 1.0, 1.0)
        b.state.vel = Vector3(*velocity)
        b.groupMask = MASK_WALL
        return O.bodies.append(b)

    def add_wall(self, w):
        if self.c["contact"]["hertz"]:
            fail(HERTZ_WALLS)  # read_config refuses a scene's or the oedometer's; this, the shear box's
        if w["shape"] == "plane":
            n = w["normal"]
            # any unit vector perpendicular to n; exact for axis-aligned planes
            helper = [1.0, 0.0, 0.0] if abs(n[0]) < 0.9 else [0.0, 1.0, 0.0]
            d = helper[0] * n[0] + helper[1] * n[1] + helper[2] * n[2]
            u = _normalized([helper[0] - d * n[0], helper[1] - d * n[1], helper[2] - d * n[2]])
            bid = self._box(w["origin"], n, u, PLANE_HALF_SIZE, PLANE_HALF_SIZE, w["velocity"])
            self.walls.append({"kind": "box", "body": bid})
        elif w["shape"] == "rectangle":
            bid = self._box(w["origin"], w["normal"], w["axis_u"], w["half_u"], w["half_v"], w["velocity"])
            self.walls.append({"kind": "box", "body": bid})
        else:
            cw = {"kind": "cylinder", "origin": list(w["origin"]), "axis": w["axis"], "radius": w["radius"],
                  "axial_min": w["axial_min"], "axial_max": w["axial_max"], "velocity": w["velocity"],
                  "patches": {}, "active": set()}
            self.walls.append(cw)
            self.patch_walls.append(cw)

    def _make_patches(self):
        """One kinematic point body per (cylinder, sphere), parked until needed."""
        k = 0
        for cw in self.patch_walls:
            for i in self.particles:
                b = utils.box(center=Vector3(PARK_DISTANCE + 0.01 * k, PARK_DISTANCE, PARK_DISTANCE),
                              extents=Vector3(0, 0, 0), fixed=True, material=self.wall_material)
                b.state.mass = 1.0
                b.state.inertia = Vector3(1.0, 1.0, 1.0)
                b.state.vel = Vector3(*cw["velocity"])
                b.groupMask = MASK_PATCH
                pid = O.bodies.append(b)
                cw["patches"][i] = (pid, O.bodies[pid].state, O.bodies[i].state, O.bodies[i].shape.radius,
                                    Vector3(PARK_DISTANCE + 0.01 * k, PARK_DISTANCE, PARK_DISTANCE))
                k += 1

    def update_patches(self):
        """Before the collider: put each active patch on the cylinder at its sphere's azimuth."""
        refresh = O.iter % PATCH_REFRESH_STEPS == 0
        for cw in self.patch_walls:
            o, a, rc = cw["origin"], cw["axis"], cw["radius"]
            lo, hi = cw["axial_min"], cw["axial_max"]
            active = cw["active"]
            items = cw["patches"].items() if refresh else [(i, cw["patches"][i]) for i in active]
            for i, (pid, pst, sst, r, park) in items:
                x = sst.pos
                rx, ry, rz = x[0] - o[0], x[1] - o[1], x[2] - o[2]
                axial = rx * a[0] + ry * a[1] + rz * a[2]
                qx, qy, qz = rx - axial * a[0], ry - axial * a[1], rz - axial * a[2]
                rho = math.sqrt(qx * qx + qy * qy + qz * qz)
                in_range = lo <= axial <= hi and rho > 0.0
                if refresh:
                    # The same margin along the axis as towards the surface: a sphere just
                    # beyond an end at a refresh may enter the range before the next one
                    # (colza's candidate test likewise reaches a skin beyond the ends).
                    margin = PATCH_RANGE_FACTOR * r
                    want = (lo - margin <= axial <= hi + margin and rho > 0.0
                            and (rc - rho - r) < margin)
                    if not want:
                        if i in active:
                            active.discard(i)
                            pst.pos = park
                        continue
                    active.add(i)
                if not in_range:
                    if rho > 0.0:  # beyond an end: wait at the end, out of the sphere's reach
                        end = lo if axial < lo else hi
                        s = (max(rc, rho + r) + PATCH_RIM_GAP_FACTOR * r) / rho
                        pst.pos = Vector3(o[0] + end * a[0] + s * qx, o[1] + end * a[1] + s * qy,
                                          o[2] + end * a[2] + s * qz)
                    else:
                        pst.pos = park
                    continue
                s = rc / rho
                pst.pos = Vector3(o[0] + axial * a[0] + s * qx, o[1] + axial * a[1] + s * qy,
                                  o[2] + axial * a[2] + s * qz)

    def check_patches(self):
        """Self-check of the patch method: real interactions between a patch and a sphere
        other than its owner (must stay 0)."""
        owner = {}
        for cw in self.patch_walls:
            for i, rec in cw["patches"].items():
                owner[rec[0]] = i
        foreign = 0
        for inter in O.interactions:
            if not inter.isReal:
                continue
            for a, b in ((inter.id1, inter.id2), (inter.id2, inter.id1)):
                if a in owner and owner[a] != b:
                    foreign += 1
        return foreign

    def cylinder_force(self, cw):
        f = Vector3(0, 0, 0)
        for i in cw["active"]:
            f += O.forces.f(cw["patches"][i][0])
        return f

    def advance_cylinders(self):
        """After the step: the cylinder axis point moves like colza's wall origin."""
        dt = O.dt
        for cw in self.patch_walls:
            v = cw["velocity"]
            if v[0] != 0.0 or v[1] != 0.0 or v[2] != 0.0:
                o = cw["origin"]
                cw["origin"] = [o[0] + dt * v[0], o[1] + dt * v[1], o[2] + dt * v[2]]

    def wall_origin(self, k):
        w = self.walls[k]
        if w["kind"] == "box":
            return O.bodies[w["body"]].state.pos
        return Vector3(*w["origin"])

    def wall_force(self, k):
        w = self.walls[k]
        if w["kind"] == "box":
            return O.forces.f(w["body"])
        return self.cylinder_force(w)

    # ---- bonds -----------------------------------------------------------------------
    def bond(self, inter):
        ct = self.c["contact"]
        ph = inter.phys
        ph.cohesionBroken = False
        ph.normalAdhesion = ct["normal_strength"]
        ph.shearAdhesion = ct["shear_strength"]
        ph.fragile = True
        ph.cohesionDisablesFriction = True

    def install_bonds_if(self, *moments):
        """Installs bonds when the config's bond slot is contact_bond and its bond_install is one
        of `moments` (colza's scenarios do the same check); returns the number installed."""
        ct = self.c["contact"]
        if ct["bond"] == "contact_bond" and ct["bond_install"] in moments:
            return self.install_bonds()
        return 0

    def install_bonds(self):
        """colza's install_bonds: every particle pair with overlap >= -bond_gap is bonded
        (a pair within the gap becomes a bonded contact now)."""
        gap = self.c["contact"]["bond_gap"]
        n = 0
        pos = [O.bodies[i].state.pos for i in self.particles]
        rad = [O.bodies[i].shape.radius for i in self.particles]
        rmax = max(rad) if rad else 0.0
        # uniform grid of cell 2 rmax + gap
        cell = 2.0 * rmax + gap
        grid = {}
        for k, x in enumerate(pos):
            grid.setdefault((int(math.floor(x[0] / cell)), int(math.floor(x[1] / cell)),
                             int(math.floor(x[2] / cell))), []).append(k)
        for k, x in enumerate(pos):
            cx, cy, cz = (int(math.floor(x[0] / cell)), int(math.floor(x[1] / cell)), int(math.floor(x[2] / cell)))
            for dx in (-1, 0, 1):
                for dy in (-1, 0, 1):
                    for dz in (-1, 0, 1):
                        for m in grid.get((cx + dx, cy + dy, cz + dz), []):
                            if m <= k:
                                continue
                            overlap = rad[k] + rad[m] - (pos[m] - x).norm()
                            if overlap < -gap:
                                continue
                            i1, i2 = self.particles[k], self.particles[m]
                            inter = O.interactions[i1, i2] if O.interactions.has(i1, i2) else None
                            if inter is None or not inter.isReal:
                                inter = utils.createInteraction(i1, i2)
                            self.bond(inter)
                            n += 1
        self.bonded_at_start = n
        return n

    def bond_matchmakers(self):
        """on_new_contacts: normalAdhesion = normalCohesion(mat1, mat2) min(R1, R2)^2, so the
        per-pair value Cn / min(R1, R2)^2 gives Cn (up to rounding)."""
        ct = self.c["contact"]
        nm, sm = [], []
        items = list(self.materials.items())
        for (r1, m1) in items:
            for (r2, m2) in items:
                rmin = min(r1, r2)
                nm.append((m1, m2, ct["normal_strength"] / (rmin * rmin)))
                sm.append((m1, m2, ct["shear_strength"] / (rmin * rmin)))
        return MatchMaker(matches=nm, algo="val", val=0.0), MatchMaker(matches=sm, algo="val", val=0.0)

    def fix_new_bonds(self):
        """on_new_contacts: YADE's Ip2 leaves cohesionDisablesFriction False; set it after
        the first step of each new bond (exact unless a new bond exceeds Cs in that step)."""
        for inter in O.interactions:
            ph = inter.phys
            if ph is not None and isinstance(ph, CohFrictPhys) and not ph.cohesionBroken:
                ph.cohesionDisablesFriction = True

    # ---- engines ---------------------------------------------------------------------
    def build_engines(self, recorder_command, extra_after_law=None):
        integ = self.c["integration"]
        ct = self.c["contact"]
        on_new = ct["bond"] == "contact_bond" and ct["bond_install"] == "on_new_contacts"
        if self.patch_walls:
            self._make_patches()
        ip2_coh = Ip2_CohFrictMat_CohFrictMat_CohFrictPhys(setCohesionNow=False, setCohesionOnNewContacts=on_new)
        if on_new:
            ip2_coh.normalCohesion, ip2_coh.shearCohesion = self.bond_matchmakers()
        engines = [ForceResetter()]
        if self.patch_walls:
            engines.append(PyRunner(command="MODEL.update_patches()", iterPeriod=1, initRun=True, label="patches"))
        if ct["hertz"]:
            # Sphere-sphere only (add_wall refuses walls). ScGeom with colza's kinematics
            # (avoidGranularRatcheting=False: lever arms c - x_i); no viscous damping (betan,
            # betas unset = 0), no adhesion, no moment.
            loop = InteractionLoop(
                [Ig2_Sphere_Sphere_ScGeom(avoidGranularRatcheting=False)],
                [Ip2_FrictMat_FrictMat_MindlinPhys()],
                [Law2_ScGeom_MindlinPhys_Mindlin(includeAdhesion=False, includeMoment=False, calcEnergy=False,
                                                 label="law_pp")],
                label="loop")
        else:
            # Rolling resistance: the incremental moment (Mr carried into the new frame like the
            # shear force, then -kr w_b dt) at every contact, bonded or not.
            rolling = ct["rolling_enabled"]
            loop = InteractionLoop(
                [Ig2_Sphere_Sphere_ScGeom6D(avoidGranularRatcheting=False), Ig2_Box_Sphere_ScGeom()],
                [ip2_coh,
                 Ip2_FrictMat_FrictMat_FrictPhys(kn=MatchMaker(algo="val", val=self.kn_pw),
                                                 ks=MatchMaker(algo="val", val=self.ks_pw),
                                                 frictAngle=MatchMaker(algo="val", val=math.atan(self.mu_pw)))],
                [Law2_ScGeom6D_CohFrictPhys_CohesionMoment(useIncrementalForm=rolling, always_use_moment_law=rolling,
                                                           label="law_pp"),
                 Law2_ScGeom_FrictPhys_CundallStrack(label="law_pw")],
                label="loop")
        engines += [
            InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Box_Aabb()], avoidSelfInteractionMask=AVOID_SELF,
                                  label="collider"),
            loop,
        ]
        if on_new:
            engines.append(PyRunner(command="MODEL.fix_new_bonds()", iterPeriod=1, initRun=True, label="bondfix"))
        engines.append(PyRunner(command=recorder_command, iterPeriod=1, initRun=True, label="recorder"))
        engines.append(NewtonIntegrator(damping=integ["damping"], gravity=Vector3(*integ["gravity"]), label="newton"))
        if self.patch_walls:
            engines.append(PyRunner(command="MODEL.advance_cylinders()", iterPeriod=1, initRun=True, label="cylmove"))
        O.engines = engines

    # ---- counts ----------------------------------------------------------------------
    def counts(self):
        """Touching contacts (particle-particle + particle-wall) and intact bonds, as colza."""
        contacts = 0
        bonds = 0
        for inter in O.interactions:
            if not inter.isReal:
                continue
            contacts += 1
            ph = inter.phys
            if isinstance(ph, CohFrictPhys) and not ph.cohesionBroken:
                bonds += 1
        return contacts, bonds


def engine_seconds(labels):
    """Sum of execTime (ns) of the engines with these labels, in seconds (O.timingEnabled)."""
    t = 0
    for e in O.engines:
        if e.label in labels:
            t += e.execTime
    return t * 1e-9


def write_csv(path, names, rows):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(",".join(names) + "\n")
        for r in rows:
            f.write(",".join(repr(float(v)) for v in r) + "\n")
    os.replace(tmp, path)


def write_json(path, data):
    import json
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        json.dump(data, f, indent=2, sort_keys=True)
        f.write("\n")
    os.replace(tmp, path)


def fail(msg):
    sys.stderr.write("colza_yade: error: " + msg + "\n")
    sys.exit(2)
