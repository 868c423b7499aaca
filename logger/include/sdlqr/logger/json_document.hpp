#pragma once
// JSON documents (metrics.json, report.json) through nlohmann-json (Debian nlohmann-json3-dev):
// members in the order they are set, two-space indent, non-finite numbers as null (valid JSON),
// bytes that are not UTF-8 replaced (a log's strings are untrusted), one trailing newline.

#include <ostream>

#include <nlohmann/json.hpp>

#include "sdlqr/logger/statistics.hpp"

namespace sdlqr::logger {

using JsonDocument = nlohmann::ordered_json;

void writeJsonDocument(std::ostream& out, const JsonDocument& document);

// {"count", "mean", "min", "median", "p99", "max"}
JsonDocument toJson(const Distribution& d);

}  // namespace sdlqr::logger
