#include "io/table.hpp"

#include <cstdio>
#include <stdexcept>

#include "io/output_error.hpp"

namespace colza {

const std::vector<double>& Table::column(const std::string& name) const {
  for (std::size_t k = 0; k < names.size(); ++k)
    if (names[k] == name) return columns[k];
  throw std::out_of_range("no column " + name);
}

void write_csv(const std::string& file, const Table& table) {
  std::FILE* f = std::fopen(file.c_str(), "w");
  if (!f) throw_cannot_write(file);
  for (std::size_t k = 0; k < table.names.size(); ++k)
    std::fprintf(f, "%s%s", k ? "," : "", table.names[k].c_str());
  std::fputc('\n', f);
  for (std::size_t r = 0; r < table.rows(); ++r) {
    for (std::size_t k = 0; k < table.columns.size(); ++k)
      std::fprintf(f, "%s%.17g", k ? "," : "", table.columns[k][r]);
    std::fputc('\n', f);
  }
  if (std::fclose(f) != 0) throw_cannot_write(file);
}

}  // namespace colza
