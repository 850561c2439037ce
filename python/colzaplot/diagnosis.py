"""A diagnosis (colza diagnose, src/diagnose/diagnosis_report.cpp's summary.json): the
measured features against the model's before (the calibrated baseline) and after (the
extended fit of the verdict's cause, else of the best candidate by BIC), each as the
diagnosis's own z of the feature (measured - model over its total sd: the model's noise and
the measurement's uncertainty), with the 1 and 2 sd bands; and the candidates' signature
similarity (cosine) matrix."""
import os
import textwrap

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
    base = summary["baseline"]
    after, after_name = _after_fit(summary)
    names = [m["feature"] for m in measured]
    x = np.arange(len(names))
    fig, ax = common.figure()
    ax.axhspan(-2, 2, color="tab:green", alpha=0.08, label="2 sd")
    ax.axhspan(-1, 1, color="tab:green", alpha=0.16, label="1 sd")
    ax.axhline(0.0, color="k", lw=1.0, label="measured")
    ax.plot(x - 0.1, [base["features"][n]["z"] for n in names], "o", color="tab:red", ms=8,
            label=f"model before (baseline): chi$^2$ {base['chi_square']:.3g} on {base['degrees_of_freedom']}, "
                  f"p = {base['p_value']:.3g}")
    if after is not None:
        ax.plot(x + 0.1, [after["features"][n]["z"] for n in names], "^", color="tab:blue", ms=8,
                label=f"model after (+ {after_name}): chi$^2$ {after['chi_square']:.3g} on "
                      f"{after['degrees_of_freedom']}, p = {after['p_value']:.3g}")
    else:
        ax.plot([], [], " ", label="no extended model was fitted")
    ax.set_xticks(x)
    ax.set_xticklabels([f"{m['feature']}\n= {m['value']:.4g} {m.get('unit', '')}".rstrip() for m in measured],
                       rotation=30, ha="right", fontsize=7)
    ax.set_ylabel("z = (measured - model) / sd")
    verdict = summary.get("verdict") or {}
    # The verdict and its reason: the first sentence of the verdict's text, wrapped.
    reason = str(verdict.get("text", "")).split(". ")[0].rstrip(".")
    ax.set_title(f"Diagnosis: {verdict.get('kind', '')}" + (f", cause {verdict['cause']}" if verdict.get("cause") else "")
                 + ("\n" + "\n".join(textwrap.wrap(reason, 115, max_lines=3, placeholder=" ...")) if reason else ""), fontsize=8)
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
