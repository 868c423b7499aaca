#pragma once
// Progress of long work on stderr: on a terminal one line redrawn in place (bar, count, elapsed,
// ETA, failures); otherwise a plain line every 10 % or 10 s, so a log file stays readable.

#include <chrono>
#include <cstdio>
#include <string>

namespace sdlqr::batch {

class Progress {
 public:
  // `total` items of which `done` were finished before this run (not counted in the rate).
  Progress(long long total, long long done, bool terminal, std::FILE* out = stderr);
  void update(long long done, long long failed);
  void finish(long long done, long long failed);
  double elapsedSeconds() const;

 private:
  std::string line(long long done, long long failed) const;
  long long total_, start_done_;
  bool terminal_;
  std::FILE* out_;
  std::chrono::steady_clock::time_point start_, last_;
  long long last_reported_ = -1;
};

}  // namespace sdlqr::batch
