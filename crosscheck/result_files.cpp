#include "result_files.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace crosscheck {

const std::vector<double>* Csv::column(const std::string& name) const {
  for (std::size_t k = 0; k < names.size(); ++k)
    if (names[k] == name) return &columns[k];
  return nullptr;
}

const std::vector<double>& Csv::at(const std::string& name) const {
  const auto* c = column(name);
  if (!c) throw std::runtime_error("no column " + name);
  return *c;
}

Csv read_csv(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  Csv csv;
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(file.string() + " is empty");
  if (!line.empty() && line.back() == '\r') line.pop_back();
  {
    std::stringstream s(line);
    std::string name;
    while (std::getline(s, name, ',')) csv.names.push_back(name);
  }
  csv.columns.resize(csv.names.size());
  std::size_t line_number = 1;
  while (std::getline(in, line)) {
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    std::stringstream s(line);
    std::string cell;
    std::size_t k = 0;
    while (std::getline(s, cell, ',') && k < csv.columns.size()) {
      // The whole cell must be a number (nan and inf included: the comparisons fail on
      // them); strtod alone read "garbage5e-07" as 0.
      char* end = nullptr;
      const double value = std::strtod(cell.c_str(), &end);
      while (end && (*end == ' ' || *end == '\t')) ++end;
      if (end == cell.c_str() || *end != '\0')
        throw std::runtime_error(file.string() + ": line " + std::to_string(line_number) + ", column " +
                                 csv.names[k] + ": '" + cell + "' is not a number");
      csv.columns[k++].push_back(value);
    }
    if (k != csv.columns.size()) throw std::runtime_error(file.string() + ": line " + std::to_string(line_number) + ": short row");
  }
  return csv;
}

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  if (!in) return nlohmann::json::object();
  try {
    return nlohmann::json::parse(in);
  } catch (...) {
    return nlohmann::json::object();
  }
}

void write_whole(const fs::path& file, const std::string& text) {
  const fs::path partial = file.string() + ".partial";
  {
    std::ofstream o(partial, std::ios::binary | std::ios::trunc);
    o << text;
    o.flush();
    if (!o) throw std::runtime_error("cannot write " + partial.string());
  }
  std::error_code ec;
  fs::rename(partial, file, ec);
  if (ec) throw std::runtime_error("cannot rename " + partial.string() + " to " + file.string() + ": " + ec.message());
}

double tol_number(const toml::table& t, const std::string& path, double fallback) {
  const auto v = t.at_path(path).value<double>();
  return v ? *v : fallback;
}

}  // namespace crosscheck
