"""Plots (issue 42) drawn by real runs and read back as PNG files: every run (oedometer,
shear, angle of repose, scene) writes DIR/plots/, `colza plot DIR` draws them again, a calibration's report.md embeds its plots,
a diagnosis's summary is drawn, and a missing plotting stack is a warning (exit 0, the
result complete), never a failure.
Each plot must be a PNG of the script's size (python/colzaplot/common.py: 1000 x 625) whose
pixels are not blank."""
import os
import shutil
import sys

from pictures_common import Scratch, args, png_size, run_colza, skip

try:
    import matplotlib.image
    import numpy as np
except ImportError as e:
    skip(f"the plotting stack is missing ({e}): install python3-matplotlib")

SIZE = (1000, 625)


def check_png(path):
    assert os.path.isfile(path), f"missing {path}"
    assert png_size(path) == SIZE, f"{path}: {png_size(path)} pixels, expected {SIZE}"
    rgb = matplotlib.image.imread(path)[:, :, :3]
    # Not blank: a tenth of the pixels at least differs from white (axes, curves, text) and
    # the image holds more than a few colours.
    inked = np.mean(np.any(rgb < 0.9, axis=2))
    colours = len(np.unique((rgb * 255).astype(np.uint8).reshape(-1, 3), axis=0))
    assert inked > 0.02 and colours > 20, f"{path} looks blank: {inked:.3f} inked, {colours} colours"


def plots_of(d):
    return sorted(os.listdir(os.path.join(d, "plots")))


def oedometer(colza, source, tmp):
    """An oedometer run draws its compression curve; without a plotting stack the run succeeds
    with a warning and no plots, and `colza plot` draws them later."""
    oed = os.path.join(source, "tests", "data", "small_oedometer.toml")
    o = os.path.join(tmp, "oedometer")
    run_colza(colza, "run", "oedometer", "--quiet", "--config", oed, "--out", o)
    assert plots_of(o) == ["compression_curve.png"], plots_of(o)
    check_png(os.path.join(o, "plots", "compression_curve.png"))
    bare = os.path.join(tmp, "no-stack")
    r = run_colza(colza, "run", "oedometer", "--quiet", "--config", oed, "--out", bare,
                  "--set", "output.snapshot_interval=0", env={"COLZA_PYTHON": os.path.join(tmp, "no-python")})
    assert "warning: no plots" in r.stderr, r.stderr
    assert os.path.isfile(os.path.join(bare, "summary.json")) and not os.path.exists(os.path.join(bare, "plots"))
    run_colza(colza, "plot", bare)
    check_png(os.path.join(bare, "plots", "compression_curve.png"))
    r = run_colza(colza, "plot", os.path.join(tmp, "nothing-here"), check=False)
    assert r.returncode == 2 and "not a colza result" in r.stderr, r.stderr


def shear(colza, source, tmp):
    """A shear series: each load's curve and the Mohr-Coulomb line."""
    s = os.path.join(tmp, "series")
    run_colza(colza, "run", "shear-series", "--quiet", "--config", os.path.join(source, "tests", "data", "small_shear.toml"),
              "--out", s, "--set", "output.snapshot_interval=0")
    expected = ["mohr_coulomb.png", "shear_curve_load-25750Pa.png", "shear_curve_load-78750Pa.png"]
    assert plots_of(s) == expected, plots_of(s)
    for name in expected:
        check_png(os.path.join(s, "plots", name))


def calibration(colza, source, tmp):
    """A calibration (compression: 3 design runs + validation from one packing): one
    response-surface plot per target, embedded in report.md, whose Plots section a second
    `colza plot` replaces."""
    oed = os.path.join(source, "tests", "data", "small_oedometer.toml")
    o = os.path.join(tmp, "packing")
    run_colza(colza, "run", "oedometer", "--quiet", "--config", oed, "--out", o,
              "--set", "output.snapshot_interval=0", "--set", "output.plots=false")
    spec = os.path.join(tmp, "spec.toml")
    with open(spec, "w") as f:
        f.write(f'stage = "compression"\n[model]\nconfig = "{oed}"\n'
                f'set = ["oedometer.stop_force=1500.0", "oedometer.fit_force_max=1400.0", '
                f'"oedometer.packing_file=\\"{os.path.join(o, "packing.txt")}\\""]\n'
                '[[parameters]]\nname = "kn_p"\nkey = "particle.normal_stiffness"\nunit = "N/m"\n'
                'design = [350e3, 450e3, 550e3]\n'
                '[measured]\nc1 = 1.05e5\nc2 = 9.5e7\nc1_uncertainty = 3.0e4\nc2_uncertainty = 3.0e7\n')
    c = os.path.join(tmp, "calibration")
    run_colza(colza, "calibrate", "compression", "--quiet", "--spec", spec, "--out", c)
    expected = ["surface_c1.png", "surface_c2.png"]
    assert plots_of(c) == expected, plots_of(c)
    for name in expected:
        check_png(os.path.join(c, "plots", name))
    with open(os.path.join(c, "report.md")) as f:
        report = f.read()
    assert "## Plots" in report and "(plots/surface_c1.png)" in report, report[-500:]
    run_colza(colza, "plot", c)
    with open(os.path.join(c, "report.md")) as f:
        assert f.read().count("## Plots") == 1


def diagnosis(colza, source, tmp):
    """A diagnosis's plots from its summary.json: data/diagnosis_summary.json is what
    `colza diagnose` wrote for data/diagnosis_small_spec.toml (a verdict "unexplained", three
    candidates: 42 DEM runs, 3-4 minutes, too long to repeat here), embedded in its report.md."""
    d = os.path.join(tmp, "diagnosis")
    os.makedirs(d)
    shutil.copy(os.path.join(source, "tests", "pictures", "data", "diagnosis_summary.json"),
                os.path.join(d, "summary.json"))
    with open(os.path.join(d, "report.md"), "w") as f:
        f.write("# Diagnosis\n")
    run_colza(colza, "plot", d)
    expected = ["diagnosis_features.png", "diagnosis_similarity.png"]
    assert plots_of(d) == expected, plots_of(d)
    for name in expected:
        check_png(os.path.join(d, "plots", name))
    with open(os.path.join(d, "report.md")) as f:
        report = f.read()
    assert "## Plots" in report and "(plots/diagnosis_features.png)" in report, report


def repose(colza, source, tmp):
    """An angle of repose run draws its heap with the fitted cone (a short rest: the plot, not
    the angle, is under test)."""
    d = os.path.join(tmp, "repose")
    run_colza(colza, "run", "repose", "--quiet", "--config", os.path.join(source, "tests", "data", "small_repose.toml"),
              "--out", d, "--set", "repose.rest_max_time=0.3", "--set", "output.snapshot_interval=0")
    assert plots_of(d) == ["heap_profile.png"], plots_of(d)
    check_png(os.path.join(d, "plots", "heap_profile.png"))


def scene(colza, source, tmp):
    """A generic scene draws its energy budget and its recorded particles' contact forces."""
    d = os.path.join(tmp, "scene")
    run_colza(colza, "run", "scene", "--quiet", "--config", os.path.join(source, "crosscheck", "scenes", "micro_damping.toml"),
              "--out", d)
    assert plots_of(d) == ["scene_series.png"], plots_of(d)
    check_png(os.path.join(d, "plots", "scene_series.png"))


CASES = {"oedometer": oedometer, "shear": shear, "repose": repose, "scene": scene, "calibration": calibration,
         "diagnosis": diagnosis}


def main():
    colza, source = args()
    source = os.path.abspath(source)
    case = sys.argv[3] if len(sys.argv) > 3 else ""
    if case not in CASES:
        sys.exit(f"usage: {sys.argv[0]} COLZA_EXECUTABLE SOURCE_DIR {'|'.join(CASES)}")
    with Scratch() as tmp:
        CASES[case](colza, source, tmp)
    print(f"ok: {case} plots")


if __name__ == "__main__":
    main()
