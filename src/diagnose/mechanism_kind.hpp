// What a candidate mechanism does physically, and which laboratory test separates two of
// them (physics.md section 8): the advice the diagnosis gives when the data cannot tell two
// candidates apart.
#pragma once
#include <string>
#include <vector>

namespace colza::diagnose {

enum class MechanismKind { kRollingResistance, kElastoPlastic, kHertz, kViscous, kCohesion, kOther };

const char* to_string(MechanismKind k);
// From a candidate's settings ("contact.rolling=elastic_plastic", ...): the slot it switches.
MechanismKind mechanism_kind_of(const std::vector<std::string>& settings);

// The experiment that tells a from b apart, with why (one sentence), or "" for the same kind.
std::string separating_experiment(MechanismKind a, MechanismKind b);

// The test that shows mechanism k apart from what a baseline's parameters absorb, when none
// of `features` (run_features.hpp names) comes from such a test, with why (one sentence);
// "" when one does, or for a kind without a revealing test here. Revealing: an angle of
// repose (angle_of_repose_deg) for rolling resistance, a load-unload cycle (cycle<k>/...) for
// elasto-plastic contact, moduli at two stresses of one branch for Hertz contact. A speed
// series is never visible in the features, so viscous damping is always named.
std::string unseen_by(MechanismKind k, const std::vector<std::string>& features);

}  // namespace colza::diagnose
