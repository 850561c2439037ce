#!/usr/bin/env python3
"""The oedometer loading with each contact mechanism on, time relative to the paper's law.

Runs the loading stage from a settled oedometer packing (the one compare_codes.py prepares,
or --packing) with a fixed dt and number of steps, one configuration after the other in
interleaved rounds, and prints each configuration's least and median CPU time per step of
the loading stage (summary.json; one thread, so CPU time is the run's own even on a shared
machine) and its ratio to the paper's law (linear, Coulomb, no mechanism: the batched
kernels); each other row switches one mechanism on, which runs the generic tier.

    python3 tests/bench/mechanism_speed.py build/src/colza --packing /tmp/colza-compare/prep/packing.txt
"""
import argparse
import json
import os
import platform
import statistics
import subprocess

from compare_codes import PISTON_SPEED, prepare_packing

# name -> --set overrides (physics.md section 7; parameters in docs/configuration.md)
CONFIGS = {
    "paper's law (baseline)": [],
    "rolling resistance": ["contact.rolling=elastic_plastic", "contact.elastic_plastic.stiffness_factor=1.0",
                           "contact.elastic_plastic.friction=0.1"],
    "Hertz-Mindlin": ["contact.normal=hertz", "contact.tangential=mindlin", "particle.young_modulus=5e7",
                      "particle.poisson_ratio=0.3", "wall.young_modulus=2e11", "wall.poisson_ratio=0.3"],
    "viscous damping": ["contact.damping=viscous", "contact.viscous.normal_damping_ratio=0.2",
                        "contact.viscous.tangential_damping_ratio=0.2"],
    "Walton-Braun": ["contact.normal=walton_braun", "contact.walton_braun.unloading_stiffness_ratio=2.0"],
    "load-induced cohesion": ["contact.bond=load_induced", "contact.load_induced.onset_force=1.0",
                              "contact.load_induced.normal_strength_ratio=0.1",
                              "contact.load_induced.shear_strength_ratio=0.1"],
}


def cpu_model():
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor()


def run(colza, packing, dt, steps, work, name, overrides):
    out = os.path.join(work, "mechanism-" + "".join(c if c.isalnum() else "_" for c in name))
    travel = PISTON_SPEED * dt * (steps - 1.5)
    cmd = [colza, "run", "oedometer", "--threads", "1", "--quiet", "--set", f"oedometer.packing_file={packing}",
           "--set", f"integration.time_step={dt!r}", "--set", f"oedometer.max_piston_travel={travel!r}",
           "--out", out, "--force"]
    for o in overrides:
        cmd += ["--set", o]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    s = json.load(open(os.path.join(out, "summary.json")))
    stage = next(st for st in s["stages"] if st["name"] == "loading")
    return stage["cpu_seconds"] / stage["steps"]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("colza")
    ap.add_argument("--packing")
    ap.add_argument("--work", default="/tmp/colza-compare")
    ap.add_argument("--dt", type=float, default=1e-5)
    ap.add_argument("--steps", type=int, default=20000)
    ap.add_argument("--rounds", type=int, default=3)
    a = ap.parse_args()
    colza = os.path.abspath(a.colza)
    os.makedirs(a.work, exist_ok=True)
    packing = os.path.abspath(a.packing) if a.packing else prepare_packing(colza, a.work)
    per_step = {name: [] for name in CONFIGS}
    for _ in range(a.rounds):
        for name, overrides in CONFIGS.items():
            per_step[name].append(run(colza, packing, a.dt, a.steps, a.work, name, overrides))
    base = min(per_step["paper's law (baseline)"])
    print(f"CPU: {cpu_model()}; one thread; {a.steps} loading steps at dt {a.dt} s; {a.rounds} interleaved rounds")
    print(f"{'mechanism':28s} {'least us/step':>14s} {'median us/step':>15s} {'least / baseline':>17s}")
    for name, values in per_step.items():
        least = min(values)
        print(f"{name:28s} {least * 1e6:14.1f} {statistics.median(values) * 1e6:15.1f} {least / base:17.2f}")


if __name__ == "__main__":
    main()
