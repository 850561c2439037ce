# YADE counterpart of `colza run oedometer --config CONFIG --out OUTDIR` started from a
# settled packing (oedometer.packing_file), as in the cross-check:
#
#   yade -n -j 1 -x yade-scripts/run_oedometer.py CONFIG OUTDIR
#
# Protocol (colza's src/scenario/oedometer.cpp with a packing file): spheres from the
# packing at rest, those whose top is above oedometer.cylinder_height discarded; bottom =
# plane z = 0; envelope = inner surface of a cylinder of radius cylinder_diameter / 2 from
# z = 0 to max(generation_height, cylinder_height) (exact, contact patches of
# colza_yade.py); piston = plane at the top of the highest sphere, facing down, moving down
# at piston_speed until the piston force reaches stop_force or the travel reaches
# max_piston_travel (checked every step, on the forces of that step). Bonds, if configured
# (before_loading / after_settling), on every pair with overlap >= -bond_gap at the start.
# Writes OUTDIR/curve.csv with colza's columns (time, piston_displacement, piston_force,
# contacts, bonds; a row every record_interval steps and at the stop) and OUTDIR/summary.json.
import builtins
import math
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))  # yade -x: argv[0] is this script
import colza_yade as cy  # noqa: E402


def main(argv):
    if len(argv) != 2:
        cy.fail("usage: yade -n -j 1 -x run_oedometer.py CONFIG OUTDIR")
    config_path, outdir = argv
    try:
        c = cy.read_config(config_path, "oedometer")
        packing = cy.read_packing(c["oedometer"]["packing_file"])
    except (cy.ConfigError, OSError, KeyError, ValueError) as e:
        cy.fail(f"{config_path}: {e}")
    o = c["oedometer"]
    m = cy.Model(c)
    kept = [(x, r) for (x, r) in packing if x[2] + r <= o["cylinder_height"]]
    for (x, r) in kept:
        m.add_particle(x, r)
    if not kept:
        cy.fail("no sphere is left below the rim")
    top = 0.0
    for (x, r) in kept:
        top = max(top, x[2] + r)
    m.add_wall({"shape": "plane", "origin": [0.0, 0.0, 0.0], "normal": [0.0, 0.0, 1.0], "velocity": [0.0, 0.0, 0.0]})
    m.add_wall({"shape": "cylinder", "origin": [0.0, 0.0, 0.0], "axis": [0.0, 0.0, 1.0],
                "radius": 0.5 * o["cylinder_diameter"], "axial_min": 0.0,
                "axial_max": max(o["generation_height"], o["cylinder_height"]), "velocity": [0.0, 0.0, 0.0]})
    m.add_wall({"shape": "plane", "origin": [0.0, 0.0, top], "normal": [0.0, 0.0, -1.0],
                "velocity": [0.0, 0.0, -o["piston_speed"]]})
    piston = m.walls[2]["body"]
    builtins.MODEL = m

    rows = []
    state = {"steps": 0, "stop": "", "max_force": 0.0}

    def record():
        n = O.iter
        pz = O.bodies[piston].state.pos[2]
        travel = top - pz
        force = O.forces.f(piston)[2]
        state["max_force"] = max(state["max_force"], force)
        if force >= o["stop_force"]:
            state["stop"] = "stop_force"
        elif travel >= o["max_piston_travel"]:
            state["stop"] = "max_piston_travel"
        stop = state["stop"] != ""
        if n % 500 == 0 or stop:
            state["foreign_patch_contacts"] = max(state.get("foreign_patch_contacts", 0), m.check_patches())
        if n % o["record_interval"] == 0 or stop:
            contacts, bonds = m.counts()
            rows.append([O.time, travel, force, contacts, bonds])
        if stop:
            state["steps"] = n + 1
            O.pause()

    builtins.RECORD = record
    m.build_engines("RECORD()")
    installed = m.install_bonds_if("before_loading", "after_settling")

    O.timingEnabled = True
    t0 = time.perf_counter()
    O.run()
    O.wait()
    wall = time.perf_counter() - t0
    os.makedirs(outdir, exist_ok=True)
    cy.write_csv(os.path.join(outdir, "curve.csv"), ["time", "piston_displacement", "piston_force", "contacts", "bonds"],
                 rows)
    n = len(m.particles)
    steps = state["steps"]
    python_s = cy.engine_seconds({"patches", "recorder", "cylmove", "bondfix"})
    cy.write_json(os.path.join(outdir, "summary.json"), {
        "code": "yade", "scenario": "oedometer", "config": os.path.abspath(config_path),
        "particles": n, "packing_height": top, "steps": steps, "dt": O.dt, "bonds_installed": installed,
        "stop_reason": state["stop"], "max_force": state["max_force"],
        "foreign_patch_contacts": state.get("foreign_patch_contacts", 0),
        "wall_seconds": wall, "particle_steps_per_second": n * steps / wall if wall > 0 else 0.0,
        "python_engine_seconds": python_s,
        "engine_particle_steps_per_second": n * steps / (wall - python_s) if wall > python_s else 0.0,
    })
    print(f"yade oedometer: {n} particles, {steps} steps of {O.dt:.4g} s, stop {state['stop']}, "
          f"max force {state['max_force']:.1f} N, {wall:.2f} s wall, {n * steps / wall:.3g} particle-steps/s")


main(sys.argv[1:])
