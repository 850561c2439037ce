// A diagnosis's outputs: summary.json (every number, machine-readable) and report.md (the
// four steps for a reader: what the simulation gets wrong, the candidates' tests and
// signatures, the extended models, the gain, and the verdict).
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "diagnose/diagnosis.hpp"

namespace colza::diagnose {

struct DiagnosisContext {
  std::string spec_file, title;
  double wall_seconds = 0.0;
  int reused_runs = 0;  // of result.forward_runs, answered from finished runs
  std::vector<std::string> notes;  // sample sizes and why, extended configs written, ...
};

nlohmann::json diagnosis_summary(const DiagnosisProblem& p, const DiagnosisResult& d, const DiagnosisContext& ctx);
std::string diagnosis_report(const DiagnosisProblem& p, const DiagnosisResult& d, const DiagnosisContext& ctx);

}  // namespace colza::diagnose
