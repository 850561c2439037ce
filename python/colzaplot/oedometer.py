"""The oedometer's compression curve with the paper's fit (section 3.1): piston force F
against piston travel s measured from where F first reaches fit.force_min (150 N by
default), and F(s) = c0 + c1 s + c2 s^2 over force_min .. force_max."""
import os

import numpy as np

from . import common


def plot(result_dir, out_dir):
    summary = common.read_json(os.path.join(result_dir, "summary.json"))
    curve = common.read_csv(os.path.join(result_dir, "curve.csv"))
    fit = summary.get("fit", {})
    zero = fit.get("zero_displacement", 0.0) if fit.get("valid") else 0.0
    s_mm = 1e3 * (curve["piston_displacement"] - zero)
    force_kn = 1e-3 * curve["piston_force"]

    fig, ax = common.figure()
    if "branch" in curve:  # oedometer.cycles: one colour per branch
        for b in np.unique(curve["branch"]):
            rows = curve["branch"] == b
            kind = "loading" if int(b) % 2 == 0 else "unloading"
            ax.plot(s_mm[rows], force_kn[rows], lw=1.2, label=f"branch {int(b)} ({kind})")
    else:
        ax.plot(s_mm, force_kn, color="0.25", lw=1.2, label="simulated (curve.csv)")
    if fit.get("valid"):
        # The fit over its range: s from 0 to the travel where the recorded force first reaches
        # force_max (or the largest force when the run stopped below it).
        first = curve["branch"] == 0 if "branch" in curve else np.ones_like(s_mm, dtype=bool)
        above = np.nonzero(first & (curve["piston_force"] >= fit["force_max"]))[0]
        s_end = (s_mm[above[0]] if above.size else s_mm[first].max()) * 1e-3
        s = np.linspace(0.0, s_end, 200)
        f = fit["c0"] + fit["c1"] * s + fit["c2"] * s * s
        ax.plot(1e3 * s, 1e-3 * f, color="tab:red", lw=2.0, ls="--",
                label=(f"fit F = c0 + c1 s + c2 s$^2$ over {fit['force_min']:g}-{fit['force_max']:g} N: "
                       f"c0 = {fit['c0']:.4g} N, c1 = {fit['c1']:.4g} N/m,\nc2 = {fit['c2']:.4g} N/m$^2$, "
                       f"R$^2$ = {fit['r2']:.4f}"))
        ax.axvline(0.0, color="tab:blue", lw=0.8, ls=":")
        ax.axhline(1e-3 * fit["force_min"], color="tab:blue", lw=0.8, ls=":")
        ax.plot([0.0], [1e-3 * fit["force_min"]], "o", color="tab:blue",
                label=f"zero of s: F = {fit['force_min']:g} N at travel {1e3 * zero:.3f} mm")
    else:
        ax.text(0.02, 0.95, "no valid fit (too few points above force_min)", transform=ax.transAxes, va="top")
    ax.set_xlabel("piston travel s from the zero (mm)")
    ax.set_ylabel("piston force F (kN)")
    ax.set_title(common.title_of(summary, "Oedometer: compression curve"))
    ax.grid(alpha=0.3)
    ax.legend(loc="upper left", fontsize=8)
    fig.tight_layout()
    return [common.save(fig, out_dir, "compression_curve.png")]
