#!/usr/bin/python3
"""Plots of a colza result directory into DIR/plots/ (PNG): `colza plot DIR` and every run
call it. What it draws depends on the result (summary.json): an oedometer run, a shear
load or series, an angle of repose run, a generic scene, a calibration (then report.md gets a Plots
section) or a diagnosis.

Exit status: 0 plots written (or none for this kind of result), 3 the plotting stack
(numpy, matplotlib) is missing, 2 DIR is not a colza result, 1 anything else."""
import argparse
import os
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
# The paper's measured failure line (data/measured/README.md), drawn beside a series' line.
DEFAULT_MEASURED_SHEAR = os.path.join(HERE, "..", "data", "measured", "shear_strength_paper_line.csv")
MISSING_STACK = 3


def kind_of(summary):
    if "verdict" in summary and "candidates" in summary:
        return "diagnosis"
    if "surfaces" in summary and "stage" in summary:
        return "calibration"
    return summary.get("scenario", "")


def draw(result_dir, out_dir, measured_shear):
    from colzaplot import calibration, common, diagnosis, oedometer, repose, scene, shear

    summary = common.read_json(os.path.join(result_dir, "summary.json"))
    kind = kind_of(summary)
    if kind == "oedometer":
        return kind, oedometer.plot(result_dir, out_dir)
    if kind == "shear":
        return kind, shear.plot_single(result_dir, out_dir)
    if kind == "shear-series":
        return kind, shear.plot_series(result_dir, out_dir, measured_shear)
    if kind == "repose":
        return kind, repose.plot(result_dir, out_dir)
    if kind == "scene":
        return kind, scene.plot(result_dir, out_dir)
    if kind == "calibration":
        return kind, calibration.plot(result_dir, out_dir, summary)
    if kind == "diagnosis":
        return kind, diagnosis.plot(result_dir, out_dir, summary)
    return kind, []


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("dir", help="a colza result directory (it holds summary.json)")
    parser.add_argument("--measured-shear", default=DEFAULT_MEASURED_SHEAR,
                        help="CSV (normal_stress, shear_strength in Pa) drawn beside a series' Mohr-Coulomb line; "
                             "'none' for none (default: the paper's line, data/measured/)")
    args = parser.parse_args()
    try:
        import matplotlib  # noqa: F401
        import numpy  # noqa: F401
    except ImportError as e:
        print(f"colza plot: the plotting stack is missing ({e}); install python3-matplotlib", file=sys.stderr)
        return MISSING_STACK
    result_dir = os.path.abspath(args.dir)
    if not os.path.isfile(os.path.join(result_dir, "summary.json")):
        print(f"colza plot: {args.dir} holds no summary.json: not a colza result", file=sys.stderr)
        return 2
    sys.path.insert(0, HERE)
    measured = None if args.measured_shear == "none" else args.measured_shear
    # Drawn into a folder of this process, then moved into place: plots/ is complete or the old one.
    staging = os.path.join(result_dir, f".plots-partial-{os.getpid()}")
    final = os.path.join(result_dir, "plots")
    os.makedirs(staging)
    try:
        kind, written = draw(result_dir, staging, measured)
        if not written:
            os.rmdir(staging)
            print(f"colza plot: no plots for a result of kind '{kind}'")
            return 0
        if os.path.isdir(final):
            shutil.rmtree(final)
        os.rename(staging, final)
    except BaseException:
        shutil.rmtree(staging, ignore_errors=True)
        raise
    names = [os.path.basename(p) for p in written]
    if kind in ("calibration", "diagnosis"):
        from colzaplot import report
        report.embed_plots(os.path.join(result_dir, "report.md"), names)
    print(f"colza plot: {len(names)} plot(s) in {final}: {', '.join(names)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
