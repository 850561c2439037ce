# YADE counterpart of `colza run scene --config CONFIG --out OUTDIR`.
#
#   yade -n -j 1 -x yade-scripts/run_scene.py CONFIG OUTDIR
#
# Reads the colza scene config (particles listed or from scene.packing_file, walls with
# prescribed velocities, a fixed number of steps), runs it in YADE with the mapping of
# colza_yade.py, and writes OUTDIR/series.csv with colza's columns (src/scenario/scene.hpp):
# step, time, per recorded particle k: pK_{x,y,z} x(t_n), pK_v{x,y,z} v(t_n - dt/2),
# pK_w{x,y,z}, pK_f{x,y,z} and pK_t{x,y,z} (contact force and torque of step n, no gravity);
# per wall w: wW_f{x,y,z} (force exerted by the particles on the wall) and wW_{x,y,z} (its
# origin); then contacts, bonds and the energies. YADE has no equivalent of colza's
# damping_dissipated, bond_break_lost, shear_break_released and wall_work bookkeeping: those columns are NaN;
# with Hertz-Mindlin slip_dissipated is NaN too (YADE's frictionDissipation is another formula).
# The mechanisms' own columns of colza (engine/energy.hpp: elastic_rolling_energy after
# elastic_shear_energy, rolling_dissipated and shear_stiffness_change after wall_work, when
# rolling resistance or the Mindlin spring is on) are written as NaN.
# OUTDIR/summary.json holds the wall time and the particle-steps per second.
import builtins
import math
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))  # yade -x: argv[0] is this script
import colza_yade as cy  # noqa: E402


def scene_columns(particles, walls, rolling=False, mindlin=False):
    names = ["step", "time"]
    for k in particles:
        for q in ("", "v", "w", "f", "t"):
            for a in ("x", "y", "z"):
                names.append(f"p{k}_{q}{a}")
    for w in range(walls):
        for q in ("f", ""):
            for a in ("x", "y", "z"):
                names.append(f"w{w}_{q}{a}")
    names += ["contacts", "bonds", "kinetic_energy", "gravitational_energy", "elastic_normal_energy",
              "elastic_shear_energy"]
    if rolling:
        names.append("elastic_rolling_energy")
    names += ["slip_dissipated", "damping_dissipated", "bond_break_lost", "shear_break_released", "wall_work"]
    if rolling:
        names.append("rolling_dissipated")
    if mindlin:
        names.append("shear_stiffness_change")
    return names


def main(argv):
    if len(argv) != 2:
        cy.fail("usage: yade -n -j 1 -x run_scene.py CONFIG OUTDIR")
    config_path, outdir = argv
    try:
        c = cy.read_config(config_path, "scene")
    except (cy.ConfigError, OSError, KeyError, ValueError) as e:
        cy.fail(f"{config_path}: {e}")
    s = c["scene"]
    m = cy.Model(c)
    for p in s["particles"]:
        m.add_particle(p["position"], p["radius"], p["velocity"], p["angular_velocity"], p["fixed"])
    for w in s["walls"]:
        m.add_wall(w)
    builtins.MODEL = m

    total = s["steps"]
    interval = s["record_interval"]
    rec = s["record_particles"]
    rec_ids = [m.particles[k] for k in rec]
    rolling = c["contact"]["rolling"] != "none"
    mindlin = c["contact"]["hertz"]
    names = scene_columns(rec, len(m.walls), rolling, mindlin)
    rows = []
    g = c["integration"]["gravity"]
    laws = []

    def record():
        n = O.iter
        if n % interval != 0 and n + 1 != total:
            return
        row = [float(n), O.time]
        for i in rec_ids:
            st = O.bodies[i].state
            for v in (st.pos, st.vel, st.angVel, O.forces.f(i), O.forces.t(i)):
                row += [v[0], v[1], v[2]]
        for k in range(len(m.walls)):
            f = m.wall_force(k)
            o = m.wall_origin(k)
            row += [f[0], f[1], f[2], o[0], o[1], o[2]]
        contacts, bonds = m.counts()
        kin = grav = 0.0
        for i in m.particles:
            st = O.bodies[i].state
            kin += 0.5 * st.mass * st.vel.squaredNorm() + 0.5 * st.inertia[0] * st.angVel.squaredNorm()
            grav -= st.mass * (g[0] * st.pos[0] + g[1] * st.pos[1] + g[2] * st.pos[2])
        en = es = 0.0
        for inter in O.interactions:
            if not inter.isReal:
                continue
            ph = inter.phys
            if isinstance(ph, MindlinPhys):
                # Hertz: 8/15 E* sqrt(R*) un^(5/2) = 2/5 Fn un (ph.kn is the tangent stiffness);
                # shear: |Fs|^2 / (2 kt), kt the tangent 8 G* sqrt(R* un)
                en += 0.4 * ph.normalForce.norm() * inter.geom.penetrationDepth
                if ph.ks > 0.0:
                    es += 0.5 * ph.shearForce.squaredNorm() / ph.ks
            else:
                en += 0.5 * ph.normalForce.squaredNorm() / ph.kn
                es += 0.5 * ph.shearForce.squaredNorm() / ph.ks
        # Mindlin's frictionDissipation is another formula than colza's: NaN there
        slip = math.nan if c["contact"]["hertz"] else sum(law.plasticDissipation() for law in laws)
        row += [contacts, bonds, kin, grav, en, es] + ([math.nan] if rolling else [])
        row += [slip, math.nan, math.nan, math.nan, math.nan]
        row += ([math.nan] if rolling else []) + ([math.nan] if mindlin else [])
        rows.append(row)

    builtins.RECORD = record
    m.build_engines("RECORD()")
    loop = [e for e in O.engines if isinstance(e, InteractionLoop)][0]
    for law in loop.lawDispatcher.functors:
        laws.append(law)
        if not isinstance(law, Law2_ScGeom_MindlinPhys_Mindlin):
            law.traceEnergy = True  # slip dissipation, same bookkeeping as colza's slip_dissipated
    installed = m.install_bonds_if("before_loading", "after_settling")

    O.timingEnabled = True
    t0 = time.perf_counter()
    O.run(total, True)
    wall = time.perf_counter() - t0
    os.makedirs(outdir, exist_ok=True)
    cy.write_csv(os.path.join(outdir, "series.csv"), names, rows)
    n = len(m.particles)
    python_s = cy.engine_seconds({"patches", "recorder", "cylmove", "bondfix"})
    cy.write_json(os.path.join(outdir, "summary.json"), {
        "code": "yade", "scenario": "scene", "config": os.path.abspath(config_path),
        "particles": n, "walls": len(m.walls), "steps": total, "dt": O.dt,
        "bonds_installed": installed,
        "wall_seconds": wall, "particle_steps_per_second": n * total / wall if wall > 0 else 0.0,
        "python_engine_seconds": python_s,
        "engine_particle_steps_per_second": n * total / (wall - python_s) if wall > python_s else 0.0,
    })
    print(f"yade scene: {n} particles, {len(m.walls)} walls, {total} steps of {O.dt:.4g} s, {wall:.2f} s wall")


main(sys.argv[1:])
