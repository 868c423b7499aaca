#pragma once
// Names of recorded logs: "<dir>/<YYYYmmdd-HHMMSS>-<scenario>.lcmlog", so a folder of flights
// sorts by date and says what each one was.

#include <ctime>
#include <string>

namespace sdlqr::logger {

inline constexpr const char* kLogExtension = ".lcmlog";

// Empty when `scenario` is usable in a file name: letters, digits, '_', '-', '.', not starting
// with '.', at most 100 characters.
std::string invalidScenarioReason(const std::string& scenario);

// `local_time` is the calendar time the recording starts.
std::string scenarioLogPath(const std::string& dir, const std::string& scenario, const std::tm& local_time);

// Turns an LCM channel name into a relative path for its CSV file: "QUAD1/IMU" -> "QUAD1/IMU.csv".
// Characters outside [A-Za-z0-9_.-] and the components "", ".", ".." become '_', so a channel
// name read from a log can never leave the export folder.
std::string channelCsvPath(const std::string& channel);

}  // namespace sdlqr::logger
