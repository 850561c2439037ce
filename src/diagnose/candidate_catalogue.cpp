#include "diagnose/candidate_catalogue.hpp"

namespace colza::diagnose {

namespace {

CatalogueEntry entry(const std::string& name, std::vector<std::string> settings, const std::string& short_name,
                     const std::string& key, double neutral, double upper, double probe,
                     std::vector<StrengthKey> also = {}) {
  CatalogueEntry e;
  e.candidate.name = name;
  e.candidate.settings = std::move(settings);
  e.candidate.parameter = {short_name, key, "-", neutral, upper};
  e.candidate.probe = probe;
  e.candidate.kind = mechanism_kind_of(e.candidate.settings);
  e.also_sets = std::move(also);
  return e;
}

}  // namespace

const std::vector<CatalogueEntry>& candidate_catalogue() {
  static const std::vector<CatalogueEntry> entries = {
      entry("rolling_resistance", {"contact.rolling=elastic_plastic"}, "mu_r", "contact.elastic_plastic.friction", 0.0,
            0.3, 0.1),
      entry("elasto_plastic", {"contact.normal=walton_braun"}, "k2_over_k1",
            "contact.walton_braun.unloading_stiffness_ratio", 1.0, 5.0, 2.0),
      entry("viscous_damping", {"contact.damping=viscous"}, "zeta", "contact.viscous.normal_damping_ratio", 0.0, 0.5,
            0.2, {{"contact.viscous.tangential_damping_ratio", 1.0}}),
      entry("load_induced_cohesion", {"contact.bond=load_induced"}, "a_n", "contact.load_induced.normal_strength_ratio",
            0.0, 1.0, 0.3, {{"contact.load_induced.shear_strength_ratio", 2.5}}),
  };
  return entries;
}

const CatalogueEntry* catalogue_entry(const std::string& name) {
  for (const auto& e : candidate_catalogue())
    if (e.candidate.name == name) return &e;
  return nullptr;
}

}  // namespace colza::diagnose
