// A column table of doubles: the in-memory form of every recorded curve. Written as CSV
// (for people and the YADE cross-check; units in docs/running.md) and as an HDF5 group (for
// programs; each column's unit is its dataset's "units" attribute).
#pragma once
#include <string>
#include <vector>

namespace colza {

struct Table {
  std::vector<std::string> names;
  std::vector<std::string> units;  // per column, SI ("s", "m", "N", "Pa", "1" for counts); may be empty
  std::vector<std::vector<double>> columns;

  explicit Table(std::vector<std::string> column_names = {}, std::vector<std::string> column_units = {})
      : names(std::move(column_names)), units(std::move(column_units)), columns(names.size()) {}
  void add_row(const std::vector<double>& row) {
    for (std::size_t k = 0; k < columns.size(); ++k) columns[k].push_back(row[k]);
  }
  std::size_t rows() const { return columns.empty() ? 0 : columns[0].size(); }
  const std::vector<double>& column(const std::string& name) const;
};

// Full precision (17 significant digits), header line with the column names.
void write_csv(const std::string& file, const Table& table);

}  // namespace colza
