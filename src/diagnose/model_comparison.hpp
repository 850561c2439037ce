// Does the extended model earn its extra parameter? (colza diagnose, step 3.)
//
// Likelihood ratio of the baseline (phi = neutral) inside the extended model: with Gaussian
// noise of known covariance, -2 ln LR = chi2_baseline - chi2_extended = D. The neutral value
// is the boundary of phi's range, so under the null D follows the mixture
// 1/2 chi2_0 + 1/2 chi2_1 (Self & Liang 1987, J. Am. Statist. Assoc. 82, 605-610):
// p = 1/2 P(chi2_1 >= D) for D > 0, else 1.
// Bayesian information criterion BIC = chi2 + k ln n (k fitted parameters, n features; the
// Gaussian log-likelihood's constant cancels between models fitted to the same data):
// a difference above 2 is "positive", above 6 "strong" evidence (Kass & Raftery 1995).
#pragma once

namespace colza::diagnose {

double boundary_likelihood_ratio_p(double chi_square_baseline, double chi_square_extended);
double bayesian_information_criterion(double chi_square, int parameters, int features);

// Kass & Raftery's scale for a BIC difference in favour of one model.
constexpr double kPositiveEvidence = 2.0;
constexpr double kStrongEvidence = 6.0;

}  // namespace colza::diagnose
