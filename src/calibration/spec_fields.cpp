#include "calibration/spec_fields.hpp"

#include <cmath>

#include "io/format_number.hpp"

namespace colza::calibration {

std::string spec_number_text(double v) { return format_significant(v, 6); }

double required_number(const ConfigNode& t, const std::string& key) {
  const toml::node* n = t.get(key);
  if (!n) t.fail(key, "missing (a number is required)" + t.misspelt_hint(key));
  if (auto v = n->value<double>()) {
    if (!std::isfinite(*v)) t.fail(key, "must be a finite number");
    return *v;
  }
  t.fail(key, "must be a number");
}

double number_or(const ConfigNode& t, const std::string& key, double fallback) {
  return t.has(key) ? required_number(t, key) : fallback;
}

double required_positive(const ConfigNode& t, const std::string& key) {
  const double v = required_number(t, key);
  if (!(v > 0.0)) t.fail(key, "must be > 0, got " + spec_number_text(v));
  return v;
}

long long whole_number_or(const ConfigNode& t, const std::string& key, long long fallback, long long lo,
                          long long hi) {
  const toml::node* n = t.get(key);
  if (!n) return fallback;
  if (!n->is_integer()) t.fail(key, "must be a whole number");
  const long long v = n->as_integer()->get();
  if (v < lo || v > hi)
    t.fail(key, "must be between " + std::to_string(lo) + " and " + std::to_string(hi) + ", got " + std::to_string(v));
  return v;
}

std::string required_string(const ConfigNode& t, const std::string& key) {
  if (!t.has(key)) t.fail(key, "missing (a string is required)" + t.misspelt_hint(key));
  return string_or(t, key, "");
}

std::string string_or(const ConfigNode& t, const std::string& key, const std::string& fallback) {
  const toml::node* n = t.get(key);
  if (!n) return fallback;
  if (auto v = n->value<std::string>()) return *v;
  t.fail(key, "must be a string");
}

std::vector<double> number_array(const ConfigNode& t, const std::string& key) {
  const toml::node* n = t.get(key);
  if (!n) return {};
  const toml::array* a = n->as_array();
  if (!a) t.fail(key, "must be an array of numbers");
  std::vector<double> out;
  for (const auto& e : *a) {
    auto v = e.value<double>();
    if (!v || !std::isfinite(*v)) t.fail(key, "must be an array of finite numbers");
    out.push_back(*v);
  }
  return out;
}

std::vector<std::string> string_array(const ConfigNode& t, const std::string& key) {
  const toml::node* n = t.get(key);
  if (!n) return {};
  const toml::array* a = n->as_array();
  if (!a) t.fail(key, "must be an array of strings");
  std::vector<std::string> out;
  for (const auto& e : *a) {
    auto v = e.value<std::string>();
    if (!v) t.fail(key, "must be an array of strings");
    out.push_back(*v);
  }
  return out;
}

ConfigNode sub_table(const ConfigNode& t, const std::string& key) {
  const toml::node* n = t.get(key);
  if (n && !n->is_table()) t.fail(key, "must be a table");
  return t.table(key);
}

void reject_unknown_spec_keys(const ConfigNode& t) {
  t.reject_unread_keys("unknown key (misspelt? it does not belong in this table)");
}

}  // namespace colza::calibration
