// The calibration spec's typed fields, read through a ConfigNode (key tracking, the spec's
// file and the key's dotted path in every error) and checked in the spec's words: every
// problem is a ConfigError naming the file, the key and the reason (CLI exit code 2).
#pragma once
#include <string>
#include <vector>

#include "config/config_reader.hpp"

namespace colza::calibration {

// A number (integers read as numbers); missing: "missing (a number is required)".
double required_number(const ConfigNode& table, const std::string& key);
// The number, or `fallback` when the key is absent.
double number_or(const ConfigNode& table, const std::string& key, double fallback);
// A required number > 0.
double required_positive(const ConfigNode& table, const std::string& key);
// A whole number in [lo, hi], or `fallback` when absent.
long long whole_number_or(const ConfigNode& table, const std::string& key, long long fallback, long long lo,
                          long long hi);
// A string; missing: "missing (a string is required)".
std::string required_string(const ConfigNode& table, const std::string& key);
// The string, or `fallback` when absent.
std::string string_or(const ConfigNode& table, const std::string& key, const std::string& fallback);
// An array of finite numbers; empty when absent.
std::vector<double> number_array(const ConfigNode& table, const std::string& key);
// An array of strings; empty when absent.
std::vector<std::string> string_array(const ConfigNode& table, const std::string& key);
// The sub-table `key` (a view on nothing when absent; "must be a table" when not one).
ConfigNode sub_table(const ConfigNode& table, const std::string& key);
// Every key of `table` nobody read is "unknown key (misspelt? it does not belong in this table)".
void reject_unknown_spec_keys(const ConfigNode& table);

// A number as the spec's messages state it: 6 significant digits.
std::string spec_number_text(double v);

}  // namespace colza::calibration
