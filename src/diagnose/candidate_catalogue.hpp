// The candidate mechanisms a diagnosis tests when its spec names none: every mechanism of
// physics.md section 7 that extends the baseline continuously from a neutral value, with
// the settings that switch it on, the parameter that sets its strength, the physical range
// of that parameter and the probe value its signature is measured at.
//
//  rolling_resistance     contact.rolling = elastic_plastic; mu_r = contact.elastic_plastic.friction
//                         in [0, 0.3] (seeds: 0.05-0.2, Wensrich & Katterfeld 2012), probe 0.1
//  elasto_plastic         contact.normal = walton_braun; k2 / k1 = unloading_stiffness_ratio in
//                         [1, 5] (1: elastic), probe 2
//  viscous_damping        contact.damping = viscous; zeta = normal_damping_ratio =
//                         tangential_damping_ratio in [0, 0.5], probe 0.2
//  load_induced_cohesion  contact.bond = load_induced; a_n = normal_strength_ratio in [0, 1],
//                         a_s = shear_strength_ratio = 2.5 a_n (the paper's Cs / Cn = 3.2 / 1.1 ~ 2.9
//                         and 3.17 / 1.32 ~ 2.4), probe 0.3
// Hertz-Mindlin is not in the list: it replaces the linear law rather than extending it
// from a neutral value, so it has no signature "per unit from zero"; to test it, diagnose
// with a baseline config that uses it and compare the verdicts.
#pragma once
#include <string>
#include <vector>

#include "diagnose/diagnosis.hpp"

namespace colza::diagnose {

// A candidate's strength sets each of these keys to factor x strength.
struct StrengthKey {
  std::string key;
  double factor = 1.0;
};

struct CatalogueEntry {
  Candidate candidate;                 // settings, parameter (key, lower = neutral, upper), probe, kind
  std::vector<StrengthKey> also_sets;  // further keys tied to the strength
};

const std::vector<CatalogueEntry>& candidate_catalogue();
// The entry named `name`, or nullptr.
const CatalogueEntry* catalogue_entry(const std::string& name);

}  // namespace colza::diagnose
