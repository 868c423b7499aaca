#!/usr/bin/env bash
# function_length.py passes on the repository, and fails, naming the rule and the function, on a
# sample whose function is 81 lines; a brace in a string or a comment does not end a function, a
# digit separator (1'800'000) is no character literal hiding the brace after it, and an 80-line
# function passes.
#   function_length_test.sh SOURCE_DIR WORK_DIR
set -u
root="$1" work="$2"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
source "$here/../support/checker_test.sh" /usr/bin/python3 "$here/function_length.py"

# sample LINES: a .cpp in WORK_DIR with one function `longOne` whose head to closing brace spans
# LINES lines, with '}' inside a string and a comment on the way, and a braced number with digit
# separators.
sample() {
  rm -rf "$work" && mkdir -p "$work/src"
  {
    echo 'namespace demo {'
    echo 'int longOne(int x) {'
    echo '  const char* brace = "}";  // } here neither'
    echo "  const long big[] = {1'800'000'000}; x += big[0] > 0;"
    for ((i = 0; i < $1 - 4; ++i)); do echo "  x += $i;"; done
    echo '}'
    echo 'int shortOne() { return 1; }'
    echo '}  // namespace demo'
  } >"$work/src/sample.cpp"
}

expect_repository_passes "functions over 80 lines" "$root"
sample 81
expect_caught "an 81-line function" "^src/sample.cpp:2: function-too-long longOne is 81 lines" "$work"
sample 80
if out="$(checker "$work")"; then
  echo "ok   an 80-line function passes"
else
  echo "FAIL: an 80-line function must pass: $out"
  failed=1
fi
rm -rf "$work"
exit "$failed"
