#include "run_stamp.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <toml++/toml.h>
#include "result_files.hpp"

namespace crosscheck {

namespace {

// FNV-1a 64 of a file's bytes as 16 hex digits (the same function as colza's
// io/fingerprint.hpp, written here so the cross-check shares no code with colza).
std::string file_fingerprint(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a 64 offset basis
  char buf[1 << 16];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) {
    for (std::streamsize k = 0; k < in.gcount(); ++k) h = (h ^ static_cast<unsigned char>(buf[k])) * 1099511628211ull;
    if (!in) break;
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

// Programs are stamped once per version of the file (colza's executable is megabytes; an
// ensemble stamps dozens of runs, from run_in_parallel's threads): a rebuilt program, at the
// same path, has another size or modification time and is read again.
std::string program_fingerprint(const fs::path& file) {
  static std::mutex mutex;
  static std::map<std::tuple<fs::path, std::uintmax_t, fs::file_time_type>, std::string> known;
  std::error_code ec;
  const auto key = std::make_tuple(file, fs::file_size(file, ec), fs::last_write_time(file, ec));
  const std::lock_guard<std::mutex> lock(mutex);
  auto it = known.find(key);
  if (it == known.end()) it = known.emplace(key, file_fingerprint(file)).first;
  return it->second;
}

fs::path absolute_path(const fs::path& p) {
  std::error_code ec;
  const fs::path a = fs::absolute(p, ec);
  return (ec ? p : a).lexically_normal();
}

bool names_a_file(const fs::path& p) {
  std::error_code ec;
  return !p.empty() && fs::is_regular_file(p, ec);
}

// Every string of a TOML document, tables and arrays included.
void collect_strings(const toml::node& node, std::vector<std::string>& out) {
  if (const auto* s = node.as_string()) {
    out.push_back(s->get());
  } else if (const auto* t = node.as_table()) {
    for (const auto& [key, value] : *t) collect_strings(value, out);
  } else if (const auto* a = node.as_array()) {
    for (const auto& value : *a) collect_strings(value, out);
  }
}

}  // namespace

std::string run_stamp(const std::string& command, const std::vector<fs::path>& programs, const fs::path& config,
                      const std::vector<std::string>& arguments) {
  std::ostringstream stamp;
  stamp << "command " << command << "\n";
  for (const fs::path& p : programs)
    if (names_a_file(p)) stamp << "program " << absolute_path(p).string() << " " << program_fingerprint(p) << "\n";
  // Inputs in a fixed order, each once: the config, the files its strings name (relative to
  // the config's folder, as colza and the YADE scripts read them), the files the arguments
  // name (a --set key=value by its value, relative to the working folder, as colza reads it).
  std::vector<fs::path> inputs{config};
  toml::table doc;
  try {
    doc = toml::parse_file(config.string());
  } catch (const toml::parse_error& e) {
    throw std::runtime_error(config.string() + ": " + std::string(e.description()));
  }
  std::vector<std::string> strings;
  collect_strings(doc, strings);
  for (const std::string& s : strings) {
    const fs::path named = fs::path(s).is_absolute() ? fs::path(s) : config.parent_path() / s;
    if (!s.empty() && names_a_file(named)) inputs.push_back(named);
  }
  for (const std::string& a : arguments) {
    const std::size_t eq = a.find('=');
    const std::string value = eq == std::string::npos ? a : a.substr(eq + 1);
    if (names_a_file(value)) inputs.emplace_back(value);
  }
  std::set<fs::path> seen;
  for (const fs::path& p : inputs)
    if (const fs::path a = absolute_path(p); seen.insert(a).second)
      stamp << "input " << a.string() << " " << file_fingerprint(p) << "\n";
  return stamp.str();
}

fs::path stamp_file(const fs::path& out) { return out.string() + ".inputs"; }

namespace {

// The stamp's last lines: the fingerprints of the results it vouches for, the run's
// summary.json first (written last by both codes; throws if there is none), then every other
// file of the run folder in name order (the curves and series the checks read, the packing a
// kept sample is kept for).
std::string result_lines(const fs::path& out) {
  const fs::path summary = out / "summary.json";
  std::string lines = "result " + summary.string() + " " + file_fingerprint(summary) + "\n";
  std::vector<fs::path> others;
  for (const auto& entry : fs::recursive_directory_iterator(out))
    if (entry.is_regular_file() && entry.path() != summary) others.push_back(entry.path());
  std::sort(others.begin(), others.end());
  for (const fs::path& result : others) lines += "result " + result.string() + " " + file_fingerprint(result) + "\n";
  return lines;
}

struct ResultLine {
  fs::path file;
  std::string fingerprint;
};

// A stamp split into its inputs part and its result lines; nothing if there is no stamp, or
// its first result is not out/summary.json.
struct ParsedStamp {
  std::string inputs;
  std::vector<ResultLine> results;
};
std::optional<ParsedStamp> parse_stamp(const fs::path& out) {
  std::string text;
  try {
    text = read_text(stamp_file(out));
  } catch (const std::exception&) {
    return std::nullopt;
  }
  ParsedStamp parsed;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("result ", 0) != 0) {
      if (!parsed.results.empty()) return std::nullopt;  // inputs after results: not a stamp crosscheck wrote
      parsed.inputs += line + "\n";
      continue;
    }
    const std::size_t last_space = line.rfind(' ');
    parsed.results.push_back({line.substr(7, last_space - 7), line.substr(last_space + 1)});
  }
  if (parsed.results.empty() || parsed.results.front().file != out / "summary.json") return std::nullopt;
  return parsed;
}

// Why `result` no longer is what the stamp vouched for ("" if it is).
std::string result_change(const ResultLine& result) {
  if (!names_a_file(result.file)) return result.file.string() + " is missing";
  try {
    if (file_fingerprint(result.file) != result.fingerprint) return result.file.string() + " has changed";
  } catch (const std::exception&) {
    return result.file.string() + " cannot be read";
  }
  return "";
}

}  // namespace

std::optional<std::string> read_stamp(const fs::path& out) {
  const std::optional<ParsedStamp> parsed = parse_stamp(out);
  if (!parsed || !result_change(parsed->results.front()).empty()) return std::nullopt;
  return parsed->inputs;
}

std::string damaged_result(const fs::path& out) {
  const std::optional<ParsedStamp> parsed = parse_stamp(out);
  if (!parsed || !result_change(parsed->results.front()).empty()) return "";  // another run's summary.json
  for (std::size_t k = 1; k < parsed->results.size(); ++k)
    if (std::string why = result_change(parsed->results[k]); !why.empty()) return why;
  return "";
}

void write_stamp(const fs::path& out, const std::string& stamp) {
  write_whole(stamp_file(out), stamp + result_lines(out));
}

std::string first_change(const std::string& before, const std::string& now) {
  std::set<std::string> old_lines;
  std::istringstream b(before), n(now);
  std::string line;
  while (std::getline(b, line)) old_lines.insert(line);
  while (std::getline(n, line))
    if (!old_lines.count(line)) return line;
  return {};
}

}  // namespace crosscheck
