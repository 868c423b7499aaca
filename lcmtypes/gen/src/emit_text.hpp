#pragma once
// Internal: C++ spelling of names shared by the emitters.

#include <string>

#include "sdlqr/lcmgen/schema.hpp"

namespace sdlqr::lcmgen::text {

std::string quoted(const std::string& s);          // a C++ string literal
std::string packageNamespace(const std::string& package);  // "a.b" -> "a::b"
std::string lcmClass(const LcmStruct& type);       // "::sdlqr::imu_t"
std::string lcmInclude(const LcmStruct& type);     // "sdlqr/imu_t.hpp"
std::string descriptorName(const LcmStruct& type); // "kImuT"
std::string banner(const std::string& source_note);

}  // namespace sdlqr::lcmgen::text
