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
// The opening of every generated header: #pragma once, the banner naming its inputs
// (`source_note`) and `purpose`, the comment that says what the header is for.
std::string headerOpening(const std::string& source_note, const std::string& purpose);

}  // namespace sdlqr::lcmgen::text
