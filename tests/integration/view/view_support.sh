# Sourced by the view's tests: begin_view_test sources tests/support/prerequisite.sh itself.

# Every view test's start: its prerequisites (needs: npm, or browser for Chromium too; missing:
# skipped here, failed with CI=true), an empty WORK folder, and the LOG it reads, when it reads one.
begin_view_test() {  # ROOT WORK npm|browser [LOG]
  source "$1/tests/support/prerequisite.sh"
  if [ "$3" = browser ]; then require_browser_and_npm "$1"; else require_npm "$1"; fi
  rm -rf "$2" && mkdir -p "$2"
  if [ $# -ge 4 ] && [ ! -s "$4" ]; then echo "FAIL: no log $4 (its fixture failed?)"; exit 1; fi
}

# Node and the pinned npm packages; missing: skipped here, failed with CI=true.
require_npm() {  # ROOT
  command -v node >/dev/null || missing_prerequisite node "Debian package nodejs (./sdlqr setup)"
  local package
  for package in puppeteer-core @foxglove/ws-protocol @foxglove/schemas @mcap/core ws; do
    [ -d "$1/node_modules/$package" ] || missing_prerequisite "npm package $package" "./sdlqr setup runs npm ci"
  done
}

# And Debian's Chromium for the page.
require_browser_and_npm() {  # ROOT
  require_npm "$1"
  [ -x "${SDLQR_CHROMIUM:-/usr/bin/chromium}" ] || missing_prerequisite chromium "Debian package chromium (./sdlqr setup)"
}

# Waits up to 10 s until something listens on 127.0.0.1:PORT.
wait_for_port() {  # PORT
  local _
  for _ in $(seq 100); do
    (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null && return 0
    sleep 0.1
  done
  return 1
}

# User + system CPU ticks (1/100 s) of a process so far.
cpu_ticks() {  # PID
  awk '{ sub(/.*\) /, ""); print $12 + $13 }' "/proc/$1/stat"
}
