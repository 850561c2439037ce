// The diagnosis's decision (step 4), from the tests of steps 1-3, never with more
// confidence than they give:
//  * "no significant discrepancy": the baseline passes the adequacy test;
//  * "unexplained": it fails and no candidate's score test is significant, or no extended
//    model passes the adequacy test with its strength inside the physical range and a
//    significant likelihood ratio against the baseline;
//  * "ambiguous between X and Y": X's extended model is acceptable, and Y's is too with a
//    BIC less than 2 worse (Kass & Raftery's "positive evidence"), or Y is significant, not
//    extended, and its projected signature is within the ambiguity cosine of X's;
//  * "explained by X": otherwise, X the acceptable extended model of lowest BIC.
#pragma once
#include <vector>

#include "diagnose/diagnosis.hpp"

namespace colza::diagnose {

Verdict decide(const DiagnosisProblem& problem, const Fit& baseline, double baseline_bic, const ScoreTests& scores,
               const std::vector<ExtendedFit>& extended);

// Candidates whose adjusted score-test p-value is below alpha, strongest first.
std::vector<int> significant_candidates(const ScoreTests& scores, double significance);

}  // namespace colza::diagnose
