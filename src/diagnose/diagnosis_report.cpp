#include "diagnose/diagnosis_report.hpp"

#include <cmath>
#include <sstream>

#include "io/format_number.hpp"

namespace colza::diagnose {

namespace {

std::string fmt(double v) { return std::isnan(v) ? "-" : format_significant(v, 4); }

nlohmann::json vec(const Eigen::VectorXd& v) {
  nlohmann::json a = nlohmann::json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) a.push_back(v[i]);
  return a;
}

nlohmann::json fit_json(const DiagnosisProblem& p, const Fit& f, const std::vector<std::string>& names) {
  nlohmann::json parameters = nlohmann::json::object();
  for (std::size_t j = 0; j < names.size() && static_cast<Eigen::Index>(j) < f.parameters.size(); ++j)
    parameters[names[j]] = {{"value", f.parameters[static_cast<Eigen::Index>(j)]},
                            {"sigma", f.sigma.size() > static_cast<Eigen::Index>(j) ? f.sigma[static_cast<Eigen::Index>(j)] : NAN}};
  nlohmann::json features = nlohmann::json::object();
  for (std::size_t i = 0; i < p.features.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    features[p.features[i].name] = {{"model", f.mean_features[k]},
                                    {"noise_sd", f.noise.sd[k]},
                                    {"scatter_sd", f.noise.scatter_sd[k]},
                                    {"z", f.adequacy.z[k]}};
  }
  nlohmann::json held = nlohmann::json::array();
  for (bool b : f.held_at_bound) held.push_back(b);
  return {{"model", f.model},
          {"parameters", parameters},
          {"refit_shift", vec(f.refit_shift)},
          {"refit_held_at_bound", held},
          {"features", features},
          {"chi_square", f.adequacy.chi_square},
          {"degrees_of_freedom", f.adequacy.degrees_of_freedom},
          {"p_value", f.adequacy.p_value},
          {"adequate", f.adequacy.passes},
          {"realisations", f.noise.realisations},
          {"scatter_shrinkage", f.noise.shrinkage},
          {"calibration_runs", f.calibration_runs},
          {"strength_at_upper_bound", f.strength_at_upper_bound}};
}

std::vector<std::string> baseline_names(const DiagnosisProblem& p) {
  std::vector<std::string> n;
  for (const auto& par : p.parameters) n.push_back(par.name);
  return n;
}

}  // namespace

nlohmann::json diagnosis_summary(const DiagnosisProblem& p, const DiagnosisResult& d, const DiagnosisContext& ctx) {
  nlohmann::json measured = nlohmann::json::array();
  for (const Feature& f : p.features)
    measured.push_back({{"feature", f.name}, {"unit", f.unit}, {"test", f.test}, {"value", f.measured},
                        {"uncertainty", f.uncertainty}});
  nlohmann::json j = {{"spec", ctx.spec_file},
                      {"title", ctx.title},
                      {"verdict", {{"kind", to_string(d.verdict.kind)},
                                   {"cause", d.verdict.cause >= 0 ? p.candidates[static_cast<std::size_t>(d.verdict.cause)].name : ""},
                                   {"runner_up", d.verdict.runner_up >= 0 ? p.candidates[static_cast<std::size_t>(d.verdict.runner_up)].name : ""},
                                   {"experiment", d.verdict.experiment},
                                   {"text", d.verdict.text}}},
                      {"significance", p.settings.significance},
                      {"measured", measured},
                      {"baseline", fit_json(p, d.baseline, baseline_names(p))},
                      {"baseline_bic", d.baseline_bic},
                      {"forward_runs", d.forward_runs},
                      {"reused_runs", ctx.reused_runs},
                      {"wall_seconds", ctx.wall_seconds},
                      {"warnings", d.warnings},
                      {"notes", ctx.notes}};
  nlohmann::json cands = nlohmann::json::array();
  for (std::size_t k = 0; k < p.candidates.size(); ++k) {
    const Candidate& c = p.candidates[k];
    nlohmann::json e = {{"name", c.name}, {"kind", to_string(c.kind)}, {"settings", c.settings},
                        {"parameter", c.parameter.key}, {"neutral", c.neutral()}, {"upper", c.parameter.upper},
                        {"probe", c.probe}};
    if (k < d.signatures.size()) {
      const CandidateScore& s = d.scores.scores[k];
      e["signature"] = vec(d.signatures[k].mean);
      e["signature_standard_error"] = vec(d.signatures[k].standard_error);
      e["signature_seeds"] = d.signatures[k].seeds;
      e["score"] = {{"z", s.z}, {"p_value", s.p_value}, {"adjusted_p", s.adjusted_p},
                    {"absorbed_fraction", s.absorbed_fraction}, {"alignment", s.alignment},
                    {"linear_estimate", s.estimate}, {"linear_estimate_sd", s.estimate_sd},
                    {"signal_to_noise", s.signal_to_noise}, {"reach", s.reach}};
    }
    cands.push_back(e);
  }
  j["candidates"] = cands;
  if (d.scores.cosine.size() > 0) {
    nlohmann::json m = nlohmann::json::array();
    for (Eigen::Index r = 0; r < d.scores.cosine.rows(); ++r) m.push_back(vec(d.scores.cosine.row(r).transpose()));
    j["signature_cosines"] = m;
  }
  nlohmann::json ext = nlohmann::json::array();
  for (const ExtendedFit& e : d.extended) {
    std::vector<std::string> names = baseline_names(p);
    names.push_back(p.candidates[static_cast<std::size_t>(e.candidate)].parameter.name);
    nlohmann::json f = fit_json(p, e.fit, names);
    f["chi_square_under_baseline_noise"] = e.chi_square_common;
    f["likelihood_ratio_p"] = e.likelihood_ratio_p;
    f["bic"] = e.bic;
    f["searches"] = e.searches;
    f["search_start"] = vec(e.start);
    ext.push_back(f);
  }
  j["extended"] = ext;
  nlohmann::json held = nlohmann::json::array();
  for (const auto& h : d.held_out) held.push_back({{"test", h.test}, {"rms_before", h.rms_before}, {"rms_after", h.rms_after}});
  j["held_out"] = held;
  return j;
}

std::string diagnosis_report(const DiagnosisProblem& p, const DiagnosisResult& d, const DiagnosisContext& ctx) {
  std::ostringstream o;
  o << "# Diagnosis" << (ctx.title.empty() ? "" : ": " + ctx.title) << "\n\n";
  o << "Spec: `" << ctx.spec_file << "`. " << d.forward_runs << " forward runs (" << ctx.reused_runs
    << " reused), " << fmt(ctx.wall_seconds) << " s wall time.\n\n";
  o << "## Verdict: " << to_string(d.verdict.kind) << "\n\n" << d.verdict.text << "\n\n";
  o << "## 1. What the simulation gets wrong\n\n";
  o << "The baseline calibrated to every feature, then run in " << d.baseline.noise.realisations
    << " realisations (other seeds) at the fit. Noise = measurement uncertainty and realisation scatter "
       "(src/diagnose/noise_model.hpp); z = (measured - model) / noise.\n\n";
  // The model at the fit, and after the linearised refit (the residual z is judged on).
  const bool refit = d.baseline.refit_shift.size() == d.baseline_sensitivity.cols();
  const Eigen::VectorXd refitted =
      refit ? Eigen::VectorXd(d.baseline.mean_features + d.baseline_sensitivity * d.baseline.refit_shift)
            : d.baseline.mean_features;
  o << "| feature | test | measured | model at the fit | after the refit | noise sd | z |\n|---|---|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < p.features.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    const std::string& unit = p.features[i].unit;
    o << "| " << p.features[i].name << (unit.empty() || unit == "-" ? "" : " (" + unit + ")") << " | "
      << p.features[i].test << " | "
      << fmt(p.features[i].measured) << " | " << fmt(d.baseline.mean_features[k]) << " | " << fmt(refitted[k]) << " | "
      << fmt(d.baseline.noise.sd[k]) << " | " << fmt(d.baseline.adequacy.z[k]) << " |\n";
  }
  if (refit) {
    o << "\nLinearised refit from the fit (shift within the ranges): ";
    for (std::size_t j = 0; j < p.parameters.size(); ++j)
      o << (j ? "; " : "") << p.parameters[j].name << " "
        << (d.baseline.refit_shift[static_cast<Eigen::Index>(j)] >= 0 ? "+" : "")
        << fmt(d.baseline.refit_shift[static_cast<Eigen::Index>(j)])
        << (d.baseline.held_at_bound[j] ? " (held at its bound)" : "");
    o << ".\n";
  }
  o << "\nAdequacy: chi2 = " << fmt(d.baseline.adequacy.chi_square) << " on " << d.baseline.adequacy.degrees_of_freedom
    << (d.baseline.adequacy.degrees_of_freedom == 1 ? " degree" : " degrees")
    << " of freedom, p = " << fmt(d.baseline.adequacy.p_value) << " (alpha = " << fmt(p.settings.significance)
    << "). Baseline parameters: ";
  for (std::size_t j = 0; j < p.parameters.size(); ++j)
    o << (j ? "; " : "") << p.parameters[j].name << " = " << fmt(d.baseline.parameters[static_cast<Eigen::Index>(j)])
      << " +/- " << fmt(d.baseline.sigma[static_cast<Eigen::Index>(j)]) << unit_suffix(p.parameters[j].unit);
  o << ".\n\n";
  if (!d.signatures.empty()) {
    o << "## 2. Candidates\n\nEach candidate's signature (d feature / d parameter from its neutral value, common random "
         "numbers), the part the baseline's own parameters cannot absorb, and the one-sided score test against the "
         "residual (adjusted by max-T over " << p.candidates.size() << " candidates, their null correlations the projected signatures' cosines).\n\n";
    o << "| candidate | z | p (adjusted) | absorbed by the baseline | alignment with residual | linear estimate | reach (noise units) | signature: signal / error (pairs) |\n|---|---|---|---|---|---|---|---|\n";
    for (std::size_t k = 0; k < p.candidates.size(); ++k) {
      const CandidateScore& s = d.scores.scores[k];
      o << "| " << p.candidates[k].name << " | " << fmt(s.z) << " | " << fmt(s.adjusted_p) << " | "
        << fmt(100.0 * s.absorbed_fraction) << " % | " << fmt(s.alignment) << " | " << fmt(p.candidates[k].neutral() + s.estimate)
        << " +/- " << fmt(s.estimate_sd) << " | " << fmt(s.reach) << " | " << fmt(s.signal_to_noise) << " ("
        << d.signatures[k].seeds << ") |\n";
    }
    o << "\nCosines of the projected signatures (near 1: these data cannot tell the two apart):\n\n|  |";
    for (const auto& c : p.candidates) o << " " << c.name << " |";
    o << "\n|---|";
    for (std::size_t k = 0; k < p.candidates.size(); ++k) o << "---|";
    o << "\n";
    for (std::size_t a = 0; a < p.candidates.size(); ++a) {
      o << "| " << p.candidates[a].name << " |";
      for (std::size_t b = 0; b < p.candidates.size(); ++b)
        o << " " << fmt(d.scores.cosine(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b))) << " |";
      o << "\n";
    }
    o << "\n";
  }
  if (!d.extended.empty()) {
    o << "## 3. Extended models\n\nEach strength's +/- is the larger of two linearisations: with its signature from the "
       "neutral value, and with its slope at the fit (common random numbers).\n\n| model | chi2 (own noise) | p | chi2 (baseline noise) | likelihood ratio p | BIC | strength |\n|---|---|---|---|---|---|---|\n";
    o << "| baseline | " << fmt(d.baseline.adequacy.chi_square) << " | " << fmt(d.baseline.adequacy.p_value) << " | "
      << fmt(d.baseline.adequacy.chi_square) << " | - | " << fmt(d.baseline_bic) << " | - |\n";
    for (const ExtendedFit& e : d.extended) {
      const Candidate& c = p.candidates[static_cast<std::size_t>(e.candidate)];
      const Eigen::Index j = e.fit.parameters.size() - 1;
      o << "| " << c.name << " | " << fmt(e.fit.adequacy.chi_square) << " | " << fmt(e.fit.adequacy.p_value) << " | "
        << fmt(e.chi_square_common) << " | " << fmt(e.likelihood_ratio_p) << " | " << fmt(e.bic) << " | "
        << c.parameter.name << " = " << fmt(e.fit.parameters[j]) << " +/- " << fmt(e.fit.sigma[j]) << unit_suffix(c.parameter.unit)
        << (e.fit.strength_at_upper_bound ? " (at its physical top)" : "") << " |\n";
    }
    o << "\n";
    for (const ExtendedFit& e : d.extended)
      if (e.searches > 1)
        o << p.candidates[static_cast<std::size_t>(e.candidate)].name
          << ": the search from the baseline's fit ended at a fit the adequacy test rejects; a second search began at "
             "the joint linearised fit and the better of the two is shown (" << e.fit.calibration_runs << " runs in all).\n\n";
  }
  if (!d.extended.empty()) {
    o << "## 4. The gain\n\nMisfit per feature, noise units, before and after:\n\n| feature | baseline z |";
    for (const ExtendedFit& e : d.extended) o << " " << p.candidates[static_cast<std::size_t>(e.candidate)].name << " z |";
    o << "\n|---|---|";
    for (std::size_t k = 0; k < d.extended.size(); ++k) o << "---|";
    o << "\n";
    for (std::size_t i = 0; i < p.features.size(); ++i) {
      o << "| " << p.features[i].name << " | " << fmt(d.baseline.adequacy.z[static_cast<Eigen::Index>(i)]) << " |";
      for (const ExtendedFit& e : d.extended) o << " " << fmt(e.fit.adequacy.z[static_cast<Eigen::Index>(i)]) << " |";
      o << "\n";
    }
    if (!d.held_out.empty()) {
      o << "\nEach test held out (calibrate without it, predict it; linearised about each fit, "
           "src/diagnose/held_out.hpp), RMS error in units of the prediction's own sd (the noise and what the "
           "other tests leave undetermined; - where they do not determine it):\n\n| held out | baseline | extended |\n|---|---|---|\n";
      for (const auto& h : d.held_out) o << "| " << h.test << " | " << fmt(h.rms_before) << " | " << fmt(h.rms_after) << " |\n";
    }
    o << "\n";
  }
  if (!d.warnings.empty() || !ctx.notes.empty()) {
    o << "## Notes\n\n";
    for (const auto& w : d.warnings) o << "* " << w << "\n";
    for (const auto& n : ctx.notes) o << "* " << n << "\n";
  }
  return o.str();
}

}  // namespace colza::diagnose
