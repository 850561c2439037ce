// Typed, tracked access to a TOML document. Every key read is recorded, so after a
// scenario has read what it needs, `reject_unknown_keys` reports any key nobody asked for
// (a misspelt key must not be silently ignored). Overrides from `--set key=value` are
// merged into the document first and reported as coming from the command line.
#pragma once
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>
#include <toml++/toml.h>
#include "config/config_error.hpp"
#include "core/types.hpp"

namespace colza {

class ConfigReader;

// For a key that is missing from `table` (may be null): " (the table has 'radus': misspelt?)"
// when a key of the table is at most two edits away from it, "" otherwise.
std::string misspelt_key_hint(const toml::table* table, const std::string& missing_key);

// A view on one table of the document, with its dotted path.
class ConfigNode {
 public:
  double number(const std::string& key, double fallback) const;
  double positive(const std::string& key, double fallback) const;      // > 0
  double non_negative(const std::string& key, double fallback) const;  // >= 0
  double number_in(const std::string& key, double fallback, double lo, double hi) const;  // [lo, hi]
  std::int64_t integer(const std::string& key, std::int64_t fallback, std::int64_t min_value) const;
  bool boolean(const std::string& key, bool fallback) const;
  std::string string(const std::string& key, const std::string& fallback) const;
  // A string that must be one of `choices`.
  std::string choice(const std::string& key, const std::string& fallback,
                     const std::vector<std::string>& choices) const;
  Vec3 vec3(const std::string& key, const Vec3& fallback) const;
  std::vector<std::int64_t> integer_list(const std::string& key) const;
  std::vector<double> number_list(const std::string& key) const;
  std::vector<double> number_list(const std::string& key, const std::vector<double>& fallback) const;
  bool has(const std::string& key) const;
  bool is_string(const std::string& key) const;
  // The value of `key` as it stands in the document, recorded as read; null when absent.
  const toml::node* get(const std::string& key) const { return find(key); }
  // Whether this table is in the document (a view on an absent table has no keys).
  bool exists() const { return table_ != nullptr; }
  // The table's keys, in the document's order.
  std::vector<std::string> keys() const;
  ConfigNode table(const std::string& key) const;              // empty view if absent
  std::vector<ConfigNode> table_array(const std::string& key) const;
  // Raises a ConfigError about `key` of this table.
  [[noreturn]] void fail(const std::string& key, const std::string& reason) const;
  // Raises "is required (<what>)" about `key` unless the table has it, naming a key of the
  // table that looks like a misspelling of it.
  void require(const std::string& key, const std::string& what) const;
  // " (the table has 'radus': misspelt?)" for a key of this table close to `key`, else "".
  std::string misspelt_hint(const std::string& key) const { return misspelt_key_hint(table_, key); }
  // Raises a ConfigError (`reason`) about the first key of this table that was not read; a
  // sub-table or array of tables counts as read when one of its keys was. For a document
  // checked table by table; ConfigReader::reject_unknown_keys checks a whole document.
  void reject_unread_keys(const std::string& reason) const;
  const std::string& path() const { return path_; }
  // `key`'s dotted path in the document ("measured.curves[0].file").
  std::string full(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

 private:
  friend class ConfigReader;
  ConfigNode(const ConfigReader* reader, const toml::table* table, std::string path)
      : reader_(reader), table_(table), path_(std::move(path)) {}
  const toml::node* find(const std::string& key) const;
  // Records that `key` was absent and `fallback` used: resolved_text() writes it.
  template <class T>
  T use_default(const std::string& key, const T& fallback) const;
  const ConfigReader* reader_;
  const toml::table* table_;  // may be null (absent table)
  std::string path_;
};

class ConfigReader {
 public:
  // `source_name` is what errors call the document (the file path).
  static ConfigReader from_file(const std::string& path);
  static ConfigReader from_string(const std::string& text, const std::string& source_name);
  static ConfigReader empty(const std::string& source_name = "(built-in defaults)");
  // A document parsed by the caller (who reports its syntax errors in its own words).
  static ConfigReader from_table(toml::table document, const std::string& source_name);

  // key=value, value in TOML syntax (bare words are taken as strings).
  void apply_override(const std::string& assignment);
  ConfigNode root() const { return ConfigNode(this, &document_, ""); }
  void reject_unknown_keys() const;
  // The configuration as used, as TOML text (stored with every result): the document with
  // overrides applied and, for every key read but absent, the default that was used. A run
  // is then described in full whether its values came from the file, --set or the built-in
  // defaults.
  std::string resolved_text() const;
  const std::string& source_name() const { return source_; }
  std::string origin_of(const std::string& full_key) const;

 private:
  friend class ConfigNode;
  ConfigReader(toml::table doc, std::string source) : document_(std::move(doc)), source_(std::move(source)) {}
  toml::table document_;
  std::string source_;
  std::set<std::string> overridden_;
  mutable std::set<std::string> used_;
  // Defaults used for absent keys, by full key ("scene.particles[1].radius"), each as a
  // table {v = value}, in the order they were read.
  mutable std::vector<std::pair<std::string, toml::table>> defaults_used_;
};

}  // namespace colza
