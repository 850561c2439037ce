"""A generic scene's series (series.csv, docs/running.md "Generic scene"): the energy budget against
time, stored energies and what left the system (J), with the balance
stored + dissipated - wall work, less its first value, which a complete bookkeeping keeps at
zero (engine/energy.hpp); and the contact force on each recorded particle (N)."""
import os
import re

import numpy as np

from . import common

# The ledger's column that is work done on the particles (engine/energy.hpp, kLedgerChannels:
# sign -1); every other ledger column is energy that left them.
WORK_ON_THE_SYSTEM = "wall_work"
LEDGER = re.compile(r".*_(dissipated|lost|released|change)$")


def plot(result_dir, out_dir):
    series_file = os.path.join(result_dir, "series.csv")
    if not os.path.isfile(series_file):
        return []
    summary = common.read_json(os.path.join(result_dir, "summary.json"))
    s = common.read_csv(series_file)
    t_ms = 1e3 * s["time"]
    stored = [n for n in s if n.endswith("_energy")]
    ledger = [n for n in s if LEDGER.match(n)]

    fig, (energy, force) = common.figure(1, 2)
    for n in stored:
        energy.plot(t_ms, s[n] - s[n][0], lw=1.2, label=f"{n} (change)")
    for n in ledger:
        if np.any(s[n] != 0.0):
            energy.plot(t_ms, s[n], lw=1.0, ls="--", label=n)
    if WORK_ON_THE_SYSTEM in s and np.any(s[WORK_ON_THE_SYSTEM] != 0.0):
        energy.plot(t_ms, s[WORK_ON_THE_SYSTEM], lw=1.0, ls=":", label=f"{WORK_ON_THE_SYSTEM} (on the particles)")
    total = sum(s[n] for n in stored) + sum(s[n] for n in ledger)
    if WORK_ON_THE_SYSTEM in s:
        total = total - s[WORK_ON_THE_SYSTEM]
    energy.plot(t_ms, total - total[0], color="black", lw=2.0, label="balance (change): 0 when complete")
    energy.set_xlabel("time (ms)")
    energy.set_ylabel("energy (J)")
    energy.grid(alpha=0.3)
    energy.legend(fontsize=6, loc="best")

    particles = sorted({int(m.group(1)) for n in s for m in [re.match(r"p(\d+)_fx$", n)] if m})
    for p in particles:
        f = np.sqrt(s[f"p{p}_fx"] ** 2 + s[f"p{p}_fy"] ** 2 + s[f"p{p}_fz"] ** 2)
        force.plot(t_ms, f, lw=1.2, label=f"particle {p}")
    if not particles:
        force.text(0.02, 0.95, "no particle recorded (scene.record_particles)", transform=force.transAxes, va="top")
    else:
        force.legend(fontsize=7, loc="best")
    force.set_xlabel("time (ms)")
    force.set_ylabel("|contact force| (N)")
    force.grid(alpha=0.3)
    fig.suptitle(common.title_of(summary, "Scene: energy budget and contact forces"), fontsize=10)
    fig.tight_layout()
    return [common.save(fig, out_dir, "scene_series.png")]
