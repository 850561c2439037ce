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

}  // namespace colza::diagnose
