#include "contact/slot_registry.hpp"

#include <cmath>
#include <functional>
#include <limits>

namespace colza {

const char* to_string(RollingForm form) { return form == RollingForm::kYade ? "yade" : "pfc"; }

namespace {

template <class Slot>
struct Registration {
  const char* name;
  std::function<Slot(const ConfigNode& params)> make;
};

// ---- registration tables: one row per implementation ------------------------------
// Parameters are read from [contact.<name>]; units and sources are in the slot's header.

const std::vector<Registration<NormalSlot>>& normal_registry() {
  static const std::vector<Registration<NormalSlot>> rows = {
      {LinearNormal::kName, [](const ConfigNode&) { return NormalSlot(LinearNormal{}); }},
      {HertzNormal::kName, [](const ConfigNode&) { return NormalSlot(HertzNormal{}); }},
      {WaltonBraunNormal::kName,
       [](const ConfigNode& p) {
         WaltonBraunNormal n;
         n.unloading_stiffness_ratio = p.number_in("unloading_stiffness_ratio", 2.0, 1.0, 1e6);  // k2 / k1 (-)
         return NormalSlot(n);
       }},
  };
  return rows;
}

const std::vector<Registration<TangentialSlot>>& tangential_registry() {
  static const std::vector<Registration<TangentialSlot>> rows = {
      {CoulombTangential::kName, [](const ConfigNode&) { return TangentialSlot(CoulombTangential{}); }},
      {MindlinTangential::kName, [](const ConfigNode&) { return TangentialSlot(MindlinTangential{}); }},
  };
  return rows;
}

const std::vector<Registration<DampingSlot>>& damping_registry() {
  static const std::vector<Registration<DampingSlot>> rows = {
      {NoDamping::kName, [](const ConfigNode&) { return DampingSlot(NoDamping{}); }},
      {ViscousDamping::kName,
       [](const ConfigNode& p) {
         ViscousDamping d;
         d.normal_ratio = p.number_in("normal_damping_ratio", 0.0, 0.0, 0.999);          // zeta_n (-)
         d.tangential_ratio = p.number_in("tangential_damping_ratio", 0.0, 0.0, 0.999);  // zeta_t (-)
         return DampingSlot(d);
       }},
  };
  return rows;
}

const std::vector<Registration<RollingSlot>>& rolling_registry() {
  static const std::vector<Registration<RollingSlot>> rows = {
      {NoRolling::kName, [](const ConfigNode&) { return RollingSlot(NoRolling{}); }},
      {ElasticPlasticRolling::kName,
       [](const ConfigNode& p) {
         ElasticPlasticRolling r;
         r.stiffness_factor = p.positive("stiffness_factor", 1.0);  // beta (-)
         r.friction = p.non_negative("friction", 0.0);              // mu_r (-)
         r.form = p.choice("form", "yade", {"yade", "pfc"}) == "yade" ? RollingForm::kYade : RollingForm::kPfc;
         r.at_walls = p.boolean("at_walls", false);
         // eta_r (-). At most 0.5: the dashpot's Cr = 2 eta_r sqrt(I_r kr) damps a sphere rocking
         // about its centre (inertia I = 2/7 I_r at a wall or between two equal spheres) at
         // zeta = eta_r sqrt(7/2), and the explicit step stays stable while w dt <= 2 (sqrt(1 +
         // zeta^2) - zeta): at the time step's w dt <= 0.8 (safety 0.8 of sqrt(I / k_rot)), zeta
         // <= 1.05, eta_r <= 0.56.
         r.damping_ratio = p.number_in("damping_ratio", 0.0, 0.0, 0.5);
         return RollingSlot(r);
       }},
  };
  return rows;
}

const std::vector<Registration<BondSlot>>& bond_registry() {
  static const std::vector<Registration<BondSlot>> rows = {
      {NoBond::kName, [](const ConfigNode&) { return BondSlot(NoBond{}); }},
      {ContactBond::kName,
       [](const ConfigNode& p) {
         ContactBond b;
         b.normal_strength = p.non_negative("normal_strength", 0.0);  // Cn (N)
         b.shear_strength = p.non_negative("shear_strength", 0.0);    // Cs (N)
         return BondSlot(b);
       }},
      {LoadInducedBond::kName,
       [](const ConfigNode& p) {
         constexpr double kNoCap = std::numeric_limits<double>::infinity();
         LoadInducedBond b;
         b.onset_force = p.non_negative("onset_force", 0.0);                    // F_on (N)
         b.normal_strength_ratio = p.non_negative("normal_strength_ratio", 0.0);  // a_n (-)
         b.shear_strength_ratio = p.non_negative("shear_strength_ratio", 0.0);    // a_s (-)
         if (p.has("normal_strength_cap")) b.normal_strength_cap = p.non_negative("normal_strength_cap", kNoCap);
         if (p.has("shear_strength_cap")) b.shear_strength_cap = p.non_negative("shear_strength_cap", kNoCap);
         return BondSlot(b);
       }},
  };
  return rows;
}

// The parameters each implementation runs with, under its [contact.<name>] keys (a row
// above reads them; an implementation without parameters has none to report).
template <class Implementation>
nlohmann::json parameters_of(const Implementation&) {
  return nlohmann::json::object();
}
nlohmann::json parameters_of(const WaltonBraunNormal& n) {
  return {{"unloading_stiffness_ratio", n.unloading_stiffness_ratio}};
}
nlohmann::json parameters_of(const ViscousDamping& d) {
  return {{"normal_damping_ratio", d.normal_ratio}, {"tangential_damping_ratio", d.tangential_ratio}};
}
nlohmann::json parameters_of(const ElasticPlasticRolling& r) {
  return {{"stiffness_factor", r.stiffness_factor}, {"friction", r.friction}, {"form", to_string(r.form)},
          {"at_walls", r.at_walls}, {"damping_ratio", r.damping_ratio}};
}
nlohmann::json parameters_of(const ContactBond& b) {
  return {{"normal_strength", b.normal_strength}, {"shear_strength", b.shear_strength}};
}
nlohmann::json parameters_of(const LoadInducedBond& b) {
  const auto cap = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json("none"); };
  return {{"onset_force", b.onset_force},
          {"normal_strength_ratio", b.normal_strength_ratio},
          {"shear_strength_ratio", b.shear_strength_ratio},
          {"normal_strength_cap", cap(b.normal_strength_cap)},
          {"shear_strength_cap", cap(b.shear_strength_cap)}};
}

// -----------------------------------------------------------------------------------

template <class Slot>
std::vector<std::string> names_of(const std::vector<Registration<Slot>>& rows) {
  std::vector<std::string> names;
  for (const auto& r : rows) names.push_back(r.name);
  return names;
}

template <class Slot>
Slot choose(const ConfigNode& contact, const std::string& slot_key, const std::string& fallback,
            const std::vector<Registration<Slot>>& rows) {
  const std::string name = contact.choice(slot_key, fallback, names_of(rows));
  Slot chosen{};
  for (const auto& r : rows) {
    if (name == r.name) chosen = r.make(contact.table(r.name));
    // An inactive implementation's table may stay in the config (data/oedometer.toml keeps
    // [contact.contact_bond] with bond = "none"), but it is checked all the same: a misspelt
    // key or a value out of range there is an error too, not a silent surprise when the
    // implementation is switched on.
    else if (contact.has(r.name)) (void)r.make(contact.table(r.name));
  }
  return chosen;
}

BondInstallMoment parse_install(const ConfigNode& contact) {
  const std::string s = contact.choice("bond_install", "before_loading",
                                       {"never", "after_settling", "before_loading", "on_new_contacts"});
  if (s == "never") return BondInstallMoment::kNever;
  if (s == "after_settling") return BondInstallMoment::kAfterSettling;
  if (s == "on_new_contacts") return BondInstallMoment::kOnNewContacts;
  return BondInstallMoment::kBeforeLoading;
}

}  // namespace

const char* to_string(BondInstallMoment moment) {
  switch (moment) {
    case BondInstallMoment::kNever: return "never";
    case BondInstallMoment::kAfterSettling: return "after_settling";
    case BondInstallMoment::kBeforeLoading: return "before_loading";
    case BondInstallMoment::kOnNewContacts: return "on_new_contacts";
  }
  return "?";
}

ContactModel read_contact_model(const ConfigNode& contact) {
  ContactModel m;
  m.normal = choose(contact, "normal", LinearNormal::kName, normal_registry());
  m.tangential = choose(contact, "tangential", CoulombTangential::kName, tangential_registry());
  m.damping = choose(contact, "damping", NoDamping::kName, damping_registry());
  m.rolling = choose(contact, "rolling", NoRolling::kName, rolling_registry());
  m.bond = choose(contact, "bond", NoBond::kName, bond_registry());
  m.bond_install = parse_install(contact);
  m.bond_gap = contact.non_negative("bond_gap", 0.0);
  // Only the contact bond is installed at a moment; a load-induced bond forms under load.
  if (!std::holds_alternative<ContactBond>(m.bond)) m.bond_install = BondInstallMoment::kNever;
  return m;
}

bool needs_hertz_moduli(const ContactModel& model) {
  return std::holds_alternative<HertzNormal>(model.normal) || std::holds_alternative<MindlinTangential>(model.tangential);
}

std::vector<std::string> normal_slot_names() { return names_of(normal_registry()); }
std::vector<std::string> tangential_slot_names() { return names_of(tangential_registry()); }
std::vector<std::string> damping_slot_names() { return names_of(damping_registry()); }
std::vector<std::string> rolling_slot_names() { return names_of(rolling_registry()); }
std::vector<std::string> bond_slot_names() { return names_of(bond_registry()); }

std::string describe(const ContactModel& model) {
  std::string s;
  std::visit([&](const auto& n) { s += std::string("normal=") + n.kName; }, model.normal);
  std::visit([&](const auto& t) { s += std::string(", tangential=") + t.kName; }, model.tangential);
  std::visit([&](const auto& d) { s += std::string(", damping=") + d.kName; }, model.damping);
  std::visit([&](const auto& r) { s += std::string(", rolling=") + r.kName; }, model.rolling);
  std::visit([&](const auto& b) { s += std::string(", bond=") + b.kName; }, model.bond);
  s += std::string(", bond_install=") + to_string(model.bond_install);
  return s;
}

nlohmann::json contact_summary(const ContactModel& model) {
  const auto slot = [](const auto& variant) {
    return std::visit(
        [](const auto& implementation) {
          nlohmann::json j = {{"law", implementation.kName}};
          j.update(parameters_of(implementation));
          return j;
        },
        variant);
  };
  return {{"normal", slot(model.normal)},   {"tangential", slot(model.tangential)}, {"damping", slot(model.damping)},
          {"rolling", slot(model.rolling)}, {"bond", slot(model.bond)},             {"bond_install", to_string(model.bond_install)},
          {"bond_gap", model.bond_gap}};
}

}  // namespace colza
