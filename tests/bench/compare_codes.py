#!/usr/bin/env python3
"""colza vs YADE vs LAMMPS on the paper's oedometer packing (issue 5 benchmark).

Prepares the settled oedometer packing once with colza (or takes --packing), then runs the
loading stage of the same packing in every code with the same fixed dt and the same number
of steps while the piston compresses at 500 mm/min, one thread each, and prints

    code, particles, steps, wall seconds, particle-steps/s, ratio to colza, peak memory

(wall seconds, rate and ratio of each code's best round, then its median rate and ratio).

The codes run in --repeat interleaved rounds (default 3) and each code's best round and
median are reported, with the ratios round by round: this class of machine (2 shared
cores) slows down by up to 2x for minutes at a time, and the longest run (YADE) would
otherwise catch more of it than the others.

Wall seconds are the time of the stepping loop only (colza: the loading stage clock in
summary.json; LAMMPS: "Loop time"; YADE: O.run(N, True) timed inside the script); peak
memory is the whole process (/usr/bin/time -v, maximum resident set size).

Physics is matched as closely as the codes allow (it is a speed benchmark, not a
cross-check): linear springs with tangential history and Coulomb friction, contact
stiffnesses Kn = kn/2 (colza's series rule for one material), walls with the series rule of
particle and wall stiffness; colza and YADE use local damping 0.7, LAMMPS has no local
damping (pair gran/hooke/history with zero viscous damping). YADE's cylinder is a facet
cylinder (YADE has no analytic cylinder wall for spheres); LAMMPS uses fix wall/gran
zcylinder and a moving fix wall/gran/region plane for the piston.

YADE runs twice per round, both times computing colza's sphere-sphere law with colza's
stiffnesses (one particle material per distinct radius, young = Kn / R: physics.md section
6). Row "YADE" is YADE's cheapest form of it (FrictMat, Ig2_Sphere_Sphere_ScGeom,
Law2_ScGeom_FrictPhys_CundallStrack); row "YADE CohFrict" is the form the cross-check uses,
which also carries bonds, twist and bending (CohFrictMat, Ig2_Sphere_Sphere_ScGeom6D,
Law2_ScGeom6D_CohFrictPhys_CohesionMoment; yade-scripts/colza_yade.py). The two agree to
rounding on this packing (velocities 1e-11 m/s apart after 100 steps, where they reach
9e-3 m/s; session 12 of tests/bench/PERFORMANCE_LOG.md), so row "YADE" is the fair
comparison; --skip-yade-cohfrict leaves the slower form out.

colza's force loops are compiled once per instruction set (src/core/kernel_isa.hpp); row
"colza" runs the copy colza chooses on this CPU, and --isa adds a row per copy forced through
$COLZA_ISA (e.g. --isa generic,avx2,avx512), --also another colza binary (e.g. an older or a
-march=native build: --also native=/path/to/colza). The CPU model, the copy each row ran and
what it was built for are printed from colza's summary.json.

Neither YADE nor LAMMPS is needed by the build or the tests: this script is run by hand,
e.g.  python3 tests/bench/compare_codes.py --colza build/src/colza --steps 20000
"""
import argparse
import json
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import time

YADE_SCRIPTS = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "yade-scripts"))
sys.path.insert(0, YADE_SCRIPTS)
from colza_packing import read_packing  # noqa: E402  (pure Python, no YADE needed)

# Defaults of the oedometer scenario (src/config/run_config.hpp).
DENSITY = 1250.0
KN, KS, MU = 437e3, 100e3, 0.20
KN_W, KS_W, MU_W = 4000e3, 1000e3, 0.23
CYL_R = 0.050
PISTON_SPEED = 0.5 / 60.0
SKIN = 0.5e-3
DAMPING = 0.7


def series(a, b):
    return a * b / (a + b)


def ensure_installed(binary, package):
    """True when `binary` is on PATH, installing Debian's `package` first if it is missing
    (apt-get as root, or through sudo). Neither code is needed by colza's build or tests."""
    if shutil.which(binary):
        return True
    apt = ["apt-get", "install", "-y", "--no-install-recommends", package]
    if os.geteuid() != 0:
        if not shutil.which("sudo"):
            return False
        apt = ["sudo"] + apt
    print(f"{binary} not found: installing the Debian package {package} ...", file=sys.stderr)
    subprocess.run(apt, env=dict(os.environ, DEBIAN_FRONTEND="noninteractive"), check=False)
    return shutil.which(binary) is not None


def peak_rss_kb(stderr_text):
    m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", stderr_text)
    return int(m.group(1)) if m else None


def run_timed(cmd, cwd, log_path, env=None):
    """Runs cmd under /usr/bin/time -v; returns (stdout, stderr, peak RSS kB, wall s)."""
    t0 = time.perf_counter()
    p = subprocess.run(["/usr/bin/time", "-v"] + cmd, cwd=cwd, capture_output=True, text=True, env=env)
    wall = time.perf_counter() - t0
    with open(log_path, "w") as f:
        f.write(" ".join(cmd) + "\n--- stdout\n" + p.stdout + "\n--- stderr\n" + p.stderr)
    if p.returncode != 0:
        sys.exit(f"command failed ({p.returncode}), see {log_path}: {' '.join(cmd)}")
    return p.stdout, p.stderr, peak_rss_kb(p.stderr), wall


def prepare_packing(colza, work):
    packing = os.path.join(work, "prep", "packing.txt")
    if os.path.exists(packing):
        return packing
    print("preparing the settled oedometer packing with colza (once; several minutes) ...", flush=True)
    subprocess.run([colza, "run", "oedometer", "--out", os.path.join(work, "prep"), "--force"], check=True,
                   stdout=subprocess.DEVNULL)
    return packing


def run_colza(colza, packing, dt, steps, work, threads, isa=None, code="colza"):
    """One loading run; `isa` forces a copy of the force loops ($COLZA_ISA), None lets colza choose."""
    out = os.path.join(work, "colza")
    # Loading stops at the first step whose piston travel reaches max_piston_travel: with
    # travel(k) = v k dt that is step k = steps - 1 (counted from 0), i.e. `steps` steps.
    travel = PISTON_SPEED * dt * (steps - 1.5)
    # The stop force stays the paper's 30 kN: 20000 steps reach 3.8 N on this packing, so the
    # travel ends the run (checked below). (1e12 N, used before, drew the unit-slip warnings.)
    cmd = [colza, "run", "oedometer", "--threads", str(threads), "--set", f"oedometer.packing_file={packing}",
           "--set", f"integration.time_step={dt!r}",
           "--set", f"oedometer.max_piston_travel={travel!r}", "--out", out, "--force"]
    env = dict(os.environ)
    env.pop("COLZA_ISA", None)
    if isa:
        env["COLZA_ISA"] = isa
    _, err, rss, _ = run_timed(cmd, work, os.path.join(work, "colza.log"), env=env)
    s = json.load(open(os.path.join(out, "summary.json")))
    if s["stop_reason"] != "max_piston_travel":
        sys.exit(f"colza's loading stopped by {s['stop_reason']}, not after the {steps} steps asked: fewer steps")
    stage = next(st for st in s["stages"] if st["name"] == "loading")
    # Older colza binaries do not record their force loops' copy or the CPU.
    kernels = (f"{s['kernel_isa']} copy, built for {s['kernel_isa_built_for']}" if "kernel_isa" in s
               else "(no kernel_isa in its summary.json: one copy, built before run-time dispatch)")
    return dict(code=code, particles=s["particles"], steps=stage["steps"], seconds=stage["wall_seconds"], rss=rss,
                kernels=kernels, report=s.get("kernel_isa_report"), cpu=s.get("cpu_model"))


def write_lammps(path_dir, spheres, dt, steps):
    top = max(z + r for (_, _, z, r) in spheres)
    with open(os.path.join(path_dir, "packing.data"), "w") as f:
        f.write("colza oedometer packing\n\n%d atoms\n1 atom types\n\n" % len(spheres))
        f.write("-0.06 0.06 xlo xhi\n-0.06 0.06 ylo yhi\n-0.005 %.6f zlo zhi\n\nAtoms # sphere\n\n" % (top + 0.01))
        for k, (x, y, z, r) in enumerate(spheres):
            f.write("%d 1 %.17g %.17g %.17g %.17g %.17g\n" % (k + 1, 2 * r, DENSITY, x, y, z))
    kn, kt = series(KN, KN), series(KS, KS)
    knw, ktw = series(KN, KN_W), series(KS, KS_W)
    wall = f"hooke/history {knw!r} {ktw!r} 0.0 0.0 {MU_W} 1"
    with open(os.path.join(path_dir, "in.oedometer"), "w") as f:
        f.write(f"""# generated by tests/bench/compare_codes.py
units si
atom_style sphere
atom_modify map array
boundary f f f
newton off
comm_modify vel yes
read_data packing.data
pair_style gran/hooke/history {kn!r} {kt!r} 0.0 0.0 {MU} 1
pair_coeff * *
neighbor {SKIN} bin
neigh_modify delay 0 every 1 check yes
timestep {dt!r}
fix integ all nve/sphere
fix grav all gravity 9.81 vector 0 0 -1
fix bottom all wall/gran {wall} zplane 0.0 NULL
fix envelope all wall/gran {wall} zcylinder {CYL_R}
variable dz equal -{PISTON_SPEED * dt!r}*elapsed
region piston plane 0.0 0.0 {top!r} 0.0 0.0 -1.0 side in move NULL NULL v_dz units box
fix piston all wall/gran/region {wall} region piston
thermo_modify lost ignore
thermo 5000
run {steps}
""")


def run_lammps(spheres, dt, steps, work):
    d = os.path.join(work, "lammps")
    os.makedirs(d, exist_ok=True)
    write_lammps(d, spheres, dt, steps)
    env_cmd = ["env", "OMP_NUM_THREADS=1", "lmp", "-in", "in.oedometer", "-log", "log.lammps"]
    out, err, rss, wall = run_timed(env_cmd, d, os.path.join(work, "lammps.log"))
    m = re.search(r"Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps with (\d+) atoms", out)
    if not m:
        sys.exit(f"could not read the LAMMPS loop time, see {work}/lammps.log")
    return dict(code="LAMMPS", particles=int(m.group(3)), steps=int(m.group(2)), seconds=float(m.group(1)), rss=rss)


# YADE's sphere-sphere law per row (physics.md section 6): both compute colza's unbonded law
# with colza's stiffnesses, one particle material per distinct radius (young = Kn / R, so
# that 2 E1 R1 E2 R2 / (E1 R1 + E2 R2) = Kn for every pair; poisson = Ks / Kn).
#   "YADE": YADE's cheapest form (FrictMat, ScGeom, FrictPhys, CundallStrack).
#   "YADE CohFrict": the cross-check's form (yade-scripts/colza_yade.py), which also carries
#   bonds, twist and bending (CohFrictMat, ScGeom6D, CohFrictPhys, CohesionMoment).
# Each entry: (material constructor and arguments, Ig2 for two spheres, extra Ip2, extra Law2).
YADE_LAWS = {
    "YADE": ("FrictMat", "", "Ig2_Sphere_Sphere_ScGeom(avoidGranularRatcheting=False)", "", ""),
    "YADE CohFrict": (
        "CohFrictMat", ", isCohesive=True, momentRotationLaw=False, alphaKr=0.0, alphaKtw=0.0, etaRoll=-1.0, "
        "etaTwist=-1.0, fragile=True", "Ig2_Sphere_Sphere_ScGeom6D(avoidGranularRatcheting=False)",
        "Ip2_CohFrictMat_CohFrictMat_CohFrictPhys(setCohesionNow=False, setCohesionOnNewContacts=False), ",
        "Law2_ScGeom6D_CohFrictPhys_CohesionMoment(useIncrementalForm=False, always_use_moment_law=False), "),
}


def yade_wall_entity(pair, particle):
    """E_w R for the wall material: YADE gives a sphere-wall pair 2 a b / (a + b) with
    a = E_s R (= the particle-particle value `particle`) and b = E_w R; solved for the
    pair value `pair` (colza's series rule), exact at R = r_mean."""
    return pair * particle / (2.0 * particle - pair)


def write_yade(path, packing, dt, steps, law):
    material, material_extra, ig2_spheres, ip2_spheres, law2_spheres = YADE_LAWS[law]
    kn_pp, ks_pp = series(KN, KN), series(KS, KS)
    wall_kn = yade_wall_entity(series(KN, KN_W), kn_pp)
    wall_ks = yade_wall_entity(series(KS, KS_W), ks_pp)
    top_expr = "max(s[2] + s[3] for s in spheres)"
    r_mean = "sum(s[3] for s in spheres) / len(spheres)"
    with open(path, "w") as f:
        f.write(f"""# generated by tests/bench/compare_codes.py (run with: yade -n -j 1 -x this.py)
import math, sys, time
sys.path.insert(0, {YADE_SCRIPTS!r})
from colza_packing import read_packing
spheres = read_packing({packing!r})
top = {top_expr}
r_mean = {r_mean}
# Walls: Kn_w, Ks_w exact for a sphere of radius r_mean, within a few per cent for the others.
# Their friction is min(atan {MU}, atan {MU_W}) = atan {MU}: YADE's Ip2 takes the smaller angle.
wmat = O.materials.append(FrictMat(young={wall_kn!r} / r_mean, poisson={wall_ks / wall_kn!r},
                                   frictionAngle=math.atan({MU_W}), density=1000.0))
per_radius = {{}}
for (x, y, z, r) in spheres:
    if r not in per_radius:
        per_radius[r] = O.materials.append({material}(young={kn_pp!r} / r, poisson={ks_pp / kn_pp!r},
                                           density={DENSITY}, frictionAngle=math.atan({MU}){material_extra}))
    O.bodies.append(sphere((x, y, z), r, material=per_radius[r]))
O.bodies.append(wall(0.0, axis=2, sense=1, material=wmat))
piston = wall(top, axis=2, sense=-1, material=wmat)
piston.state.vel = Vector3(0, 0, -{PISTON_SPEED!r})
pid = O.bodies.append(piston)
# A polygon of 48 facets whose flat faces touch the cylinder of radius {CYL_R} (physics.md section 6).
O.bodies.append(geom.facetCylinder(center=(0, 0, 0.5 * (top + 0.01)), radius={CYL_R} / math.cos(math.pi / 48),
                                   height=top + 0.01, segmentsNumber=48, wallMask=4, material=wmat))
O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb(), Bo1_Facet_Aabb()], verletDist={SKIN}),
    InteractionLoop([{ig2_spheres}, Ig2_Facet_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],
                    [{ip2_spheres}Ip2_FrictMat_FrictMat_FrictPhys()],
                    [{law2_spheres}Law2_ScGeom_FrictPhys_CundallStrack()]),
    NewtonIntegrator(damping={DAMPING}, gravity=(0, 0, -9.81)),
]
O.dt = {dt!r}
t0 = time.perf_counter()
O.run({steps}, True)
t1 = time.perf_counter()
print('COLZA_BENCH particles=%d steps=%d seconds=%.6f' % (len(spheres), O.iter, t1 - t0))
""")


def run_yade(packing, dt, steps, work, law):
    name = law.lower().replace(" ", "-")
    d = os.path.join(work, name)
    os.makedirs(d, exist_ok=True)
    script = os.path.join(d, "oedometer_bench.py")
    write_yade(script, os.path.abspath(packing), dt, steps, law)
    log = os.path.join(work, name + ".log")
    out, err, rss, _ = run_timed(["yade", "-n", "-j", "1", "-x", script], d, log)
    m = re.search(r"COLZA_BENCH particles=(\d+) steps=(\d+) seconds=([0-9.eE+-]+)", out + err)
    if not m:
        sys.exit(f"could not read the YADE timing, see {log}")
    return dict(code=law, particles=int(m.group(1)), steps=int(m.group(2)), seconds=float(m.group(3)), rss=rss)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--colza", default="build/src/colza")
    ap.add_argument("--packing", help="settled packing (x y z r); default: prepared once with colza in --work")
    ap.add_argument("--work", default="/tmp/colza-compare")
    ap.add_argument("--dt", type=float, default=1e-5, help="fixed time step for every code (s)")
    ap.add_argument("--steps", type=int, default=20000)
    ap.add_argument("--threads", type=int, default=1, help="colza threads (YADE and LAMMPS run on one)")
    ap.add_argument("--repeat", type=int, default=3, help="interleaved rounds (best and median are reported)")
    ap.add_argument("--skip-yade", action="store_true")
    ap.add_argument("--skip-yade-cohfrict", action="store_true", help="run YADE in its cheapest form only")
    ap.add_argument("--skip-lammps", action="store_true")
    ap.add_argument("--isa", default="",
                    help="comma-separated copies of colza's force loops to run besides its own choice, each forced "
                         "through $COLZA_ISA (generic, avx2, avx512)")
    ap.add_argument("--also", action="append", default=[], metavar="LABEL=PATH",
                    help="another colza binary to run on the same loading (repeatable), e.g. native=/tmp/native/colza")
    a = ap.parse_args()
    colza = os.path.abspath(a.colza)
    # colza rows: (code, binary, forced copy)
    colza_rows = [("colza", colza, None)]
    colza_rows += [(f"colza {isa}", colza, isa) for isa in a.isa.split(",") if isa]
    for also in a.also:
        label, _, path = also.partition("=")
        if not path:
            sys.exit(f"--also {also}: expected LABEL=PATH")
        colza_rows.append((f"colza {label}", os.path.abspath(path), None))
    os.makedirs(a.work, exist_ok=True)
    packing = os.path.abspath(a.packing) if a.packing else prepare_packing(colza, a.work)
    spheres = read_packing(packing)

    # The other codes, installed from Debian on demand (never needed by colza itself).
    others = []  # (code, runner taking the step count)
    for code, binary, package, skip, runner in (
            ("LAMMPS", "lmp", "lammps", a.skip_lammps, lambda n: run_lammps(spheres, a.dt, n, a.work)),
            ("YADE", "yade", "yade", a.skip_yade, lambda n: run_yade(packing, a.dt, n, a.work, "YADE")),
            ("YADE CohFrict", "yade", "yade", a.skip_yade or a.skip_yade_cohfrict,
             lambda n: run_yade(packing, a.dt, n, a.work, "YADE CohFrict"))):
        if skip:
            continue
        if ensure_installed(binary, package):
            others.append((code, runner))
        else:
            print(f"{binary} not found and could not be installed: {code} skipped", file=sys.stderr)
    # Rounds interleave the codes, so a slow phase of this shared machine hits all of them
    # alike; each code's best round (least disturbed) and median are reported.
    runs = {}  # code -> list of rows, one per round
    steps = None
    for k in range(a.repeat):
        for code, binary, isa in colza_rows:
            row = run_colza(binary, packing, a.dt, a.steps, a.work, a.threads, isa=isa, code=code)
            runs.setdefault(code, []).append(row)
            if steps is None:
                steps = row["steps"]
            elif row["steps"] != steps:
                sys.exit(f"{code} ran {row['steps']} steps, colza {steps}")
        for code, runner in others:
            runs.setdefault(code, []).append(runner(steps))
        print(f"round {k + 1}/{a.repeat}: " + ", ".join(f"{c} {r[-1]['seconds']:.2f} s" for c, r in runs.items()),
              file=sys.stderr, flush=True)

    def rate(r):
        return r["particles"] * r["steps"] / r["seconds"]

    best = {c: max(rs, key=rate) for c, rs in runs.items()}
    median = {c: statistics.median(rate(r) for r in rs) for c, rs in runs.items()}
    print(f"\noedometer loading from {packing}: dt = {a.dt:g} s, {steps} steps, one thread "
          f"(colza --threads {a.threads}), {a.repeat} interleaved round(s)")
    first = runs["colza"][0]
    print(f"CPU: {first['cpu'] or 'not recorded'}")
    print(f"colza's force loops: {first['report'] or 'not recorded'}")
    for code, _, _ in colza_rows:
        print(f"  {code}: {runs[code][0]['kernels']}")
    print()
    head = (f"{'code':<13} {'particles':>9} {'steps':>7} {'best s':>8} {'Mp-steps/s':>11} {'vs colza':>9} "
            f"{'median Mp/s':>12} {'vs colza':>9} {'peak MB':>8}")
    print(head)
    print("-" * len(head))
    for c, r in best.items():
        rss = max((x["rss"] for x in runs[c] if x["rss"]), default=None)
        rss_text = f"{rss / 1024:.1f}" if rss else "?"
        print(f"{c:<13} {r['particles']:>9} {r['steps']:>7} {r['seconds']:>8.2f} {rate(r) / 1e6:>11.2f} "
              f"{rate(r) / rate(best['colza']):>9.3f} {median[c] / 1e6:>12.2f} {median[c] / median['colza']:>9.3f} "
              f"{rss_text:>8}")
    if a.repeat > 1:
        print("\ncolza's speed over each code, round by round: " + "; ".join(
            f"{c} " + " ".join(f"{rate(runs['colza'][k]) / rate(runs[c][k]):.2f}x" for k in range(a.repeat))
            for c in runs if c != "colza"))

if __name__ == "__main__":
    main()
