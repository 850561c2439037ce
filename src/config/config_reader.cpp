#include "config/config_reader.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <type_traits>

#include "io/input_file.hpp"

namespace colza {

namespace {

std::string describe(const toml::node& n) {
  std::ostringstream s;
  if (n.is_string()) s << '"' << *n.value<std::string>() << '"';
  else if (n.is_table()) s << "a table";
  else if (n.is_array()) s << "an array";
  else if (auto d = n.value_exact<double>()) s << *d;
  else if (auto i = n.value_exact<std::int64_t>()) s << *i;
  else if (auto b = n.value_exact<bool>()) s << (*b ? "true" : "false");
  else s << "a value of another type";
  return s.str();
}

std::string format_number(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

}  // namespace

// ---- ConfigReader -------------------------------------------------------------------

ConfigReader ConfigReader::from_file(const std::string& path) {
  if (const std::string why = unreadable_file_reason(path); !why.empty())
    throw ConfigError(path, "", "the config file " + why + " (a config is a TOML file, e.g. data/oedometer.toml)");
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return from_string(buffer.str(), path);
}

ConfigReader ConfigReader::from_string(const std::string& text, const std::string& source_name) {
  try {
    return ConfigReader(toml::parse(text, source_name), source_name);
  } catch (const toml::parse_error& e) {
    std::ostringstream s;
    s << "line " << e.source().begin.line << ": TOML syntax error: " << e.description();
    throw ConfigError(source_name, "", s.str());
  }
}

ConfigReader ConfigReader::empty(const std::string& source_name) { return ConfigReader(toml::table{}, source_name); }

ConfigReader ConfigReader::from_table(toml::table document, const std::string& source_name) {
  return ConfigReader(std::move(document), source_name);
}

void ConfigReader::apply_override(const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw ConfigError("--set", assignment, "expected key=value");
  // Spaces around the key and the value are not part of them: "particle.friction = 0.3"
  // (quoted on the command line) means particle.friction=0.3.
  const auto trimmed = [](const std::string& text) {
    const std::size_t first = text.find_first_not_of(" \t"), last = text.find_last_not_of(" \t");
    return first == std::string::npos ? std::string() : text.substr(first, last - first + 1);
  };
  const std::string key = trimmed(assignment.substr(0, eq));
  const std::string value_text = trimmed(assignment.substr(eq + 1));
  if (key.empty()) throw ConfigError("--set", assignment, "expected key=value");
  toml::table parsed;
  try {
    parsed = toml::parse("v = " + value_text);
  } catch (const toml::parse_error&) {
    // Bare words such as `--set contact.bond=contact_bond` are strings.
    parsed = toml::table{{"v", value_text}};
  }
  // Walk/create the dotted path.
  toml::table* table = &document_;
  std::size_t start = 0;
  while (true) {
    const auto dot = key.find('.', start);
    const std::string part = key.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (part.empty()) throw ConfigError("--set", key, "empty key component");
    if (dot == std::string::npos) {
      table->insert_or_assign(part, *parsed.get("v"));
      break;
    }
    auto* next = table->get(part);
    if (!next) {
      table->insert(part, toml::table{});
      next = table->get(part);
    }
    if (!next->is_table()) throw ConfigError("--set", key, "'" + part + "' is not a table");
    table = next->as_table();
    start = dot + 1;
  }
  overridden_.insert(key);
}

std::string ConfigReader::origin_of(const std::string& full_key) const {
  for (const auto& k : overridden_)
    if (full_key == k || full_key.rfind(k + ".", 0) == 0) return "--set " + k;
  return source_;
}

namespace {

// The table at the dotted path `table_path` of `doc` ("scene.particles[1]": member 1 of the
// array of tables scene.particles), made where absent; null where the path names a value or
// a member that does not exist.
toml::table* table_at(toml::table& doc, const std::string& table_path) {
  toml::table* t = &doc;
  std::size_t start = 0;
  while (t && start < table_path.size()) {
    const std::size_t dot = table_path.find('.', start);
    std::string part = table_path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    start = dot == std::string::npos ? table_path.size() : dot + 1;
    std::optional<std::size_t> index;
    if (const std::size_t open = part.find('['); open != std::string::npos) {
      index = std::stoul(part.substr(open + 1));
      part = part.substr(0, open);
    }
    if (!t->contains(part)) t->insert(part, toml::table{});
    toml::node* n = t->get(part);
    if (index) {
      toml::array* a = n->as_array();
      n = a && *index < a->size() ? a->get(*index) : nullptr;
    }
    t = n ? n->as_table() : nullptr;
  }
  return t;
}

}  // namespace

std::string ConfigReader::resolved_text() const {
  toml::table resolved = document_;
  for (const auto& [full_key, value] : defaults_used_) {
    const std::size_t dot = full_key.rfind('.');
    toml::table* t = dot == std::string::npos ? &resolved : table_at(resolved, full_key.substr(0, dot));
    const std::string key = dot == std::string::npos ? full_key : full_key.substr(dot + 1);
    if (t && !t->contains(key)) t->insert(key, *value.get("v"));
  }
  std::ostringstream s;
  s << resolved;
  return s.str();
}

namespace {
void collect_unknown(const toml::table& t, const std::string& path, const std::set<std::string>& used,
                     std::vector<std::string>& unknown) {
  for (const auto& [k, node] : t) {
    const std::string full = path.empty() ? std::string(k.str()) : path + "." + std::string(k.str());
    if (used.count(full)) continue;
    if (const auto* sub = node.as_table()) {
      collect_unknown(*sub, full, used, unknown);
    } else if (const auto* arr = node.as_array(); arr && arr->is_array_of_tables()) {
      for (std::size_t i = 0; i < arr->size(); ++i)
        collect_unknown(*arr->get(i)->as_table(), full + "[" + std::to_string(i) + "]", used, unknown);
    } else {
      unknown.push_back(full);
    }
  }
}
}  // namespace

void ConfigReader::reject_unknown_keys() const {
  std::vector<std::string> unknown;
  collect_unknown(document_, "", used_, unknown);
  if (!unknown.empty())
    throw ConfigError(origin_of(unknown.front()), unknown.front(),
                      "unknown key (misspelt, or not used by this scenario)");
}

// ---- ConfigNode ---------------------------------------------------------------------

namespace {

// Levenshtein distance (insertions, deletions, substitutions).
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string misspelt_key_hint(const toml::table* table, const std::string& missing_key) {
  if (!table) return "";
  for (const auto& [k, node] : *table) {
    const std::string name(k.str());
    if (name != missing_key && edit_distance(name, missing_key) <= 2)
      return " (the table has '" + name + "': misspelt?)";
  }
  return "";
}

void ConfigNode::require(const std::string& key, const std::string& what) const {
  if (!has(key)) fail(key, "is required (" + what + ")" + misspelt_key_hint(table_, key));
}

void ConfigNode::fail(const std::string& key, const std::string& reason) const {
  const std::string k = full(key);
  throw ConfigError(reader_->origin_of(k), k, reason);
}

const toml::node* ConfigNode::find(const std::string& key) const {
  if (!table_) return nullptr;
  const toml::node* n = table_->get(key);
  if (n) reader_->used_.insert(full(key));
  return n;
}

template <class T>
T ConfigNode::use_default(const std::string& key, const T& fallback) const {
  toml::table value;
  if constexpr (std::is_same_v<T, Vec3>) {
    value.insert("v", toml::array{fallback.x(), fallback.y(), fallback.z()});
  } else if constexpr (std::is_same_v<T, std::vector<double>>) {
    toml::array a;
    for (double x : fallback) a.push_back(x);
    value.insert("v", std::move(a));
  } else {
    value.insert("v", fallback);
  }
  reader_->defaults_used_.emplace_back(full(key), std::move(value));
  return fallback;
}

bool ConfigNode::has(const std::string& key) const { return table_ && table_->contains(key); }

std::vector<std::string> ConfigNode::keys() const {
  std::vector<std::string> out;
  if (table_)
    for (const auto& [k, node] : *table_) out.emplace_back(k.str());
  return out;
}

void ConfigNode::reject_unread_keys(const std::string& reason) const {
  const auto read_under = [&](const std::string& prefix) {
    const auto it = reader_->used_.lower_bound(prefix);
    return it != reader_->used_.end() && it->compare(0, prefix.size(), prefix) == 0;
  };
  for (const std::string& key : keys()) {
    const std::string k = full(key);
    if (!reader_->used_.count(k) && !read_under(k + ".") && !read_under(k + "[")) fail(key, reason);
  }
}

bool ConfigNode::is_string(const std::string& key) const {
  return table_ && table_->get(key) && table_->get(key)->is_string();
}

double ConfigNode::number(const std::string& key, double fallback) const {
  const toml::node* n = find(key);
  if (!n) return use_default(key, fallback);
  if (auto v = n->value_exact<double>()) {
    if (!std::isfinite(*v)) fail(key, "must be a finite number");
    return *v;
  }
  if (auto v = n->value_exact<std::int64_t>()) return static_cast<double>(*v);
  fail(key, "expected a number, got " + describe(*n));
}

double ConfigNode::positive(const std::string& key, double fallback) const {
  const double v = number(key, fallback);
  if (!(v > 0.0)) fail(key, "must be positive, got " + format_number(v));
  return v;
}

double ConfigNode::non_negative(const std::string& key, double fallback) const {
  const double v = number(key, fallback);
  if (!(v >= 0.0)) fail(key, "must not be negative, got " + format_number(v));
  return v;
}

double ConfigNode::number_in(const std::string& key, double fallback, double lo, double hi) const {
  const double v = number(key, fallback);
  if (!(v >= lo && v <= hi))
    fail(key, "must lie in [" + format_number(lo) + ", " + format_number(hi) + "], got " + format_number(v));
  return v;
}

std::int64_t ConfigNode::integer(const std::string& key, std::int64_t fallback, std::int64_t min_value) const {
  const toml::node* n = find(key);
  if (!n) return use_default(key, fallback);
  auto v = n->value_exact<std::int64_t>();
  if (!v) fail(key, "expected an integer, got " + describe(*n));
  if (*v < min_value) fail(key, "must be at least " + std::to_string(min_value) + ", got " + std::to_string(*v));
  return *v;
}

bool ConfigNode::boolean(const std::string& key, bool fallback) const {
  const toml::node* n = find(key);
  if (!n) return use_default(key, fallback);
  auto v = n->value_exact<bool>();
  if (!v) fail(key, "expected true or false, got " + describe(*n));
  return *v;
}

std::string ConfigNode::string(const std::string& key, const std::string& fallback) const {
  const toml::node* n = find(key);
  if (!n) return use_default(key, fallback);
  auto v = n->value_exact<std::string>();
  if (!v) fail(key, "expected a string, got " + describe(*n));
  return *v;
}

std::string ConfigNode::choice(const std::string& key, const std::string& fallback,
                               const std::vector<std::string>& choices) const {
  const std::string v = string(key, fallback);
  for (const auto& c : choices)
    if (c == v) return v;
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "" : ", ") + ("\"" + c + "\"");
  fail(key, "must be one of " + list + ", got \"" + v + "\"");
}

Vec3 ConfigNode::vec3(const std::string& key, const Vec3& fallback) const {
  const toml::node* n = find(key);
  if (!n) return use_default(key, fallback);
  const toml::array* a = n->as_array();
  if (!a || a->size() != 3) fail(key, "expected an array of 3 numbers, got " + describe(*n));
  Vec3 v;
  for (int d = 0; d < 3; ++d) {
    const toml::node* e = a->get(d);
    if (auto x = e->value_exact<double>()) v[d] = *x;
    else if (auto i = e->value_exact<std::int64_t>()) v[d] = static_cast<double>(*i);
    else fail(key, "expected an array of 3 numbers, got " + describe(*n));
  }
  if (!v.allFinite()) fail(key, "must be finite");
  return v;
}

std::vector<std::int64_t> ConfigNode::integer_list(const std::string& key) const {
  std::vector<std::int64_t> out;
  const toml::node* n = find(key);
  if (!n) return out;
  const toml::array* a = n->as_array();
  if (!a) fail(key, "expected an array of integers, got " + describe(*n));
  for (const auto& e : *a) {
    auto v = e.value_exact<std::int64_t>();
    if (!v) fail(key, "expected an array of integers");
    out.push_back(*v);
  }
  return out;
}

std::vector<double> ConfigNode::number_list(const std::string& key) const {
  std::vector<double> out;
  const toml::node* n = find(key);
  if (!n) return out;
  const toml::array* a = n->as_array();
  if (!a) fail(key, "expected an array of numbers, got " + describe(*n));
  for (const auto& e : *a) {
    if (auto v = e.value_exact<double>()) out.push_back(*v);
    else if (auto i = e.value_exact<std::int64_t>()) out.push_back(static_cast<double>(*i));
    else fail(key, "expected an array of numbers");
    if (!std::isfinite(out.back())) fail(key, "every entry must be a finite number, got " + format_number(out.back()));
  }
  return out;
}

std::vector<double> ConfigNode::number_list(const std::string& key, const std::vector<double>& fallback) const {
  return has(key) ? number_list(key) : use_default(key, fallback);
}

ConfigNode ConfigNode::table(const std::string& key) const {
  const toml::node* n = table_ ? table_->get(key) : nullptr;
  if (!n) return ConfigNode(reader_, nullptr, full(key));
  if (!n->is_table()) {
    reader_->used_.insert(full(key));
    fail(key, "expected a table, got " + describe(*n));
  }
  return ConfigNode(reader_, n->as_table(), full(key));
}

std::vector<ConfigNode> ConfigNode::table_array(const std::string& key) const {
  std::vector<ConfigNode> out;
  const toml::node* n = find(key);
  if (!n) return out;
  const toml::array* a = n->as_array();
  if (!a || !a->is_array_of_tables()) fail(key, "expected an array of tables ([[" + full(key) + "]])");
  reader_->used_.erase(full(key));  // members are tracked one by one
  for (std::size_t i = 0; i < a->size(); ++i)
    out.push_back(ConfigNode(reader_, a->get(i)->as_table(), full(key) + "[" + std::to_string(i) + "]"));
  return out;
}

}  // namespace colza
