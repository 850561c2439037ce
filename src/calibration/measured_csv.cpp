#include "calibration/measured_csv.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "config/config_error.hpp"
#include "io/format_number.hpp"
#include "io/input_file.hpp"

namespace colza::calibration {

namespace {

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> cells;
  std::istringstream s(line);
  for (std::string c; std::getline(s, c, ',');) {
    const auto b = c.find_first_not_of(" \t\r\"");
    const auto e = c.find_last_not_of(" \t\r\"");
    cells.push_back(b == std::string::npos ? "" : c.substr(b, e - b + 1));
  }
  return cells;
}

bool skipped(const std::string& line) {
  const auto first = line.find_first_not_of(" \t\r");
  return first == std::string::npos || line[first] == '#';
}

}  // namespace

std::vector<std::string> read_csv_header(const std::string& csv, const std::string& spec_file, const std::string& key) {
  if (const std::string why = unreadable_file_reason(csv); !why.empty())
    throw ConfigError(spec_file, key, "the measured data file " + csv + " " + why);
  std::ifstream in(csv);
  std::string line;
  for (std::size_t line_number = 1; std::getline(in, line); ++line_number) {
    if (line_number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    if (!skipped(line)) return split_csv_line(line);
  }
  throw ConfigError(spec_file, key, csv + ": the file has no header line (it is empty or only comments)");
}

std::vector<std::vector<double>> read_csv_columns(const std::string& csv, const std::vector<std::string>& columns,
                                                  const std::string& spec_file, const std::string& key,
                                                  std::vector<std::size_t>& line_numbers) {
  if (const std::string why = unreadable_file_reason(csv); !why.empty())
    throw ConfigError(spec_file, key, "the measured data file " + csv + " " + why);
  std::ifstream in(csv);
  std::string line;
  std::size_t line_number = 0;
  bool have_header = false;
  while (std::getline(in, line)) {
    ++line_number;
    // A spreadsheet's "CSV UTF-8" starts with a byte-order mark, invisible in a message.
    if (line_number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    if (!skipped(line)) {
      have_header = true;
      break;
    }
  }
  if (!have_header)
    throw ConfigError(spec_file, key, csv + ": the file has no header line (it is empty or only comments)");
  const std::vector<std::string> header = split_csv_line(line);
  std::vector<std::size_t> index;
  for (const auto& c : columns) {
    const auto it = std::find(header.begin(), header.end(), c);
    if (it == header.end())
      throw ConfigError(spec_file, key, csv + ": no column \"" + c + "\" in the header line \"" + line + "\"" +
                                            (line.find(';') != std::string::npos && line.find(',') == std::string::npos
                                                 ? " (columns must be separated by commas, not semicolons)"
                                                 : ""));
    // A column named twice (a spreadsheet's copied column) would be read from its first
    // place without a word; which one is meant is the user's to say.
    if (std::find(it + 1, header.end(), c) != header.end())
      throw ConfigError(spec_file, key, csv + ": the header line \"" + line + "\" names column \"" + c +
                                            "\" twice: rename or remove one");
    index.push_back(static_cast<std::size_t>(it - header.begin()));
  }
  std::vector<std::vector<double>> out(columns.size());
  line_numbers.clear();
  while (std::getline(in, line)) {
    ++line_number;
    if (skipped(line)) continue;
    const auto cells = split_csv_line(line);
    for (std::size_t k = 0; k < columns.size(); ++k) {
      const std::string where = csv + ": line " + std::to_string(line_number) + ": column \"" + columns[k] + "\"";
      if (index[k] >= cells.size()) throw ConfigError(spec_file, key, where + " is missing (the row is short)");
      const std::string& cell = cells[index[k]];
      double v = 0.0;
      try {
        std::size_t used = 0;
        v = std::stod(cell, &used);
        if (used != cell.size() || !std::isfinite(v)) throw std::invalid_argument("");
      } catch (const std::exception&) {
        throw ConfigError(spec_file, key, where + " is \"" + cell + "\", not a finite number");
      }
      out[k].push_back(v);
    }
    line_numbers.push_back(line_number);
  }
  if (line_numbers.empty()) throw ConfigError(spec_file, key, csv + ": the file has no rows after its header line");
  return out;
}

std::vector<std::vector<double>> read_csv_columns(const std::string& csv, const std::vector<std::string>& columns,
                                                  const std::string& spec_file, const std::string& key) {
  std::vector<std::size_t> line_numbers;
  return read_csv_columns(csv, columns, spec_file, key, line_numbers);
}

void require_increasing(const std::vector<double>& x, const std::vector<std::size_t>& line_numbers,
                        const std::string& column, const std::string& csv, const std::string& spec_file,
                        const std::string& key) {
  for (std::size_t k = 1; k < x.size(); ++k)
    if (!(x[k] > x[k - 1]))
      throw ConfigError(spec_file, key,
                        csv + ": line " + std::to_string(line_numbers[k]) + ": " + column + " " +
                            format_significant(x[k], 6) + " m does not increase on the previous row's " +
                            format_significant(x[k - 1], 6) + " m (line " + std::to_string(line_numbers[k - 1]) +
                            "): the displacement must increase strictly along the curve (sort the rows; remove "
                            "repeated rows and any unloading part)");
}

std::vector<std::vector<double>> read_csv_columns_with_optional(const std::string& csv,
                                                                const std::vector<std::string>& required,
                                                                const std::vector<std::string>& optional,
                                                                const std::string& spec_file, const std::string& key) {
  const std::vector<std::string> header = read_csv_header(csv, spec_file, key);
  std::vector<bool> present;
  std::vector<std::string> names = required;
  for (const std::string& name : optional) {
    present.push_back(std::find(header.begin(), header.end(), name) != header.end());
    if (present.back()) names.push_back(name);
  }
  std::vector<std::vector<double>> read = read_csv_columns(csv, names, spec_file, key);
  std::vector<std::vector<double>> columns(read.begin(), read.begin() + static_cast<std::ptrdiff_t>(required.size()));
  auto next = read.begin() + static_cast<std::ptrdiff_t>(required.size());
  for (const bool is_present : present) columns.push_back(is_present ? std::move(*next++) : std::vector<double>{});
  return columns;
}

}  // namespace colza::calibration

