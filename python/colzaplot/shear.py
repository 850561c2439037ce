"""The shear box: each load's shear curve (shear stress against shear displacement) with its
strength window, the strength (mean stress over the window), the peak and the dilatancy
(plate rise); a series' Mohr-Coulomb line tau = C + sigma tan(Phi) through the simulated
strengths, beside the measured line and points (a CSV of normal_stress, shear_strength in Pa)."""
import os

import numpy as np

from . import common


def _curve_panel(ax_tau, ax_dil, curve, summary):
    d_mm = 1e3 * curve["shear_displacement"]
    tau_kpa = 1e-3 * curve["shear_stress"]
    ax_tau.plot(d_mm, tau_kpa, color="0.25", lw=1.0, label="shear stress (curve.csv)")
    window = summary.get("strength_window")
    strength = summary.get("shear_strength")
    if window and common.finite(strength):
        w0, w1 = 1e3 * window[0], 1e3 * window[1]
        ax_tau.axvspan(w0, w1, color="tab:green", alpha=0.15, label=f"strength window {w0:g}-{w1:g} mm")
        ax_tau.plot([w0, w1], [1e-3 * strength] * 2, color="tab:green", lw=2.5,
                    label=f"strength (window mean) {1e-3 * strength:.2f} kPa")
    features = summary.get("curve_features") or {}
    peak, at, width = (features.get(k) for k in ("peak_strength", "peak_displacement", "peak_width"))
    peak_interval = None
    if common.finite(peak) and common.finite(at) and common.finite(width):
        # The peak strength: the largest mean stress over a trailing interval of peak_width,
        # drawn over the interval [at - width, at] whose mean it is.
        peak_interval = (at - width, at)
        ax_tau.plot([1e3 * (at - width), 1e3 * at], [1e-3 * peak] * 2, color="tab:red", lw=2.5,
                    label=f"peak {1e-3 * peak:.2f} kPa: the largest mean over {1e3 * width:g} mm")
    stiffness, d_f = features.get("initial_stiffness"), features.get("stiffness_displacement")
    if common.finite(stiffness) and common.finite(d_f):
        # The initial stiffness: the secant from the curve's start to where it first reaches a
        # fraction of the peak, tau(d_f) = tau_0 + k (d_f - d_0).
        d0, tau0 = curve["shear_displacement"][0], curve["shear_stress"][0]
        ax_tau.plot([1e3 * d0, 1e3 * d_f], [1e-3 * tau0, 1e-3 * (tau0 + stiffness * (d_f - d0))], color="tab:purple",
                    lw=1.2, ls="--", label=f"initial stiffness (secant) {1e-6 * stiffness:.3g} kPa/mm")
    ax_tau.set_ylabel("shear stress (kPa)")
    ax_tau.grid(alpha=0.3)
    ax_tau.legend(loc="lower right", fontsize=7)
    ax_dil.plot(d_mm, 1e3 * curve["dilatancy"], color="tab:blue", lw=1.0, label="plate rise")
    psi = features.get("dilatancy_angle_deg")
    if common.finite(psi) and peak_interval is not None:
        # The dilatancy angle: atan of the least-squares slope of the plate rise over the
        # peak's interval, drawn there.
        d, h = curve["shear_displacement"], curve["dilatancy"]
        inside = (d >= peak_interval[0]) & (d <= peak_interval[1])
        mid_d, mid_h = np.mean(d[inside]), np.mean(h[inside])
        slope = np.tan(np.radians(psi))
        ends = np.array(peak_interval)
        ax_dil.plot(1e3 * ends, 1e3 * (mid_h + slope * (ends - mid_d)), color="tab:red", lw=2.0,
                    label=f"dilatancy angle {psi:.1f} deg over the peak's interval")
        ax_dil.legend(loc="lower right", fontsize=7)
    ax_dil.set_xlabel("shear displacement (mm)")
    ax_dil.set_ylabel("plate rise (mm)")
    ax_dil.grid(alpha=0.3)


def plot_load(load_dir, out_dir, name):
    summary = common.read_json(os.path.join(load_dir, "summary.json"))
    curve = common.read_csv(os.path.join(load_dir, "curve.csv"))
    fig, (ax_tau, ax_dil) = common.figure(2, 1, sharex=True, gridspec_kw={"height_ratios": [3, 1.3]})
    _curve_panel(ax_tau, ax_dil, curve, summary)
    sigma = summary.get("normal_stress", 0.0)
    ax_tau.set_title(common.title_of(summary, f"Shear curve at {1e-3 * sigma:g} kPa"))
    fig.tight_layout()
    return common.save(fig, out_dir, name)


def _line(sigma, tau):
    """Least-squares line tau = C + sigma tan(Phi): (C, tan(Phi))."""
    slope, intercept = np.polyfit(np.asarray(sigma), np.asarray(tau), 1)
    return intercept, slope


def plot_mohr_coulomb(summary, out_dir, measured_file):
    loads = summary["loads"]
    sigma = np.array([l["normal_stress"] for l in loads])
    tau = np.array([l["shear_strength"] for l in loads])
    fig, ax = common.figure()
    top = 1.15 * sigma.max()
    s = np.linspace(0.0, top, 50)
    ax.plot(1e-3 * sigma, 1e-3 * tau, "o", color="tab:red", ms=7, label="simulated strengths")
    if common.finite(summary.get("cohesion")) and common.finite(summary.get("friction_angle_deg")):
        c, phi = summary["cohesion"], summary["friction_angle_deg"]
        ax.plot(1e-3 * s, 1e-3 * (c + s * np.tan(np.radians(phi))), color="tab:red", lw=1.8,
                label=f"simulated line: C = {1e-3 * c:.2f} kPa, Phi = {phi:.2f} deg")
    if measured_file and os.path.exists(measured_file):
        m = common.read_csv(measured_file)
        ms, mt = m["normal_stress"], m["shear_strength"]
        ax.plot(1e-3 * ms, 1e-3 * mt, "s", mfc="none", color="k", ms=7,
                label=f"measured ({os.path.basename(measured_file)})")
        if len(ms) >= 2:
            c, t = _line(ms, mt)
            ax.plot(1e-3 * s, 1e-3 * (c + s * t), color="k", lw=1.2, ls="--",
                    label=f"measured line: C = {1e-3 * c:.2f} kPa, Phi = {np.degrees(np.arctan(t)):.2f} deg")
    ax.set_xlim(0.0, 1e-3 * top)
    ax.set_ylim(bottom=0.0)
    ax.set_xlabel("normal stress (kPa)")
    ax.set_ylabel("shear strength (kPa)")
    ax.set_title(common.title_of(summary, "Mohr-Coulomb line"))
    ax.grid(alpha=0.3)
    ax.legend(loc="upper left", fontsize=8)
    fig.tight_layout()
    return common.save(fig, out_dir, "mohr_coulomb.png")


def plot_single(result_dir, out_dir):
    return [plot_load(result_dir, out_dir, "shear_curve.png")]


def plot_series(result_dir, out_dir, measured_file):
    summary = common.read_json(os.path.join(result_dir, "summary.json"))
    written = []
    for load in summary.get("loads", []):
        load_dir = os.path.join(result_dir, load["directory"])
        if os.path.exists(os.path.join(load_dir, "curve.csv")):
            written.append(plot_load(load_dir, out_dir, f"shear_curve_{load['directory']}.png"))
    if len(summary.get("loads", [])) >= 1:
        written.append(plot_mohr_coulomb(summary, out_dir, measured_file))
    return written
