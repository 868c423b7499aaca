#pragma once
// What the parameter and file tests ask of every bad file they load: the key its ConfigError
// blames, or the message of the error it throws.

#include <initializer_list>
#include <string>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "sdlqr/config/config.hpp"

namespace sdlqr::testing {

// What `describe` says of the E that `run()` throws, or "<no error>" when it runs through.
template <class E, class Run, class Describe>
std::string describeThrown(Run&& run, Describe&& describe) {
  try {
    run();
  } catch (const E& e) {
    return describe(e);
  }
  return "<no error>";
}

// The key of the ConfigError `load()` throws, or "<no error>" when it loads.
template <class Load>
std::string keyBlamedBy(Load&& load) {
  return describeThrown<ConfigError>(load, [](const ConfigError& e) { return e.key(); });
}

// The message of the E that `run()` throws, or "<no error>" when it runs through.
template <class E, class Run>
std::string messageThrownBy(Run&& run) {
  return describeThrown<E>(run, [](const E& e) { return std::string(e.what()); });
}

// P read from YAML text as the section `section`, which prefixes the keys its errors blame.
template <class P>
P loadSectionText(const std::string& text, const std::string& section) {
  return P::load(ConfigReader(YAML::Load(text), section));
}

// A file its loader must refuse, and the key the refusal must blame.
struct RefusedFile {
  std::string yaml;
  std::string key;
};

// Each file, given to `load`, must be refused with a ConfigError blaming its key; a failure names
// the file, so one table lists every bad value of a section.
template <class Load>
void expectKeysBlamed(const Load& load, std::initializer_list<RefusedFile> files) {
  for (const RefusedFile& file : files) {
    EXPECT_EQ(keyBlamedBy([&] { load(file.yaml); }), file.key) << "loading " << file.yaml;
  }
}

}  // namespace sdlqr::testing
