# YADE counterpart of `colza run shear --config CONFIG --normal-stress PA --out OUTDIR`
# started from a settled packing (shear_box.packing_file), as in the cross-check:
#
#   yade -n -j 1 -x yade-scripts/run_shear.py CONFIG OUTDIR --normal-stress PA
#
# Protocol (colza's src/scenario/shear_box.cpp, run_shear_load, with a packing file):
#   * every sphere of the packing, at rest (no discarding: colza cut the sample when it made
#     the packing);
#   * the eleven box walls of build_shear_box as zero-thickness Boxes (colza_yade.py: the
#     exact rectangle geometry, contact point in the middle of the overlap); the upper sides
#     reach up to shear_box.generation_height, as in colza;
#   * the pressure plate: a rectangle length x width at the top of the highest sphere,
#     facing down;
#   * bonds: after_settling before consolidation, before_loading when shearing starts;
#   * consolidation: every step, between the force computation and the integration (a
#     PyRunner just before NewtonIntegrator), the plate's speed towards the particles is
#       v = relaxation (F_target - F) / (k_plate dt),  k_plate = Kn_pw max(1, plate contacts),
#     clamped to +-servo_max_speed, with F = O.forces.f(plate).z (contact forces of this
#     step) and the contacts counted on the plate's real interactions; "held" = relative
#     force error < consolidation_tolerance and |v| < consolidation_plate_speed, for
#     consolidation_window s of simulated time (or stop at consolidation_max_time);
#   * shearing: the six lower-half walls move at shear_speed in +x until the offset reaches
#     shear_displacement, the servo goes on; shear force = -(sum of the x forces of the
#     particles on the lower-half walls); shear strength = mean shear stress over EVERY
#     step whose offset lies in the strength window; mean normal stress over every step.
# Writes OUTDIR/curve.csv with colza's columns (a row every record_interval shearing steps
# and at the end) and OUTDIR/summary.json.
import builtins
import math
import os
import sys
import time
import tomllib

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))  # yade -x: argv[0] is this script
import colza_yade as cy  # noqa: E402

# colza's ShearBoxSpec defaults (src/config/run_config.hpp)
SHEAR_BOX_DEFAULTS = {
    "length": 0.200, "width": 0.200, "height": 0.080, "shear_plane": 0.040, "rim_length": 0.040,
    "generation_height": 0.200, "shear_speed": 0.3 / 60.0, "shear_displacement": 0.030,
    "strength_window_start": 0.020, "strength_window_end": 0.030, "servo_relaxation": 0.5,
    "servo_max_speed": 0.05, "consolidation_tolerance": 0.01, "consolidation_window": 0.02,
    "consolidation_plate_speed": 1e-4, "consolidation_max_time": 2.0, "record_interval": 100,
}

COLUMNS = ["time", "shear_displacement", "shear_force", "shear_stress", "normal_stress", "plate_height", "dilatancy",
           "contacts", "bonds"]


def read_shear_config(path):
    """colza_yade.read_config knows the oedometer and scenes; the particle, wall, contact and
    integration sections (with colza's defaults) are read by it from the same document
    presented as a scene, and [shear_box] here."""
    with open(path, "rb") as f:
        doc = tomllib.load(f)
    declared = doc.get("scenario", "shear")
    if declared != "shear":
        raise cy.ConfigError(f'{path}: this file is for scenario "{declared}", not "shear"')
    common = {k: v for k, v in doc.items() if k not in ("shear_box", "sample", "seed", "scenario")}
    common["scenario"] = "scene"
    common["scene"] = {"steps": 0}
    load = cy.tomllib.load
    cy.tomllib.load = lambda f: common
    try:
        c = cy.read_config(path, "scene")
    finally:
        cy.tomllib.load = load
    b = dict(SHEAR_BOX_DEFAULTS)
    for k, v in doc.get("shear_box", {}).items():
        if k in ("normal_stresses",):
            continue
        if k == "packing_file":
            b[k] = v
        elif k == "edge_contacts":
            # YADE's boxes touch a sphere each with its own edges, as colza's "per_wall";
            # colza's "per_surface" (open edges at the seams and rim corners) has no YADE form.
            if v != "per_wall":
                raise cy.ConfigError(f'shear_box.edge_contacts = "{v}": YADE\'s boxes give one contact per '
                                     'plate, which is "per_wall" only')
        elif k == "preconsolidation_stress":
            # colza's alone: this script consolidates once, at the load it shears at.
            if float(v) != 0.0:
                raise cy.ConfigError("shear_box.preconsolidation_stress: overconsolidation is not in the YADE shear "
                                     "script (yade-scripts/run_shear.py consolidates at the shearing load only)")
        elif k in b:
            b[k] = int(v) if k == "record_interval" else float(v)
        else:
            raise cy.ConfigError(f"unknown key shear_box.{k}")
    pf = b.get("packing_file", "")
    if not pf:
        raise cy.ConfigError("the YADE shear box starts from a settled packing: set shear_box.packing_file")
    base = os.path.dirname(os.path.abspath(path))
    b["packing_file"] = pf if os.path.isabs(pf) else os.path.join(base, pf)
    c["shear_box"] = b
    return c


def rect(center, normal, axis_u, half_u, half_v):
    return {"shape": "rectangle", "origin": list(center), "normal": list(normal), "axis_u": list(axis_u),
            "half_u": half_u, "half_v": half_v, "velocity": [0.0, 0.0, 0.0]}


def box_walls(b, wall_top):
    """build_shear_box: (lower walls, upper walls), same order and positions."""
    L, W, sp, rl = b["length"], b["width"], b["shear_plane"], b["rim_length"]
    ex, ey, ez = [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]
    mx, my, mz = [-1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0]
    lower = [
        rect((L / 2, W / 2, 0), ez, ex, L / 2, W / 2),            # lower_bottom
        rect((0, W / 2, sp / 2), ex, ey, W / 2, sp / 2),          # lower_trailing
        rect((L, W / 2, sp / 2), mx, ey, W / 2, sp / 2),          # lower_leading
        rect((L / 2, 0, sp / 2), ey, ex, L / 2, sp / 2),          # lower_front
        rect((L / 2, W, sp / 2), my, ex, L / 2, sp / 2),          # lower_back
        rect((-rl / 2, W / 2, sp), ez, ex, rl / 2, W / 2),        # lower_rim
    ]
    uh, uz = 0.5 * (wall_top - sp), 0.5 * (wall_top + sp)
    upper = [
        rect((0, W / 2, uz), ex, ey, W / 2, uh),                  # upper_trailing
        rect((L, W / 2, uz), mx, ey, W / 2, uh),                  # upper_leading
        rect((L / 2, 0, uz), ey, ex, L / 2, uh),                  # upper_front
        rect((L / 2, W, uz), my, ex, L / 2, uh),                  # upper_back
        rect((L + rl / 2, W / 2, sp), mz, ex, rl / 2, W / 2),     # upper_rim
    ]
    return lower, upper


def count_outside(m, b, offset, plate_z):
    """colza's count_outside: centres that left the box (half a radius of tolerance)."""
    n = 0
    for i in m.particles:
        body = O.bodies[i]
        x = body.state.pos
        tol = 0.5 * body.shape.radius
        lower = x[2] < b["shear_plane"]
        x0 = offset if lower else 0.0
        inside = (-tol < x[1] < b["width"] + tol and -tol < x[2] < plate_z + tol
                  and x0 - tol < x[0] < x0 + b["length"] + tol)
        if not inside:
            n += 1
    return n


def main(argv):
    args = list(argv)
    sigma_target = None
    if "--normal-stress" in args:
        k = args.index("--normal-stress")
        if k + 1 >= len(args):
            cy.fail("--normal-stress needs a value (Pa)")
        sigma_target = float(args[k + 1])
        del args[k:k + 2]
    if len(args) != 2 or sigma_target is None or not sigma_target > 0.0:
        cy.fail("usage: yade -n -j 1 -x run_shear.py CONFIG OUTDIR --normal-stress PA")
    config_path, outdir = args
    try:
        c = read_shear_config(config_path)
        packing = cy.read_packing(c["shear_box"]["packing_file"])
    except (cy.ConfigError, OSError, KeyError, ValueError) as e:
        cy.fail(f"{config_path}: {e}")
    b = c["shear_box"]
    area = b["length"] * b["width"]
    m = cy.Model(c)
    for (x, r) in packing:
        m.add_particle(x, r)
    if not packing:
        cy.fail("the packing is empty")
    top = max(x[2] + r for (x, r) in packing)
    lower_specs, upper_specs = box_walls(b, b["generation_height"])
    for w in lower_specs + upper_specs:
        m.add_wall(w)
    lower = [m.walls[k]["body"] for k in range(len(lower_specs))]
    m.add_wall(rect((b["length"] / 2, b["width"] / 2, top), [0.0, 0.0, -1.0], [1.0, 0.0, 0.0],
                    b["length"] / 2, b["width"] / 2))
    plate = m.walls[-1]["body"]
    builtins.MODEL = m

    dt = c["integration"]["time_step"]
    target_force = sigma_target * area
    relax, vmax = b["servo_relaxation"], b["servo_max_speed"]
    kn_plate = m.kn_pw
    s = {"phase": "consolidation", "t": 0.0, "held_since": -1.0, "consolidated": False, "cons_steps": 0,
         "shear_steps": 0, "x0": 0.0, "z0": 0.0, "ts": 0.0, "sigma_sum": 0.0, "sigma_err_sum": 0.0,
         "window_sum": 0.0, "window_count": 0, "peak": 0.0, "done": False}
    rows = []
    plate_body = O.bodies[plate]
    plate_state = plate_body.state
    lower_bottom_state = O.bodies[lower[0]].state

    def control_plate():
        """PlateServo::advance_speed on the forces of this step; returns (F, v_z)."""
        f = O.forces.f(plate)[2]
        count = 0
        for inter in plate_body.intrs():
            if inter.isReal:
                count += 1
        k = kn_plate * max(1, count)
        v = relax * (target_force - f) / (k * dt)
        v = min(max(v, -vmax), vmax)
        plate_state.vel = cy.Vector3(0.0, 0.0, -v)
        return f, -v

    def step():
        if s["phase"] == "consolidation":
            f, vz = control_plate()
            error = abs(f - target_force) / target_force
            held = error < b["consolidation_tolerance"] and abs(vz) < b["consolidation_plate_speed"]
            if not held:
                s["held_since"] = -1.0
            elif s["held_since"] < 0.0:
                s["held_since"] = s["t"]
            s["t"] += dt  # colza's world.time after finish_step
            s["cons_steps"] += 1
            if s["held_since"] >= 0.0 and s["t"] - s["held_since"] >= b["consolidation_window"]:
                s["consolidated"] = True
                O.pause()  # YADE finishes this step (NewtonIntegrator) and stops
            elif s["t"] >= b["consolidation_max_time"]:
                O.pause()
            return
        # shearing
        control_plate()
        offset = lower_bottom_state.pos[0] - s["x0"]
        fx = 0.0
        for i in lower:
            fx += O.forces.f(i)[0]
        shear_force = -fx
        tau = shear_force / area
        sigma = O.forces.f(plate)[2] / area
        s["sigma_sum"] += sigma
        s["sigma_err_sum"] += abs(sigma - sigma_target) / sigma_target
        s["peak"] = max(s["peak"], tau)
        if b["strength_window_start"] <= offset <= b["strength_window_end"]:
            s["window_sum"] += tau
            s["window_count"] += 1
        done = offset >= b["shear_displacement"]
        if s["shear_steps"] % b["record_interval"] == 0 or done:
            pz = plate_state.pos[2]
            contacts, bonds = m.counts()
            rows.append([s["t"] - s["ts"], offset, shear_force, tau, sigma, pz, pz - s["z0"], contacts, bonds])
        s["t"] += dt
        s["shear_steps"] += 1
        if done:
            s["done"] = True
            O.pause()

    builtins.SHEAR_STEP = step
    m.build_engines("SHEAR_STEP()")
    installed = m.install_bonds_if("after_settling")

    O.timingEnabled = True
    t0 = time.perf_counter()
    O.run()
    O.wait()
    consolidation_time = s["t"]
    installed += m.install_bonds_if("before_loading")
    for i in lower:
        O.bodies[i].state.vel = cy.Vector3(b["shear_speed"], 0.0, 0.0)
    s["x0"] = lower_bottom_state.pos[0]
    s["z0"] = plate_state.pos[2]
    s["ts"] = s["t"]
    s["phase"] = "shearing"
    O.run()
    O.wait()
    wall = time.perf_counter() - t0

    n = len(m.particles)
    steps = s["cons_steps"] + s["shear_steps"]
    offset = lower_bottom_state.pos[0] - s["x0"]
    outside = count_outside(m, b, offset, plate_state.pos[2])
    os.makedirs(outdir, exist_ok=True)
    cy.write_csv(os.path.join(outdir, "curve.csv"), COLUMNS, rows)
    python_s = cy.engine_seconds({"recorder", "bondfix"})
    shear_steps = max(s["shear_steps"], 1)
    strength = s["window_sum"] / s["window_count"] if s["window_count"] else 0.0
    cy.write_json(os.path.join(outdir, "summary.json"), {
        "code": "yade", "scenario": "shear", "config": os.path.abspath(config_path),
        "particles": n, "normal_stress": sigma_target, "shear_strength": strength,
        "strength_window": [b["strength_window_start"], b["strength_window_end"]],
        "peak_shear_stress": s["peak"], "mean_normal_stress": s["sigma_sum"] / shear_steps,
        "mean_normal_stress_error": s["sigma_err_sum"] / shear_steps, "consolidated": s["consolidated"],
        "consolidation_time": consolidation_time, "consolidation_steps": s["cons_steps"],
        "shear_steps": s["shear_steps"], "particles_outside": outside, "bonds_installed": installed,
        "steps": steps, "dt": O.dt, "wall_seconds": wall,
        "particle_steps_per_second": n * steps / wall if wall > 0 else 0.0,
        "python_engine_seconds": python_s,
        "engine_particle_steps_per_second": n * steps / (wall - python_s) if wall > python_s else 0.0,
    })
    print(f"yade shear: {n} particles, sigma {sigma_target * 1e-3:.2f} kPa: consolidated {s['consolidated']} after "
          f"{consolidation_time:.4f} s, shear strength {strength * 1e-3:.3f} kPa, mean normal stress "
          f"{s['sigma_sum'] / shear_steps * 1e-3:.2f} kPa, {outside} outside, {steps} steps of {O.dt:.4g} s, "
          f"{wall:.2f} s wall, {n * steps / wall:.3g} particle-steps/s")


main(sys.argv[1:])
