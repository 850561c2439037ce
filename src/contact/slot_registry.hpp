// Chooses the implementation of each contact-law slot by name from the config's
// [contact] table. One row per implementation: name, and a factory that reads the
// implementation's parameters from [contact.<name>].
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>
#include "config/config_reader.hpp"
#include "contact/slots.hpp"

namespace colza {

// Reads contact.normal / .tangential / .damping / .rolling / .bond and the chosen
// implementations' parameter tables; validates them.
ContactModel read_contact_model(const ConfigNode& contact);

// Registered names, per slot (for --help and error messages).
std::vector<std::string> normal_slot_names();
std::vector<std::string> tangential_slot_names();
std::vector<std::string> damping_slot_names();
std::vector<std::string> rolling_slot_names();
std::vector<std::string> bond_slot_names();

// Whether a slot of the model needs E and nu of every material (Hertz, Mindlin).
bool needs_hertz_moduli(const ContactModel& model);

// Names of the slot implementations in use, e.g. {"linear", "coulomb", "contact_bond"}.
std::string describe(const ContactModel& model);

// Each slot's implementation and the parameters it runs with (summary.json's "contact"),
// e.g. {"normal": {"law": "walton_braun", "unloading_stiffness_ratio": 2}, "rolling": {"law":
// "none"}, ..., "bond_install": "never"}; keys as in the config's [contact.<law>] table.
nlohmann::json contact_summary(const ContactModel& model);

}  // namespace colza
