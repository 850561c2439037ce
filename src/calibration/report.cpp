#include "calibration/report.hpp"

#include <cmath>
#include <filesystem>
#include <cstdio>
#include <sstream>

#include "io/format_number.hpp"

namespace colza::calibration {

namespace {

std::string g(double v, int digits = 5) { return format_significant(v, digits); }

nlohmann::json finite_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

}  // namespace

nlohmann::json calibration_summary(const Problem& p, const CalibrationResult& r, const ReportContext& ctx) {
  nlohmann::json s;
  s["stage"] = ctx.stage;
  s["mode"] = r.mode;
  s["spec"] = ctx.spec_file;
  s["measured_file"] = ctx.measured_file;
  if (!ctx.measured.is_null()) s["measured"] = ctx.measured;
  s["parameters"] = nlohmann::json::array();
  for (std::size_t j = 0; j < p.parameters.size(); ++j)
    s["parameters"].push_back({{"name", p.parameters[j].name},
                               {"key", p.parameters[j].key},
                               {"unit", p.parameters[j].unit},
                               {"value", r.solution[j]},
                               {"uncertainty", finite_or_null(r.sigma[j])},
                               {"uncertainty_from_targets", finite_or_null(r.sigma_target[j])},
                               {"uncertainty_from_surface", finite_or_null(r.sigma_surface[j])},
                               {"uncertainty_from_scatter",
                                r.scatter.size() ? finite_or_null(r.sigma_scatter[j]) : nlohmann::json(nullptr)},
                               {"bounds", {p.parameters[j].lower, p.parameters[j].upper}}});
  s["targets"] = nlohmann::json::array();
  for (std::size_t i = 0; i < p.targets.size(); ++i)
    s["targets"].push_back({{"name", p.targets[i].name},
                            {"unit", p.targets[i].unit},
                            {"measured", p.targets[i].value},
                            {"uncertainty", p.targets[i].uncertainty},
                            {"predicted_by_surface", r.predicted[i]},
                            {"achieved", r.achieved[i]},
                            {"error", r.error[i]},
                            {"relative_error", p.targets[i].value != 0.0 ? r.error[i] / std::abs(p.targets[i].value) : 0.0},
                            {"error_in_uncertainties", r.error[i] / p.targets[i].uncertainty},
                            {"tolerance", r.tolerance[i]}});
  s["within_uncertainty"] = r.within_uncertainty;
  const auto matrix = [](const Eigen::MatrixXd& m) {
    nlohmann::json rows = nlohmann::json::array();
    for (Eigen::Index i = 0; i < m.rows(); ++i) {
      std::vector<double> row(static_cast<std::size_t>(m.cols()));
      for (Eigen::Index j = 0; j < m.cols(); ++j) row[static_cast<std::size_t>(j)] = m(i, j);
      rows.push_back(row);
    }
    return rows;
  };
  if (p.target_correlation.size()) s["target_correlation"] = matrix(p.target_correlation);
  if (r.confirmation.size()) {
    nlohmann::json c = {{"replicate", 1},
                        {"misfit", r.confirmation_misfit},
                        {"within", r.confirmation_misfit <= 1.0},
                        {"note", "another realisation (seed + 1) at the solution, which took no part in choosing it"}};
    c["targets"] = nlohmann::json::array();
    for (std::size_t i = 0; i < p.targets.size(); ++i)
      c["targets"].push_back({{"name", p.targets[i].name},
                              {"achieved", r.confirmation[i]},
                              {"error", r.confirmation[i] - p.targets[i].value}});
    s["confirmation"] = c;
  }
  if (r.scatter.size()) {
    nlohmann::json sc = {{"replicates", p.replicates},
                         {"realisations", p.replicates + 1},
                         {"degrees_of_freedom", p.replicates},
                         {"at", std::vector<double>(r.scatter_at.data(), r.scatter_at.data() + r.scatter_at.size())},
                         {"where", r.mode == "paper" ? "the solution (validation averaged over the realisations)"
                                                     : "the first start point (before refining)"}};
    sc["targets"] = nlohmann::json::array();
    for (std::size_t i = 0; i < p.targets.size(); ++i)
      sc["targets"].push_back({{"name", p.targets[i].name}, {"std", r.scatter[i]},
                               {"std_over_uncertainty", r.scatter[i] / p.targets[i].uncertainty}});
    s["scatter"] = sc;
  }
  s["surfaces"] = nlohmann::json::array();
  std::vector<std::string> names;
  for (const auto& par : p.parameters) names.push_back(par.name);
  for (std::size_t i = 0; i < r.surfaces.size(); ++i) {
    const auto& f = r.surfaces[i];
    nlohmann::json js = {{"target", p.targets[i].name},
                         {"kind", to_string(f.kind())},
                         {"terms", f.term_names(names)},
                         {"coefficients_scaled", std::vector<double>(f.coefficients().data(), f.coefficients().data() + f.coefficients().size())},
                         {"scaling_mid", std::vector<double>(f.scaling().mid.data(), f.scaling().mid.data() + f.scaling().mid.size())},
                         {"scaling_half", std::vector<double>(f.scaling().half.data(), f.scaling().half.data() + f.scaling().half.size())},
                         {"r2", f.r2()},
                         {"residual_std", f.residual_std()},
                         {"points", f.points()},
                         {"degrees_of_freedom", f.degrees_of_freedom()}};
    if (f.kind() == SurfaceKind::kPlane) {
      const Eigen::VectorXd a = f.plane_in_si();
      js["plane_si"] = std::vector<double>(a.data(), a.data() + a.size());
    }
    s["surfaces"].push_back(js);
  }
  s["jacobian"] = nlohmann::json::array();
  for (Eigen::Index i = 0; i < r.jacobian.rows(); ++i) {
    std::vector<double> row(r.jacobian.cols());
    for (Eigen::Index j = 0; j < r.jacobian.cols(); ++j) row[j] = r.jacobian(i, j);
    s["jacobian"].push_back(row);
  }
  s["runs"] = nlohmann::json::array();
  std::size_t reused = 0;
  for (std::size_t k = 0; k < r.runs.size(); ++k) {
    nlohmann::json j = {{"role", r.runs[k].role}, {"iteration", r.runs[k].iteration}, {"replicate", r.runs[k].replicate},
                        {"parameters", std::vector<double>(r.runs[k].x.data(), r.runs[k].x.data() + r.runs[k].x.size())},
                        {"targets", std::vector<double>(r.runs[k].y.data(), r.runs[k].y.data() + r.runs[k].y.size())}};
    if (k < ctx.run_ids.size()) {
      j["id"] = ctx.run_ids[k];
      j["summary"] = (std::filesystem::path(ctx.runs_dir) / ctx.run_ids[k] / "summary.json").string();
      j["reused"] = static_cast<bool>(ctx.run_reused[k]);
      j["wall_seconds"] = ctx.run_wall_seconds[k];
      reused += ctx.run_reused[k] ? 1 : 0;
    }
    s["runs"].push_back(j);
  }
  s["runs_used"] = r.runs.size();
  s["runs_reused"] = reused;
  s["paper_design_runs"] = ctx.paper_design_runs;
  s["iterations"] = r.iterations;
  s["wall_seconds"] = ctx.wall_seconds;
  std::vector<std::string> w = ctx.extra_warnings;
  w.insert(w.end(), r.warnings.begin(), r.warnings.end());
  s["warnings"] = w;
  return s;
}

std::string calibration_report(const Problem& p, const CalibrationResult& r, const ReportContext& ctx) {
  std::ostringstream o;
  o << "# colza calibration: " << ctx.stage << " (" << r.mode << " mode)\n\n";
  if (!ctx.title.empty()) o << ctx.title << "\n\n";
  o << "Spec: `" << ctx.spec_file << "`";
  if (!ctx.measured_file.empty()) o << "; measured data: `" << ctx.measured_file << "`";
  o << ".\n\n";
  if (!ctx.notes.empty()) o << ctx.notes << "\n\n";
  if (!ctx.measured_section.empty()) o << ctx.measured_section << "\n";
  o << "Forward runs used: **" << r.runs.size() << "**";
  if (ctx.paper_design_runs)
    o << " (the paper's design on the same targets: " << ctx.paper_design_runs << " = design points + 1 validation"
      << (p.replicates ? " + " + std::to_string(p.replicates) + " replicates" : std::string()) << ")";
  o << "; wall time " << g(ctx.wall_seconds, 4) << " s.\n\n";

  const Eigen::VectorXd run_tolerance = single_run_tolerance(p, r.scatter);
  o << "## Design and runs\n\n| # | role | ";
  for (const auto& par : p.parameters) o << par.name << " (" << par.unit << ") | ";
  for (const auto& t : p.targets) o << t.name << " (" << t.unit << ") | ";
  o << (r.scatter.size() ? "misfit (tolerances) | run |\n|" : "misfit (sigmas) | run |\n|");
  for (std::size_t k = 0; k < 3 + p.parameters.size() + p.targets.size() + 1; ++k) o << "---|";
  o << "\n";
  for (std::size_t k = 0; k < r.runs.size(); ++k) {
    // Streamed piece by piece: GCC 12 warns (-Wrestrict, falsely) on " " + std::to_string(...).
    o << "| " << k + 1 << " | " << r.runs[k].role;
    if (r.runs[k].iteration) o << ' ' << r.runs[k].iteration;
    if (r.runs[k].replicate) o << " (seed +" << r.runs[k].replicate << ')';
    o << " | ";
    for (Eigen::Index j = 0; j < r.runs[k].x.size(); ++j) o << g(r.runs[k].x[j]) << " | ";
    for (Eigen::Index i = 0; i < r.runs[k].y.size(); ++i) o << g(r.runs[k].y[i]) << " | ";
    o << g(normalised_misfit(p, r.runs[k].y, run_tolerance), 3) << " | ";
    if (k < ctx.run_ids.size())
      o << "`" << (std::filesystem::path(ctx.runs_dir) / ctx.run_ids[k]).string() << "` " << g(ctx.run_wall_seconds[k], 3) << " s" << (ctx.run_reused[k] ? " (reused)" : "");
    o << " |\n";
  }

  o << "\n## Response surfaces\n\nParameters scaled to the bounds: u = (x - mid) / half.\n\n";
  std::vector<std::string> names;
  for (const auto& par : p.parameters) names.push_back(par.name);
  for (std::size_t i = 0; i < r.surfaces.size(); ++i) {
    const auto& f = r.surfaces[i];
    o << "* **" << p.targets[i].name << "**: " << to_string(f.kind()) << " over " << f.points() << " points, R^2 = "
      << g(f.r2(), 4) << ", residual std = " << g(f.residual_std(), 4) << " " << p.targets[i].unit << " ("
      << f.degrees_of_freedom() << " dof). ";
    const auto terms = f.term_names(names);
    o << p.targets[i].name << " = ";
    for (std::size_t t = 0; t < terms.size(); ++t)
      o << (t ? " + " : "") << g(f.coefficients()[static_cast<Eigen::Index>(t)]) << (t ? " " + terms[t] : "");
    if (f.kind() == SurfaceKind::kPlane) {
      const Eigen::VectorXd a = f.plane_in_si();
      o << "; in SI: " << p.targets[i].name << " = " << g(a[0]);
      for (std::size_t j = 0; j < names.size(); ++j) o << " + " << g(a[1 + j]) << " " << names[j];
    }
    o << "\n";
  }

  if (r.scatter.size()) {
    o << "\n## Realisation scatter\n\nThe same parameters with " << p.replicates + 1 << " seeds (seed, seed + 1, ..) at "
      << (r.mode == "paper" ? "the solution" : "the first start point") << ": every run is one realisation of the "
      << "packing, so a target scatters around its mean even at fixed parameters.\n\n"
      << "| target | std over seeds | measurement uncertainty | std / uncertainty | tolerance used |\n|---|---|---|---|---|\n";
    for (std::size_t i = 0; i < p.targets.size(); ++i)
      o << "| " << p.targets[i].name << " (" << p.targets[i].unit << ") | " << g(r.scatter[i], 3) << " | "
        << g(p.targets[i].uncertainty, 3) << " | " << g(r.scatter[i] / p.targets[i].uncertainty, 3) << " | "
        << g(r.tolerance[i], 3) << " |\n";
    o << "\nStandard deviations over " << p.replicates + 1 << " realisations (" << p.replicates
      << " degrees of freedom). o = max(0, s^2 - residual^2) is the part of the scatter the design's surfaces do "
         "not show (a design sharing one packing carries one common offset); the parameter uncertainty adds it, "
         "propagated like the targets'. Tolerance: "
      << (r.mode == "paper"
              ? "sqrt(u^2 + s^2 / n + o (1 - 2 / n)) for the mean of the n = " + std::to_string(p.replicates + 1) +
                    " realisations at the solution; a single run in the table is judged against sqrt(u^2 + s^2)"
              : std::string("sqrt(u^2 + s^2) for a single run (the scatter measured at the first start point is "
                            "assumed to hold across the range)"))
      << ".\n";
  }
  o << "\n## Solution\n\n| parameter | value | uncertainty (1 sigma) | from targets | from surface | from scatter | bounds "
       "|\n|---|---|---|---|---|---|---|\n";
  for (std::size_t j = 0; j < p.parameters.size(); ++j)
    o << "| " << p.parameters[j].name << " (`" << p.parameters[j].key << "`, " << p.parameters[j].unit << ") | "
      << g(r.solution[j]) << " | " << g(r.sigma[j], 3) << " | " << g(r.sigma_target[j], 3) << " | "
      << g(r.sigma_surface[j], 3) << " | " << (r.scatter.size() ? g(r.sigma_scatter[j], 3) : std::string("not measured"))
      << " | " << g(p.parameters[j].lower) << " .. " << g(p.parameters[j].upper) << " |\n";
  o << "\nUncertainty: first order, dx = G dy with G = (J^T W J)^-1 J^T W (= J^-1 for as many targets as "
       "parameters), J the surfaces' Jacobian at the solution; target uncertainty, the surfaces' residual "
       "standard error and (when measured) the realisation scatter the surfaces do not show are propagated "
       "separately and combined in quadrature.\n";
  if (p.target_correlation.size() == 4 && p.target_correlation(0, 1) != 0.0)
    o << "The measured " << p.targets[0].name << " and " << p.targets[1].name
      << " come from one fit, so their errors are taken as correlated (" << g(p.target_correlation(0, 1), 3)
      << "): the weights and the measurement's share of the uncertainty use the full covariance.\n";
  else if (p.target_correlation.size() == 4)
    o << "The errors of the measured " << p.targets[0].name << " and " << p.targets[1].name
      << " are taken as independent (correlation 0, as the spec states).\n";

  const bool mean = r.scatter.size() && r.mode == "paper";
  o << "\n## Validation against the measured data\n\n| target | measured | surface at solution | DEM at solution"
    << (mean ? " (mean of " + std::to_string(p.replicates + 1) + " seeds)" : std::string())
    << " | error | error / uncertainty | error / tolerance |\n|---|---|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < p.targets.size(); ++i)
    o << "| " << p.targets[i].name << " (" << p.targets[i].unit << ") | " << g(p.targets[i].value) << " +/- "
      << g(p.targets[i].uncertainty, 3) << " | " << g(r.predicted[i]) << " | " << g(r.achieved[i]) << " | "
      << g(r.error[i], 3) << " (" << g(100.0 * r.error[i] / std::abs(p.targets[i].value), 3) << " %) | "
      << g(r.error[i] / p.targets[i].uncertainty, 3) << " | " << g(r.error[i] / r.tolerance[i], 3) << " |\n";
  o << "\nValidation " << (r.within_uncertainty ? "**within**" : "**NOT within**")
    << (r.scatter.size() ? " the tolerance (measurement uncertainty combined with the realisation scatter)"
                         : " the measurement uncertainty");
  // The sequential stop's confirmation (calibrate.cpp): the solution's run was within, so a
  // miss here is the other realisation's, which the table above does not show.
  if (r.confirmation.size() && r.confirmation_misfit <= 1.0)
    o << "; another realisation at the solution (seed + 1) is within it too (misfit " << g(r.confirmation_misfit, 3)
      << ")";
  else if (r.confirmation.size())
    o << ": the solution's run above is within it (misfit " << g(normalised_misfit(p, r.achieved, r.tolerance), 3)
      << "), but another realisation at the solution (seed + 1) misses it (misfit " << g(r.confirmation_misfit, 3)
      << "), so the stop may have been a lucky draw";
  o << ".\n";
  std::vector<std::string> w = ctx.extra_warnings;
  w.insert(w.end(), r.warnings.begin(), r.warnings.end());
  if (!w.empty()) {
    o << "\n## Warnings\n\n";
    for (const auto& x : w) o << "* " << x << "\n";
  }
  return o.str();
}

}  // namespace colza::calibration
