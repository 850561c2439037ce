#include "diagnose/mechanism_kind.hpp"

#include <utility>

namespace colza::diagnose {

const char* to_string(MechanismKind k) {
  switch (k) {
    case MechanismKind::kRollingResistance: return "rolling resistance";
    case MechanismKind::kElastoPlastic: return "elasto-plastic contact";
    case MechanismKind::kHertz: return "Hertz-Mindlin contact";
    case MechanismKind::kViscous: return "viscous contact damping";
    case MechanismKind::kCohesion: return "cohesion";
    case MechanismKind::kOther: return "other";
  }
  return "other";
}

MechanismKind mechanism_kind_of(const std::vector<std::string>& settings) {
  for (const std::string& s : settings) {
    const auto starts = [&](const char* prefix) { return s.rfind(prefix, 0) == 0; };
    if (starts("contact.rolling=") && s != "contact.rolling=none") return MechanismKind::kRollingResistance;
    if (starts("contact.normal=walton_braun")) return MechanismKind::kElastoPlastic;
    if (starts("contact.normal=hertz")) return MechanismKind::kHertz;
    if (starts("contact.damping=") && s != "contact.damping=none") return MechanismKind::kViscous;
    if (starts("contact.bond=") && s != "contact.bond=none") return MechanismKind::kCohesion;
  }
  return MechanismKind::kOther;
}

std::string separating_experiment(MechanismKind a, MechanismKind b) {
  if (a == b) return "";
  using K = MechanismKind;
  const auto pair = [&](K x, K y) { return (a == x && b == y) || (a == y && b == x); };
  if (a == K::kViscous || b == K::kViscous)
    return "the same test at two speeds a decade apart, both at inertial numbers below 1e-3 (--speeds): only "
           "viscous damping makes a quasi-static result depend on the speed";
  if (pair(K::kHertz, K::kElastoPlastic))
    return "an oedometer load-unload cycle (oedometer.cycles): elasto-plastic contacts leave a permanent strain and a "
           "hysteresis loop, Hertz contacts unload along a curve that stiffens with stress and recover almost fully";
  if (pair(K::kRollingResistance, K::kCohesion))
    return "a shear test at a low normal stress, or an angle of repose (colza run repose): cohesion keeps a strength "
           "as the normal stress goes to zero, rolling resistance raises the friction angle and the repose angle";
  if (a == K::kElastoPlastic || b == K::kElastoPlastic)
    return "an oedometer load-unload cycle (oedometer.cycles): only plastic contacts leave a permanent strain";
  if (a == K::kHertz || b == K::kHertz)
    return "the constrained modulus at two or more stresses on loading and unloading (oedometer.cycles with "
           "oedometer.modulus_stresses): Hertz contacts stiffen as the stress grows";
  if (a == K::kRollingResistance || b == K::kRollingResistance)
    return "an angle of repose (colza run repose): rolling resistance raises it strongly, sliding friction alone "
           "saturates well below most seeds' angles";
  return "a test in which the two candidates' signatures differ (compare their rows in the signature table)";
}

}  // namespace colza::diagnose
