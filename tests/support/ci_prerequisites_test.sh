#!/usr/bin/env bash
# With CI=true a test whose prerequisite is missing fails; without it, it is skipped and says so.
# Each kind of prerequisite check is run here with its prerequisite hidden:
#   - a shell test (tools/robustness/fuzz/run_fuzz.sh) given a build folder without the libFuzzer
#     harnesses;
#   - a GoogleTest test (config_validation_tests) with `unshare` off the PATH (no namespaces).
#   ci_prerequisites_test.sh SOURCE_DIR BUILD_DIR CONFIG_VALIDATION_TESTS
set -u
src="$1" build="$2" config_tests="$3"
failed=0
expect() {  # description expected_status actual_status output pattern
  if [ "$2" -eq "$3" ] && grep -q -- "$5" <<<"$4"; then
    echo "ok   $1: exit $3"
  else
    echo "FAIL $1: exit $3 (expected $2, output matching '$5'):"
    sed 's/^/    /' <<<"$4" | tail -5
    failed=1
  fi
}

no_unshare=$(mktemp -d)
trap 'rm -rf "$no_unshare"' EXIT
out=$(env -u CI bash "$src/tools/robustness/fuzz/run_fuzz.sh" "$no_unshare" 1 2>&1)
expect "run_fuzz without libFuzzer harnesses, CI unset" 77 $? "$out" "SKIPPED: missing prerequisite"
out=$(CI=true bash "$src/tools/robustness/fuzz/run_fuzz.sh" "$no_unshare" 1 2>&1)
expect "run_fuzz without libFuzzer harnesses, CI=true" 1 $? "$out" "FAIL: missing prerequisite with CI=true"

filter=--gtest_filter=ConfigValidation.EveryInvalidFieldOfAScenarioIsRefusedByTheMission
out=$(env -u CI PATH="$no_unshare" "$config_tests" "$filter" 2>&1)
expect "config_validation without namespaces, CI unset" 0 $? "$out" "SKIPPED"
out=$(CI=true PATH="$no_unshare" "$config_tests" "$filter" 2>&1)
expect "config_validation without namespaces, CI=true" 1 $? "$out" "missing prerequisite with CI=true"

[ "$failed" -eq 0 ]
