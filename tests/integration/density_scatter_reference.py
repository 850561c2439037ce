#!/usr/bin/env python3
"""Regenerates the tolerances of CalibrateDensity.BothModesRunTheLoopOnASmallSample
(tests/integration/test_calibrate_dem.cpp): how much the small oedometer's settled bulk density
scatters from one packing to the next at the truth rho_p = 1260 kg/m^3.

Each design run of that test settles its own sample, so a calibration's rho_p = rho_b / phi
inherits the scatter of the packing fraction phi: the test's tolerance on rho_p (4 %) and on
the validation run's bulk density (2 %) are judged against the relative standard deviation
printed here (session 27: see the test's comment for the numbers).

Usage: python3 tests/integration/density_scatter_reference.py [path/to/colza] [seeds]
(default build/src/colza, seeds 1-10; ~5 s per seed)."""
import json
import os
import statistics
import subprocess
import sys
import tempfile

root = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
colza = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "build", "src", "colza")
seeds = range(1, 1 + (int(sys.argv[2]) if len(sys.argv) > 2 else 10))
config = os.path.join(root, "tests", "data", "small_oedometer.toml")
bulk = []
with tempfile.TemporaryDirectory() as work:
    for seed in seeds:
        out = os.path.join(work, f"seed{seed}")
        subprocess.run([colza, "run", "oedometer", "--quiet", "--config", config, "--set", "oedometer.stop_force=100",
                        "--set", "oedometer.fit_force_max=90", "--set", "particle.density=1260", "--seed", str(seed),
                        "--out", out], check=True, stdout=subprocess.DEVNULL)
        rho_b = json.load(open(os.path.join(out, "summary.json")))["bulk_density"]
        bulk.append(rho_b)
        print(f"seed {seed:2d}: bulk density {rho_b:.2f} kg/m^3")
mean, sd = statistics.mean(bulk), statistics.stdev(bulk)
print(f"mean {mean:.2f} kg/m^3, standard deviation {sd:.2f} kg/m^3 = {100 * sd / mean:.2f} % "
      f"(range {100 * (max(bulk) - min(bulk)) / mean:.2f} %) over {len(bulk)} packings")
