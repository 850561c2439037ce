#include "diagnose/verdict.hpp"

#include <algorithm>
#include <cmath>

#include "diagnose/model_comparison.hpp"
#include "io/format_number.hpp"

namespace colza::diagnose {

namespace {

std::string fmt(double v) { return format_significant(v, 3); }

// An extended model that explains the data: it passes its adequacy test with degrees of
// freedom left to fail it (with as many parameters as features it fits anything), improves
// on the baseline significantly, and needs no strength beyond the physical range.
bool acceptable(const ExtendedFit& e, double alpha) {
  return e.fit.adequacy.passes && e.fit.adequacy.degrees_of_freedom > 0 && e.likelihood_ratio_p < alpha &&
         !e.fit.strength_at_upper_bound;
}

// The features the remaining residual is largest in, as "name (z = ...)".
std::string residual_pattern(const DiagnosisProblem& p, const Fit& f) {
  std::vector<int> idx(static_cast<std::size_t>(f.adequacy.z.size()));
  for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = static_cast<int>(i);
  std::sort(idx.begin(), idx.end(), [&](int a, int b) { return std::abs(f.adequacy.z[a]) > std::abs(f.adequacy.z[b]); });
  std::string s;
  for (std::size_t k = 0; k < std::min<std::size_t>(3, idx.size()); ++k)
    s += (k ? ", " : "") + p.features[static_cast<std::size_t>(idx[k])].name + " (z = " + fmt(f.adequacy.z[idx[k]]) + ")";
  return s;
}

}  // namespace

const char* to_string(VerdictKind k) {
  switch (k) {
    case VerdictKind::kNoDiscrepancy: return "no significant discrepancy";
    case VerdictKind::kExplained: return "explained";
    case VerdictKind::kAmbiguous: return "ambiguous";
    case VerdictKind::kUnexplained: return "unexplained";
  }
  return "?";
}

std::vector<int> significant_candidates(const ScoreTests& scores, double alpha) {
  std::vector<int> s;
  for (std::size_t k = 0; k < scores.scores.size(); ++k)
    if (scores.scores[k].adjusted_p < alpha) s.push_back(static_cast<int>(k));
  std::sort(s.begin(), s.end(), [&](int a, int b) { return scores.scores[a].z > scores.scores[b].z; });
  return s;
}

Verdict decide(const DiagnosisProblem& p, const Fit& baseline, double baseline_bic, const ScoreTests& scores,
               const std::vector<ExtendedFit>& extended) {
  const double alpha = p.settings.significance;
  const auto& cands = p.candidates;
  Verdict v;
  const AdequacyTest& a = baseline.adequacy;
  const std::string adequacy_text = "chi2 = " + fmt(a.chi_square) + " on " + std::to_string(a.degrees_of_freedom) +
                                    (a.degrees_of_freedom == 1 ? " degree" : " degrees") + " of freedom, p = " + fmt(a.p_value);
  if (a.passes) {
    v.kind = VerdictKind::kNoDiscrepancy;
    v.text = "No significant discrepancy: the calibrated baseline reproduces every feature within its noise (" +
             adequacy_text + " >= alpha = " + fmt(alpha) + "). The data give no reason to extend the model.";
    std::vector<std::string> feature_names;
    for (const Feature& f : p.features) feature_names.push_back(f.name);
    std::string unseen;
    for (const Candidate& c : cands)
      if (const std::string why = unseen_by(c.kind, feature_names); !why.empty() && unseen.find(why) == std::string::npos)
        unseen += (unseen.empty() ? "" : "; ") + why;
    if (!unseen.empty())
      v.text += " These tests may not see every candidate: " + unseen + ".";
    return v;
  }
  const std::vector<int> significant = significant_candidates(scores, alpha);
  if (significant.empty()) {
    v.kind = VerdictKind::kUnexplained;
    v.text = "Unexplained: the baseline misses the data (" + adequacy_text + ") and no candidate points along the "
             "residual its own parameters cannot absorb (every adjusted score-test p >= " + fmt(alpha) +
             "). The largest residuals: " + residual_pattern(p, baseline) + ".";
    return v;
  }
  std::vector<const ExtendedFit*> ok;
  for (const auto& e : extended)
    if (acceptable(e, alpha)) ok.push_back(&e);
  std::sort(ok.begin(), ok.end(), [](const ExtendedFit* x, const ExtendedFit* y) { return x->bic < y->bic; });
  if (ok.empty()) {
    v.kind = VerdictKind::kUnexplained;
    std::string why;
    for (const auto& e : extended) {
      const std::string& n = cands[static_cast<std::size_t>(e.candidate)].name;
      if (e.fit.strength_at_upper_bound)
        why += " " + n + " would need more than its physical range (its strength stops at the top, " +
               fmt(cands[static_cast<std::size_t>(e.candidate)].parameter.upper) + ");";
      else if (e.fit.adequacy.degrees_of_freedom == 0)
        why += " with " + n + " the model has as many parameters as there are features, so it fits them whatever the "
               "cause (chi2 " + fmt(baseline.adequacy.chi_square) + " -> " + fmt(e.fit.adequacy.chi_square) +
               "): nothing is left to test it with; more features (another test, another load) would;";
      else if (!e.fit.adequacy.passes)
        why += " with " + n + " the misfit falls from chi2 = " + fmt(baseline.adequacy.chi_square) + " to " +
               fmt(e.fit.adequacy.chi_square) + " but stays significant (p = " + fmt(e.fit.adequacy.p_value) + ");";
      else
        why += " " + n + " does not improve the fit significantly (likelihood ratio p = " + fmt(e.likelihood_ratio_p) +
               ");";
    }
    // The residual left by the best extended model that was tested, else the baseline's.
    const Fit* left = &baseline;
    for (const auto& e : extended)
      if (e.fit.adequacy.degrees_of_freedom > 0 && (left == &baseline || e.fit.adequacy.chi_square < left->adequacy.chi_square))
        left = &e.fit;
    if (!why.empty() && why.back() == ';') why.back() = '.';
    v.text = "Unexplained: the baseline misses the data (" + adequacy_text + ");" + why + " The " +
             (left == &baseline ? "baseline's" : left->model + " model's") + " residual is largest in " +
             residual_pattern(p, *left) + ".";
    return v;
  }
  const ExtendedFit& best = *ok.front();
  v.cause = best.candidate;
  const Candidate& x = cands[static_cast<std::size_t>(best.candidate)];
  // The runner-up: a candidate whose projected signature the data cannot tell from the
  // cause's (significant or not: along nearly the same direction its score differs from the
  // cause's by the noise of the signatures, and a BIC difference between their fits by the
  // calibrations' noise), or another acceptable extended model within "positive evidence"
  // of the best's BIC.
  for (std::size_t k = 0; k < cands.size(); ++k) {
    const int other = static_cast<int>(k);
    if (other == best.candidate || scores.cosine(best.candidate, other) < p.settings.ambiguity_cosine) continue;
    if (v.runner_up < 0 || scores.scores[k].z > scores.scores[static_cast<std::size_t>(v.runner_up)].z) v.runner_up = other;
  }
  if (v.runner_up < 0)
    for (const ExtendedFit* e : ok)
      if (e != &best && e->bic - best.bic < kPositiveEvidence) {
        v.runner_up = e->candidate;
        break;
      }
  if (v.runner_up >= 0) {
    const Candidate& y = cands[static_cast<std::size_t>(v.runner_up)];
    v.kind = VerdictKind::kAmbiguous;
    v.experiment = separating_experiment(x.kind, y.kind);
    v.text = "Ambiguous between " + x.name + " and " + y.name + ": both account for the discrepancy (" +
             adequacy_text + " for the baseline); their signatures on these features have a cosine of " +
             fmt(scores.cosine(best.candidate, v.runner_up)) + ". To tell them apart: " + v.experiment + ".";
    return v;
  }
  v.kind = VerdictKind::kExplained;
  const std::size_t j = static_cast<std::size_t>(best.fit.parameters.size() - 1);
  v.text = "Explained by " + x.name + ": the baseline misses the data (" + adequacy_text + "); with " +
           x.parameter.name + " = " + fmt(best.fit.parameters[static_cast<Eigen::Index>(j)]) + " +/- " +
           fmt(best.fit.sigma[static_cast<Eigen::Index>(j)]) + unit_suffix(x.parameter.unit) +
           " the extended model passes (chi2 = " + fmt(best.fit.adequacy.chi_square) + ", p = " +
           fmt(best.fit.adequacy.p_value) + "), the likelihood ratio against the baseline has p = " +
           fmt(best.likelihood_ratio_p) + " and its BIC is " + fmt(best.bic) + " against the baseline's " + fmt(baseline_bic) + ".";
  return v;
}

}  // namespace colza::diagnose
