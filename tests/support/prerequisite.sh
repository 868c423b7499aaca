# Sourced by shell tests. missing_prerequisite WHAT HOW: the test cannot run without WHAT.
# On a developer's machine it is skipped, and says so (exit 77: ctest reports it "Skipped" where
# the test sets SKIP_RETURN_CODE 77); in CI (CI=true), where `./sdlqr setup` installed every
# prerequisite, it fails: a skip there would pass a test that never ran.
missing_prerequisite() {
  if [ "${CI:-}" = true ]; then
    echo "FAIL: missing prerequisite with CI=true: $1 ($2)"
    exit 1
  fi
  echo "SKIPPED: missing prerequisite (fails with CI=true): $1 ($2)"
  exit 77
}
