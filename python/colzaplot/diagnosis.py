"""A diagnosis (colza diagnose, src/diagnose/diagnosis_report.cpp's summary.json): the
measured features against the model's before (the calibrated baseline) and after (the
extended fit of the verdict's cause, else of the best candidate by BIC), each as the
deviation from the measurement in units of the baseline's noise sd, with the 1 and 2 sd
bands; and the candidates' signature similarity (cosine) matrix."""
import os

import numpy as np

from . import common


def _after_fit(summary):
    """The extended fit to show as "after": the cause's, else the lowest BIC; None if none."""
    extended = summary.get("extended") or []
    if not extended:
        return None, ""
    cause = (summary.get("verdict") or {}).get("cause", "")
    names = [c.get("name", "") for c in summary.get("candidates", [])]
    for fit in extended:
        if cause and cause in str(fit.get("model", "")):
            return fit, cause
    best = min(extended, key=lambda f: f.get("bic", np.inf))
    model = str(best.get("model", ""))
    return best, next((n for n in names if n and n in model), model)


def plot_features(summary, out_dir):
    measured = summary["measured"]
    base = summary["baseline"]["features"]
    after, after_name = _after_fit(summary)
    names = [m["feature"] for m in measured]
    sd = np.array([base[n]["noise_sd"] for n in names])
    value = np.array([m["value"] for m in measured])
    unc = np.array([m["uncertainty"] for m in measured])
    x = np.arange(len(names))
    fig, ax = common.figure()
    ax.axhspan(-2, 2, color="tab:green", alpha=0.08, label="2 noise sd")
    ax.axhspan(-1, 1, color="tab:green", alpha=0.16, label="1 noise sd")
    ax.errorbar(x, np.zeros_like(x, dtype=float), yerr=unc / sd, fmt="s", color="k", ms=5, capsize=3,
                label="measured (+/- its uncertainty)")
    before = np.array([base[n]["model"] for n in names])
    ax.plot(x - 0.12, (before - value) / sd, "o", color="tab:red", ms=7, label="model before (baseline)")
    if after is not None:
        model = np.array([after["features"][n]["model"] for n in names])
        ax.plot(x + 0.12, (model - value) / sd, "^", color="tab:blue", ms=7, label=f"model after (+ {after_name})")
    ax.axhline(0.0, color="k", lw=0.6)
    ax.set_xticks(x)
    ax.set_xticklabels(names, rotation=35, ha="right", fontsize=7)
    ax.set_ylabel("(model - measured) / noise sd")
    verdict = summary.get("verdict") or {}
    ax.set_title(f"Diagnosis: {verdict.get('kind', '')}" + (f", cause {verdict['cause']}" if verdict.get("cause") else ""),
                 fontsize=10)
    ax.grid(alpha=0.3, axis="y")
    ax.legend(fontsize=7, loc="best")
    fig.tight_layout()
    return common.save(fig, out_dir, "diagnosis_features.png")


def plot_similarity(summary, out_dir):
    cos = np.asarray(summary["signature_cosines"], dtype=float)
    names = [c.get("name", "") for c in summary.get("candidates", []) if "signature" in c][: cos.shape[0]]
    fig, ax = common.figure()
    image = ax.imshow(cos, vmin=-1.0, vmax=1.0, cmap="RdBu_r")
    for r in range(cos.shape[0]):
        for c in range(cos.shape[1]):
            ax.text(c, r, f"{cos[r, c]:.2f}", ha="center", va="center", fontsize=8,
                    color="white" if abs(cos[r, c]) > 0.6 else "black")
    ax.set_xticks(range(len(names)))
    ax.set_xticklabels(names, rotation=35, ha="right", fontsize=8)
    ax.set_yticks(range(len(names)))
    ax.set_yticklabels(names, fontsize=8)
    fig.colorbar(image, ax=ax, label="cosine of the signatures")
    ax.set_title("Diagnosis: similarity of the candidates' signatures", fontsize=10)
    fig.tight_layout()
    return common.save(fig, out_dir, "diagnosis_similarity.png")


def plot(result_dir, out_dir, summary):
    written = [plot_features(summary, out_dir)]
    if summary.get("signature_cosines"):
        written.append(plot_similarity(summary, out_dir))
    return written
