// Synthetic "measured" compression data for the DEM tests of `colza calibrate compression`,
// made as a lab would report them: several realisations of one truth, the curve of the one
// nearest their mean (a typical specimen), and their scatter as the uncertainties of c1 and
// c2 and the correlation of their errors. The oedometer's c1 and c2 are chaotic in the
// parameters, so one realisation alone may lie far out in that scatter; realisation k runs
// mu_pp + k x 1e-6, which changes no physics, only the chaotic path.
#pragma once

#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace colza::testing {

// x with all its digits, as a TOML value or a --set argument.
inline std::string exact(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

struct CompressionTruth {
  std::vector<double> c1, c2;  // each realisation's fit (N/m, N/m^2)
  double mean_c1 = 0.0, mean_c2 = 0.0;
  double sd_c1 = 0.0, sd_c2 = 0.0;  // sample standard deviations
  double correlation = 0.0;         // of c1 and c2 over the realisations
  std::size_t typical = 0;          // the realisation nearest the mean (Mahalanobis distance)
  std::filesystem::path measured_curve;  // its curve: columns displacement (m), force (N)
};

// Runs `realisations` oedometer loadings in dir/realisation-k: `run_args` (the colza command
// without the two parameters and --out, e.g. "run oedometer --quiet --config C --set
// oedometer.packing_file=..."), kn_p = kn, mu_pp = mu + k x 1e-6. Writes dir/measured.csv.
inline CompressionTruth make_compression_truth(const std::filesystem::path& dir, const std::string& run_args, double kn,
                                               double mu, int realisations) {
  if (realisations < 3) throw std::invalid_argument("a scatter and a correlation need at least 3 realisations");
  CompressionTruth t;
  for (int k = 0; k < realisations; ++k) {
    const auto out = dir / ("realisation-" + std::to_string(k));
    const CliResult r = run_colza(run_args + " --set particle.normal_stiffness=" + exact(kn) +
                                  " --set particle.friction=" + exact(mu + 1e-6 * k) + " --out " + out.string());
    if (r.exit_code != 0) throw std::runtime_error("truth realisation " + std::to_string(k) + ": " + r.stderr_text);
    const auto fit = read_json(out / "summary.json")["fit"];
    t.c1.push_back(fit["c1"].get<double>());
    t.c2.push_back(fit["c2"].get<double>());
  }
  const double n = static_cast<double>(realisations);
  for (int k = 0; k < realisations; ++k) t.mean_c1 += t.c1[k] / n, t.mean_c2 += t.c2[k] / n;
  double s11 = 0.0, s22 = 0.0, s12 = 0.0;
  for (int k = 0; k < realisations; ++k) {
    const double d1 = t.c1[k] - t.mean_c1, d2 = t.c2[k] - t.mean_c2;
    s11 += d1 * d1, s22 += d2 * d2, s12 += d1 * d2;
  }
  t.sd_c1 = std::sqrt(s11 / (n - 1.0));
  t.sd_c2 = std::sqrt(s22 / (n - 1.0));
  if (!(s11 > 0.0 && s22 > 0.0)) throw std::runtime_error("the realisations of the truth gave identical c1 or c2");
  t.correlation = s12 / std::sqrt(s11 * s22);
  if (!(1.0 - t.correlation * t.correlation > 1e-12))
    throw std::runtime_error("c1 and c2 of the realisations lie on a line: no distance to their mean");
  // d^2 = (z1^2 - 2 r z1 z2 + z2^2) / (1 - r^2), z the standardised deviations.
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < realisations; ++k) {
    const double z1 = (t.c1[k] - t.mean_c1) / t.sd_c1, z2 = (t.c2[k] - t.mean_c2) / t.sd_c2;
    const double d2 = (z1 * z1 - 2.0 * t.correlation * z1 * z2 + z2 * z2) / (1.0 - t.correlation * t.correlation);
    if (d2 < best) best = d2, t.typical = static_cast<std::size_t>(k);
  }
  // curve.csv: time, piston_displacement, piston_force, ... -> displacement, force.
  std::istringstream in(read_file(dir / ("realisation-" + std::to_string(t.typical)) / "curve.csv"));
  std::string line, csv = "displacement,force\n";
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::string time, s, f;
    std::getline(row, time, ',');
    std::getline(row, s, ',');
    std::getline(row, f, ',');
    csv += s + "," + f + "\n";
  }
  t.measured_curve = dir / "measured.csv";
  write_file(t.measured_curve, csv);
  return t;
}

// The [measured] table of a compression spec for that truth.
inline std::string measured_table(const CompressionTruth& t) {
  return "[measured]\ncurve = \"" + t.measured_curve.string() + "\"\nc1_uncertainty = " + exact(t.sd_c1) +
         "\nc2_uncertainty = " + exact(t.sd_c2) + "\ncorrelation = " + exact(t.correlation) + "\n";
}

}  // namespace colza::testing
