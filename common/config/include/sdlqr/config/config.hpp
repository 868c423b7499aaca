#pragma once
// Strict YAML reading for every parameter struct: a wrong type, a wrong length, a non-finite
// number or an unknown key becomes a ConfigError naming the full key ("lqr.r_diag[2]"), which
// every executable prints as one line before exiting with code 2.

#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace sdlqr {

class ConfigError : public std::runtime_error {
 public:
  ConfigError(const std::string& key, const std::string& reason)
      : std::runtime_error(key + ": " + reason), key_(key) {}
  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

// Parses a file; a missing or malformed file is a ConfigError naming the file.
YAML::Node loadYamlFile(const std::string& path);

class ConfigReader;

// The vehicle file of every process (config/*.yaml): an empty path gives built-in defaults; a
// top-level section not in vehicleFileSections() is an error (a typo would otherwise be ignored).
ConfigReader loadVehicleConfig(const std::string& path);
// The top-level sections of a vehicle file, in the order the printed defaults list them (each
// one's keys are declared by its parameter struct; tools/setup/params lists the struct of each).
const std::vector<std::string>& vehicleFileSections();

// A view of one mapping in the document, remembering its dotted path for messages.
class ConfigReader {
 public:
  ConfigReader(YAML::Node node, std::string path);

  bool has(const std::string& key) const;
  // The sub-mapping `key`; an absent key gives an empty reader (all defaults kept).
  ConfigReader child(const std::string& key) const;
  // Rejects keys not in `allowed` (typos otherwise pass silently as "default kept"); the error
  // suggests the allowed key a typo most likely meant.
  void allowOnly(std::initializer_list<const char*> allowed) const;
  void allowOnly(const std::vector<std::string>& allowed) const;

  // Each read leaves `out` untouched when the key is absent.
  void read(const std::string& key, double& out) const;
  void read(const std::string& key, int& out) const;
  void read(const std::string& key, long long& out) const;
  void read(const std::string& key, bool& out) const;
  void read(const std::string& key, std::string& out) const;
  template <int N>
  void read(const std::string& key, Eigen::Matrix<double, N, 1>& out) const {
    readVector(key, out.data(), N);
  }

  const std::string& path() const { return path_; }
  std::string keyPath(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

 private:
  void readVector(const std::string& key, double* out, int size) const;
  YAML::Node node_;
  std::string path_;
};

// Turns an invalidReason() text "key: reason" (key relative to `reader`) into a ConfigError
// naming the full key path; nothing when `reason` is empty.
void throwIfInvalid(const ConfigReader& reader, const std::string& reason);

}  // namespace sdlqr
