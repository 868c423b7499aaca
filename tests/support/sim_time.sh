# Sourced by flight tests that inject a fault (a kill, a restart, an attack, a signal): the fault
# lands at an instant of the flight's own simulation clock, never at wall seconds after a launch.
# A machine that stalls for seconds (seen when compilers ran beside the flights; `./sdlqr test` now
# builds everything first, but a user's machine may be busy) stalls the simulation with it, so a
# fault timed in wall seconds lands late in the flight, or after it.
#
#   sim_time_marks BUILD_DIR S1,S2,... [sdlqr-top options]   one waiter per flight, listening from now
#   wait_sim_time S     returns once the flight's SIM_CLOCK has reached S (one of the marks, written
#                       the same way, in order); 1 if the waiter ended first (the flight never got
#                       there: say so and fail)
#   stop_sim_time       ends the waiter (it ends by itself after its last mark)
#   now_us VAR          sets VAR to the wall time in microseconds
# Nothing between the mark and the fault starts a process: on this kind of machine (a VM whose
# page faults are costly) a fork/exec once waited 37 s beside compilers (docs/verdicts.md).
#
# The waiter is `sdlqr-top --at-sim-time` (tools/examine/inspect/top_main.cpp), a process on the bus
# like the launcher's own heartbeat waiter, under the same name, which sdlqr-faultcheck lets stop.

sim_time_marks() {
  local build="$1" marks="$2"
  shift 2
  exec {SIM_TIME_FD}< <(exec "$build/bin/sdlqr-top" --at-sim-time "$marks" --timeout 300 "$@")
  SIM_TIME_PID=$!
}

wait_sim_time() {
  local line
  while read -r -u "$SIM_TIME_FD" line; do
    [ "$line" = "sim time $1" ] && return 0
  done
  echo "wait_sim_time: the flight's simulation clock never reached $1 s"
  return 1
}

# Wall time now [us], with no process started (a fork can take seconds on a loaded machine).
now_us() { printf -v "$1" '%s' "${EPOCHREALTIME/./}"; }

stop_sim_time() {
  kill -TERM "$SIM_TIME_PID" 2>/dev/null
  exec {SIM_TIME_FD}<&-
}

# start_marked_flight BUILD WORK MARKS LAUNCH_ARGS...: an empty WORK, the waiter for MARKS (before
# the launch, so no mark is missed), then scripts/launch in the background with its log at
# WORK/flight.lcmlog and its output in WORK/launch.out. Sets `log` and `launcher` (its pid).
start_marked_flight() {
  local build="$1" work="$2" marks="$3"
  shift 3
  rm -rf "$work"
  mkdir -p "$work"
  log="$work/flight.lcmlog"
  sim_time_marks "$build" "$marks"
  "$(dirname "${BASH_SOURCE[0]}")/../../scripts/launch" --build "$build" --log "$log" "$@" > "$work/launch.out" 2>&1 &
  launcher=$!
}

# wait_sim_time_or_stop WORK S: wait_sim_time S; if the flight never gets there, shows the launcher's
# output, stops the flight started by start_marked_flight and exits 1 (the fault never happened).
wait_sim_time_or_stop() {
  wait_sim_time "$2" && return 0
  cat "$1/launch.out"
  kill -TERM "$launcher"
  wait "$launcher"
  exit 1
}
