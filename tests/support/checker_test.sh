# Sourced by the tests of the repository's own checkers (tests/lint/*_test.sh), with the checker's
# command line: `source checker_test.sh CHECKER...`; `checker DIR` then runs it on DIR. A checker
# must pass on the repository, and exit 1 naming its rule on a sample that breaks that rule. The
# test counts its failures in `failed` and exits with it.
CHECKER=("$@")
failed=0

checker() { "${CHECKER[@]}" "$@"; }

# expect_repository_passes WHAT ROOT: the checker passes on the repository at ROOT; on failure
# reports WHAT with the checker's findings.
expect_repository_passes() {
  local out
  if out="$(checker "$2")"; then
    echo "ok   the repository: ${out:-no finding}"
  else
    echo "FAIL: $1:"
    echo "$out"
    failed=1
  fi
}

# expect_caught NAME LINE_REGEX DIR: the checker, on the sample in DIR, must exit 1 and print a line
# matching LINE_REGEX (grep -E), the rule it names. Leaves the checker's output in CAUGHT_OUT.
expect_caught() {
  local status
  CAUGHT_OUT="$(checker "$3")"
  status=$?
  if [ "$status" -eq 1 ] && grep -qE "$2" <<<"$CAUGHT_OUT"; then
    echo "ok   (negative) $1 caught: $(grep -E "$2" <<<"$CAUGHT_OUT" | head -1)"
  else
    echo "FAIL (negative) $1 not caught (exit $status; expected a line /$2/):"
    echo "$CAUGHT_OUT"
    failed=1
  fi
}
