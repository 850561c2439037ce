// Plots of a result directory (issue 42): `colza plot DIR`, and every run, calibration and
// diagnosis after it has written its result. The drawing is python/colza_plot.py (matplotlib),
// run with /usr/bin/python3 (or $COLZA_PYTHON); the script is $COLZA_PLOT_SCRIPT, else the
// source tree's (COLZA_PLOT_SCRIPT, set by CMake).
#pragma once
#include <filesystem>
#include <string>

namespace colza {

enum class PlotOutcome { kDrawn, kNoPlottingStack, kFailed };

// Runs the plot script on `dir` (its stdout and stderr pass through; `quiet`: stdout
// discarded). Never throws: what went wrong is the outcome, and `why` says it.
PlotOutcome draw_plots(const std::filesystem::path& dir, bool quiet, std::string& why,
                       const std::string& measured_shear = "");

// After a run: draws the plots, or prints "colza: warning: no plots: <why>" on stderr. The
// run's result stands either way.
void plot_after_run(const std::filesystem::path& dir, bool quiet);

struct PlotOptions {
  std::string dir;
  std::string measured_shear;  // --measured-shear CSV, "none", or empty (the script's default)
};

// `colza plot DIR`: 0 drawn, 1 when nothing could be drawn (the reason on stderr), 2 when DIR
// is not a result.
int plot_command(const PlotOptions& options);

}  // namespace colza
