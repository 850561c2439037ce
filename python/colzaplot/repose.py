"""The angle of repose test's heap (scenario/repose.hpp): every sphere of the heap
(heap_profile.csv: distance rho from the axis and top of the sphere in m, azimuth in deg,
in_fit 1 for the surface spheres the cone is fitted to) seen from the side with the cone
fitted to the highest sphere of each sector and radial bin (analysis/heap_angle.hpp),
top = apex - tan(angle) rho over the fit's range of rho, and seen from above, coloured by
height."""
import os

import numpy as np

from . import common


def plot(result_dir, out_dir):
    summary = common.read_json(os.path.join(result_dir, "summary.json"))
    profile_file = os.path.join(result_dir, "heap_profile.csv")
    if not os.path.isfile(profile_file):
        return []
    profile = common.read_csv(profile_file)
    heap = summary.get("angle_of_repose", {})
    rho_mm, top_mm = 1e3 * profile["rho"], 1e3 * profile["top"]
    fit_range = heap.get("fit_rho_range", [0.0, 0.0])

    fig, (side, above) = common.figure(1, 2, gridspec_kw={"width_ratios": [1.6, 1.0]})
    side.axvspan(1e3 * fit_range[0], 1e3 * fit_range[1], color="tab:blue", alpha=0.08,
                 label="the fit's range of rho")
    side.plot(rho_mm, top_mm, "o", color="0.6", ms=2.5, label="top of every sphere")
    if "in_fit" in profile:  # a result written before heap_profile.csv had the column has no highlight
        fit = profile["in_fit"] > 0.5
        side.plot(rho_mm[fit], top_mm[fit], "o", color="tab:blue", ms=3.5,
                  label=f"surface spheres fitted ({int(np.count_nonzero(fit))})")
    if heap.get("valid"):
        slope = np.tan(np.radians(heap["angle_deg"]))
        apex = heap["cone_apex_height"]
        r = np.linspace(fit_range[0], fit_range[1], 50)
        side.plot(1e3 * r, 1e3 * (apex - slope * r), color="tab:red", lw=2.0,
                  label=f"cone: {heap['angle_deg']:.1f} +/- {heap['angle_error_deg']:.1f} deg, R$^2$ = {heap['r2']:.2f}")
        whole = np.linspace(0.0, max(heap.get("heap_radius", fit_range[1]), fit_range[1]), 50)
        side.plot(1e3 * whole, 1e3 * np.maximum(apex - slope * whole, 0.0), color="tab:red", lw=0.8, ls="--")
    else:
        side.text(0.02, 0.95, "no valid cone fit", transform=side.transAxes, va="top")
    # The side view ends at 1.5 heap radii: spheres that rolled farther are counted, not drawn.
    radius_mm = 1e3 * heap.get("heap_radius", 0.0)
    if radius_mm > 0.0:
        side.set_xlim(0.0, 1.5 * radius_mm)
        beyond = int(np.count_nonzero(rho_mm > 1.5 * radius_mm))
        if beyond:
            side.text(0.98, 0.02, f"{beyond} sphere{'s' if beyond > 1 else ''} beyond {1.5 * radius_mm:.0f} mm",
                      transform=side.transAxes, ha="right", va="bottom", fontsize=7)
    side.set_xlabel("distance from the axis rho (mm)")
    side.set_ylabel("top of the sphere (mm)")
    side.set_ylim(bottom=0.0)
    side.grid(alpha=0.3)
    side.legend(loc="upper right", fontsize=7)

    order = np.argsort(top_mm)  # the highest drawn last, on top
    azimuth = np.radians(profile["azimuth_deg"][order])
    dots = above.scatter(rho_mm[order] * np.cos(azimuth), rho_mm[order] * np.sin(azimuth), c=top_mm[order], s=12,
                         cmap="viridis")
    for radius in fit_range:
        t = np.linspace(0.0, 2.0 * np.pi, 100)
        above.plot(1e3 * radius * np.cos(t), 1e3 * radius * np.sin(t), color="tab:red", lw=0.8, ls=":")
    above.set_aspect("equal")
    above.set_xlabel("x (mm)")
    above.set_ylabel("y (mm)")
    fig.colorbar(dots, ax=above, label="top (mm)", shrink=0.8)
    fig.suptitle(common.title_of(summary, "Angle of repose: the heap"), fontsize=10)
    fig.tight_layout()
    return [common.save(fig, out_dir, "heap_profile.png")]
