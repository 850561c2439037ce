#include "contact/slot_registry.hpp"

#include <functional>

namespace colza {

namespace {

template <class Slot>
struct Registration {
  const char* name;
  std::function<Slot(const ConfigNode& params)> make;
};

// ---- registration tables: one row per implementation ------------------------------

const std::vector<Registration<NormalSlot>>& normal_registry() {
  static const std::vector<Registration<NormalSlot>> rows = {
      {LinearNormal::kName, [](const ConfigNode&) { return NormalSlot(LinearNormal{}); }},
  };
  return rows;
}

const std::vector<Registration<TangentialSlot>>& tangential_registry() {
  static const std::vector<Registration<TangentialSlot>> rows = {
      {CoulombTangential::kName, [](const ConfigNode&) { return TangentialSlot(CoulombTangential{}); }},
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
  };
  return rows;
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
  m.bond = choose(contact, "bond", NoBond::kName, bond_registry());
  m.bond_install = parse_install(contact);
  m.bond_gap = contact.non_negative("bond_gap", 0.0);
  if (std::holds_alternative<NoBond>(m.bond)) m.bond_install = BondInstallMoment::kNever;
  return m;
}

std::vector<std::string> normal_slot_names() { return names_of(normal_registry()); }
std::vector<std::string> tangential_slot_names() { return names_of(tangential_registry()); }
std::vector<std::string> bond_slot_names() { return names_of(bond_registry()); }

std::string describe(const ContactModel& model) {
  std::string s;
  std::visit([&](const auto& n) { s += std::string("normal=") + n.kName; }, model.normal);
  std::visit([&](const auto& t) { s += std::string(", tangential=") + t.kName; }, model.tangential);
  std::visit([&](const auto& b) { s += std::string(", bond=") + b.kName; }, model.bond);
  s += std::string(", bond_install=") + to_string(model.bond_install);
  return s;
}

}  // namespace colza
