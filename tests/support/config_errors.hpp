#pragma once
// What the parameter tests ask of every bad file they load: the key its ConfigError blames.

#include <string>

#include <yaml-cpp/yaml.h>

#include "sdlqr/config/config.hpp"

namespace sdlqr::testing {

// The key of the ConfigError `load()` throws, or "<no error>" when it loads.
template <class Load>
std::string keyBlamedBy(Load&& load) {
  try {
    load();
  } catch (const ConfigError& e) {
    return e.key();
  }
  return "<no error>";
}

// P read from YAML text as the section `section`, which prefixes the keys its errors blame.
template <class P>
P loadSectionText(const std::string& text, const std::string& section) {
  return P::load(ConfigReader(YAML::Load(text), section));
}

}  // namespace sdlqr::testing
