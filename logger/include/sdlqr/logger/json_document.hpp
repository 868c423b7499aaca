#pragma once
// JSON documents (metrics.json, report.json) through nlohmann-json (Debian nlohmann-json3-dev):
// members in the order they are set, two-space indent, non-finite numbers as null (valid JSON),
// bytes that are not UTF-8 replaced (a log's strings are untrusted), one trailing newline.

#include <ostream>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "sdlqr/logger/statistics.hpp"

namespace sdlqr::logger {

using JsonDocument = nlohmann::ordered_json;

void writeJsonDocument(std::ostream& out, const JsonDocument& document);

// {"count", "mean", "min", "median", "p99", "max"}
JsonDocument toJson(const Distribution& d);

// Reads a whole document; NaN, Infinity and -Infinity (what the CSV export writes for non-finite
// numbers, like Python's json module) are read as those numbers. False with *error (naming the
// byte) on bad input.
bool parseJson(std::string_view text, JsonDocument* out, std::string* error);

// A number as the CSV export writes it (integers in decimal, others "%.17g", NaN, Infinity).
std::string numberText(const JsonDocument& number);

}  // namespace sdlqr::logger
