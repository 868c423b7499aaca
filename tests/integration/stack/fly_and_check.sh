#!/usr/bin/env bash
# Flies one scenario with the real executables over real multicast (the caller runs this in its
# own network namespace) and checks every criterion of the scenario with sdlqr-analyze.
#   fly_and_check.sh BUILD_DIR WORK_DIR SCENARIO [launch options...]
set -uo pipefail
build="$1" work="$2" scenario="$3"
shift 3
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
rm -rf "$work"
mkdir -p "$work"
log="$work/flight.lcmlog"
vehicle_args=()
args=("$@")
for ((i = 0; i < ${#args[@]}; i++)); do
  [ "${args[$i]}" = --vehicle ] && vehicle_args=(--vehicle "${args[$((i + 1))]}")
done

"$root/scripts/launch" --build "$build" --log "$log" "$@" "$scenario"
launch_status=$?
echo "fly_and_check: launcher exit code $launch_status"
[ "$launch_status" -eq 0 ] || exit 1
"$build/bin/sdlqr-analyze" "$log" --scenario "$scenario" "${vehicle_args[@]+"${vehicle_args[@]}"}" \
  --calibration "$work/calibration.yaml" --json "$work/report.json"
