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

std::string unseen_by(MechanismKind k, const std::vector<std::string>& features) {
  const auto any = [&](auto&& matches) {
    for (const std::string& f : features)
      if (matches(f)) return true;
    return false;
  };
  const auto contains = [](const std::string& f, const char* part) { return f.find(part) != std::string::npos; };
  switch (k) {
    case MechanismKind::kRollingResistance:
      if (any([&](const std::string& f) { return contains(f, "angle_of_repose"); })) return "";
      return "rolling resistance: no angle of repose among these tests (colza run repose); sliding friction absorbs "
             "much of its effect on strength and density, the heap's angle does not";
    case MechanismKind::kElastoPlastic:
      if (any([&](const std::string& f) { return contains(f, "cycle"); })) return "";
      return "elasto-plastic contact: no load-unload cycle among these tests (oedometer.cycles); a loading curve "
             "alone is met by a softer linear contact";
    case MechanismKind::kHertz: {
      std::vector<std::string> moduli;
      for (const std::string& f : features)
        if (contains(f, "/modulus@")) moduli.push_back(f.substr(0, f.find("/modulus@")));
      for (std::size_t a = 0; a < moduli.size(); ++a)
        for (std::size_t b = a + 1; b < moduli.size(); ++b)
          if (moduli[a] == moduli[b]) return "";
      return "Hertz-Mindlin contact: no branch's modulus at two stresses among these tests "
             "(oedometer.modulus_stresses); Hertz contacts stiffen as the stress grows";
    }
    case MechanismKind::kViscous:
      return "viscous damping: only the same test at two speeds a decade apart shows it (colza run ... --speeds); "
             "check that the tests were run at two speeds";
    case MechanismKind::kCohesion:
    case MechanismKind::kOther:
      return "";
  }
  return "";
}

}  // namespace colza::diagnose
