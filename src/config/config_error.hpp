// Bad input: names the file, the key and the reason. The CLI turns it into exit code 2.
#pragma once
#include <stdexcept>
#include <string>

namespace colza {

class ConfigError : public std::runtime_error {
 public:
  ConfigError(std::string file, std::string key, std::string reason)
      : std::runtime_error(format(file, key, reason)), file_(std::move(file)), key_(std::move(key)),
        reason_(std::move(reason)) {}
  const std::string& file() const { return file_; }
  const std::string& key() const { return key_; }
  const std::string& reason() const { return reason_; }

 private:
  static std::string format(const std::string& file, const std::string& key, const std::string& reason) {
    std::string s = file;
    if (!key.empty()) s += ": key '" + key + "'";
    return s + ": " + reason;
  }
  std::string file_, key_, reason_;
};

}  // namespace colza
