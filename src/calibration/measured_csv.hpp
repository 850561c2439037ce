// Measured data in plain CSV (data/measured/README.md): lines starting with '#' and empty
// lines are skipped, the first other line is the header (column names, comma-separated),
// every following line one row of numbers. Cells may be quoted and padded with blanks.
#pragma once
#include <string>
#include <vector>

namespace colza::calibration {

// Returns the named columns, in the order asked for (at least one row). Every problem (file
// missing, column missing, no row after the header, a cell that is not a finite number) is a
// ConfigError naming the spec file, the spec key that named the CSV, and the CSV's path and line.
std::vector<std::vector<double>> read_csv_columns(const std::string& csv, const std::vector<std::string>& columns,
                                                  const std::string& spec_file, const std::string& key);

// Same, and the 1-based line number in the file of each row (for messages about a row).
std::vector<std::vector<double>> read_csv_columns(const std::string& csv, const std::vector<std::string>& columns,
                                                  const std::string& spec_file, const std::string& key,
                                                  std::vector<std::size_t>& line_numbers);

// The column names of the CSV's header line (to tell which optional columns it has); the file's
// problems are ConfigErrors as above.
std::vector<std::string> read_csv_header(const std::string& csv, const std::string& spec_file, const std::string& key);

// The `required` columns, then each of `optional` in the order asked for: its values when the
// header names it, an empty column when it does not. Problems as read_csv_columns'.
std::vector<std::vector<double>> read_csv_columns_with_optional(const std::string& csv,
                                                                const std::vector<std::string>& required,
                                                                const std::vector<std::string>& optional,
                                                                const std::string& spec_file, const std::string& key);

// A measured curve's displacement column `x` (named `column`, in m) must increase strictly
// from row to row: a ConfigError naming the rows' lines otherwise (sorting, repeated rows or
// an unloading part would otherwise bend the fit or the strength without a word).
void require_increasing(const std::vector<double>& x, const std::vector<std::size_t>& line_numbers,
                        const std::string& column, const std::string& csv, const std::string& spec_file,
                        const std::string& key);

}  // namespace colza::calibration
