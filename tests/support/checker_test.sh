# Sourced by the tests of the repository's own checkers (tests/lint/*_test.sh): a checker must pass
# on the repository, and exit 1 naming its rule on a sample that breaks that rule. The test counts
# its failures in `failed` and exits with it.
failed=0

# expect_repository_passes WHAT CHECKER...: runs CHECKER (on the repository); on failure reports
# WHAT with the checker's findings.
expect_repository_passes() {
  local what="$1" out
  shift
  if out="$("$@")"; then
    echo "ok   the repository: ${out:-no finding}"
  else
    echo "FAIL: $what:"
    echo "$out"
    failed=1
  fi
}

# expect_caught NAME LINE_REGEX CHECKER...: CHECKER (on a sample) must exit 1 and print a line
# matching LINE_REGEX (grep -E), the rule it names. Leaves the checker's output in CAUGHT_OUT.
expect_caught() {
  local name="$1" line="$2" status
  shift 2
  CAUGHT_OUT="$("$@")"
  status=$?
  if [ "$status" -eq 1 ] && grep -qE "$line" <<<"$CAUGHT_OUT"; then
    echo "ok   (negative) $name caught: $(grep -E "$line" <<<"$CAUGHT_OUT" | head -1)"
  else
    echo "FAIL (negative) $name not caught (exit $status; expected a line /$line/):"
    echo "$CAUGHT_OUT"
    failed=1
  fi
}
