// Reading what the two codes wrote (series.csv, curve.csv, summary.json) and the tolerance
// table's numbers.
#pragma once
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <toml++/toml.h>
#include <vector>

namespace crosscheck {

namespace fs = std::filesystem;

// A CSV file with a header row: one column of numbers per name.
struct Csv {
  std::vector<std::string> names;
  std::vector<std::vector<double>> columns;
  std::size_t rows() const { return columns.empty() ? 0 : columns[0].size(); }
  const std::vector<double>* column(const std::string& name) const;  // nullptr if absent
  const std::vector<double>& at(const std::string& name) const;      // throws if absent
};

// Throws std::runtime_error if the file cannot be read, is empty, has a short row or a cell
// that is not wholly a number (nan and inf are numbers; blank lines and a final \r are skipped).
Csv read_csv(const fs::path& file);

// The whole file as text; throws std::runtime_error naming it if it cannot be read.
std::string read_text(const fs::path& file);

// An empty object if the file is missing or not JSON (a run that did not finish).
nlohmann::json read_json(const fs::path& file);

// Writes `text` to `file` through `<file>.partial` and a rename, so the file is whole or as it
// was. Throws std::runtime_error naming the file if it cannot.
void write_whole(const fs::path& file, const std::string& text);

// The number at `path` (e.g. "micro.floor.force") of a tolerance table, or `fallback`.
double tol_number(const toml::table& t, const std::string& path, double fallback);

}  // namespace crosscheck
