#include "sdlqr/batch/progress.hpp"

#include <cmath>

namespace sdlqr::batch {

namespace {

std::string duration(double s) {
  char text[32];
  if (!std::isfinite(s)) return "?";
  if (s < 60.0) {
    std::snprintf(text, sizeof text, "%.0f s", s);
  } else {
    std::snprintf(text, sizeof text, "%dm%02ds", static_cast<int>(s) / 60, static_cast<int>(s) % 60);
  }
  return text;
}

}  // namespace

Progress::Progress(long long total, long long done, bool terminal, std::FILE* out)
    : total_(total), start_done_(done), terminal_(terminal), out_(out), start_(std::chrono::steady_clock::now()),
      last_(start_) {}

double Progress::elapsedSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

std::string Progress::line(long long done, long long failed) const {
  const double elapsed = elapsedSeconds();
  const long long flown = done - start_done_;
  const double eta = flown > 0 ? elapsed / static_cast<double>(flown) * static_cast<double>(total_ - done) : NAN;
  char text[160];
  std::snprintf(text, sizeof text, "%lld/%lld flights, %s, ETA %s, %lld failed", done, total_, duration(elapsed).c_str(),
                done == total_ ? "0 s" : duration(eta).c_str(), failed);
  if (!terminal_) return std::string("batch: ") + text;
  constexpr int kWidth = 30;
  const int filled = total_ ? static_cast<int>(kWidth * done / total_) : kWidth;
  return "\r[" + std::string(filled, '#') + std::string(kWidth - filled, '.') + "] " + text + "\033[K";
}

void Progress::update(long long done, long long failed) {
  const auto now = std::chrono::steady_clock::now();
  const double since = std::chrono::duration<double>(now - last_).count();
  if (terminal_) {
    if (since < 0.2 && done != total_) return;
  } else {
    const bool tenth = total_ > 0 && (10 * done / total_) != (10 * std::max(last_reported_, 0LL) / total_);
    if (!(tenth || since >= 10.0 || last_reported_ < 0)) return;
  }
  last_ = now;
  last_reported_ = done;
  std::fputs((line(done, failed) + (terminal_ ? "" : "\n")).c_str(), out_);
  std::fflush(out_);
}

void Progress::finish(long long done, long long failed) {
  if (!terminal_ && last_reported_ == done) return;  // the last plain line said it already
  std::fputs((line(done, failed) + "\n").c_str(), out_);
  std::fflush(out_);
}

}  // namespace sdlqr::batch
