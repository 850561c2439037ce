"""A calibration's response surfaces (calibration/response_surface.hpp): for each target,
one panel per parameter with the runs (design, refinement, validation, replicates), the
surface through the solution (the other parameters held at their solved values), the
measured value with its uncertainty band and the solution."""
import math
import os

import numpy as np

from . import common

ROLE_STYLE = {"design": ("o", "tab:blue"), "validation": ("*", "tab:red"), "design+validation": ("*", "tab:red"),
              "refinement": ("s", "tab:orange"), "replicate": ("x", "tab:gray"), "confirmation": ("D", "tab:purple")}


def surface_value(surface, x):
    """The surface at parameter point x (SI): a plane from plane_si, else the scaled terms
    1, u_j, u_j u_k (j <= k) with u = (x - mid) / half."""
    if surface.get("plane_si"):
        a = surface["plane_si"]
        return a[0] + sum(a[1 + j] * x[j] for j in range(len(x)))
    mid, half = np.asarray(surface["scaling_mid"]), np.asarray(surface["scaling_half"])
    u = (np.asarray(x) - mid) / half
    terms = [1.0] + list(u)
    if surface.get("kind") == "quadratic":
        terms += [u[j] * u[k] for j in range(len(u)) for k in range(j, len(u))]
    return float(np.dot(surface["coefficients_scaled"], terms))


def plot_target(summary, i, out_dir):
    parameters, target = summary["parameters"], summary["targets"][i]
    surface = next((s for s in summary["surfaces"] if s["target"] == target["name"]), None)
    solution = [p["value"] for p in parameters]
    n = len(parameters)
    cols = min(n, 3)
    rows = math.ceil(n / cols)
    fig, axes = common.figure(rows, cols, squeeze=False, sharey=True)
    for j, par in enumerate(parameters):
        ax = axes[j // cols][j % cols]
        lo, hi = par["bounds"]
        measured, u = target["measured"], target["uncertainty"]
        ax.axhspan(measured - u, measured + u, color="tab:green", alpha=0.15)
        ax.axhline(measured, color="tab:green", lw=1.2, label=f"measured {measured:.4g} +/- {u:.2g}")
        if surface is not None:
            xs = np.linspace(lo, hi, 60)
            ys = [surface_value(surface, [x if k == j else solution[k] for k in range(n)]) for x in xs]
            ax.plot(xs, ys, color="0.3", lw=1.5,
                    label=f"{surface.get('kind', 'surface')} (R$^2$ {surface.get('r2', float('nan')):.3f})")
        seen = set()
        for run in summary.get("runs", []):
            role = run.get("role", "")
            marker, colour = ROLE_STYLE.get(role, ("^", "tab:brown"))
            ax.plot(run["parameters"][j], run["targets"][i], marker, color=colour, ms=8 if marker == "*" else 6,
                    label=None if role in seen else f"{role} run")
            seen.add(role)
        # The solution, at the value the validation achieved, with the parameter's standard
        # uncertainty as a horizontal bar (it may reach beyond the design range).
        sd = par.get("uncertainty")
        ax.axvline(par["value"], color="tab:red", lw=0.8, ls="--")
        ax.errorbar([par["value"]], [target["achieved"]], xerr=[sd] if common.finite(sd) else None, fmt="none",
                    ecolor="tab:red", elinewidth=1.0, capsize=4,
                    label=f"solution {par['value']:.4g}" + (f" +/- {sd:.2g}" if common.finite(sd) else ""))
        unit = f" ({par['unit']})" if par.get("unit") else ""
        ax.set_xlabel(f"{par['name']}{unit}")
        ax.set_xlim(lo - 0.05 * (hi - lo), hi + 0.05 * (hi - lo))
        ax.grid(alpha=0.3)
        if j % cols == 0:
            tunit = f" ({target['unit']})" if target.get("unit") else ""
            ax.set_ylabel(f"{target['name']}{tunit}")
    for j in range(n, rows * cols):
        axes[j // cols][j % cols].axis("off")
    axes[0][0].legend(fontsize=7, loc="best")
    fig.suptitle(f"Calibration ({summary.get('stage')}, {summary.get('mode')}): response surface of "
                 f"{target['name']}; solution dashed, achieved {target['achieved']:.4g}", fontsize=10)
    fig.tight_layout()
    safe = "".join(c if c.isalnum() or c in "-_" else "_" for c in target["name"])
    return common.save(fig, out_dir, f"surface_{safe}.png")


def plot(result_dir, out_dir, summary):
    return [plot_target(summary, i, out_dir) for i in range(len(summary.get("targets", [])))]
