#!/usr/bin/env bash
# The Java side of lcm-spy, checked without a display:
#  1. DecodeCheck (javac) decodes the first message of every channel of a recorded log with
#     lcmtypes_sdlqr.jar, found by fingerprint as lcm-spy finds types;
#  2. lcm-spy itself starts under xvfb-run, stays up 5 s without error output and reports our
#     types ("Found N LCM types").
#   spy_check.sh JAR LOG WORK_DIR EXPECTED_TYPES
set -u
jar="$1" log="$2" work="$3" expected="$4"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
lcm_jar=/usr/share/java/lcm.jar
chart_jar=/usr/share/java/jchart2d.jar
rm -rf "$work" && mkdir -p "$work/classes"
failed=0
fail() { echo "FAIL: $*"; failed=1; }

echo "== 1. DecodeCheck: every channel of $log"
javac -nowarn -cp "$lcm_jar:$jar" -d "$work/classes" "$here/DecodeCheck.java" || { echo "FAIL: javac"; exit 1; }
java -cp "$lcm_jar:$jar:$work/classes" DecodeCheck "$jar" "$log" "$expected" || fail "DecodeCheck"

echo "== 2. lcm-spy under xvfb-run for 5 s"
# lcm-spy joins the LCM bus: the caller runs this in a private network namespace.
xvfb-run -a java -Djava.net.preferIPv4Stack=true -cp "$lcm_jar:$chart_jar:$jar" lcm.spy.Spy \
  >"$work/spy.out" 2>"$work/spy.err" &
spy=$!
sleep 5
if kill -0 "$spy" 2>/dev/null; then
  echo "lcm-spy still running after 5 s"
  # Stop the JVM that xvfb-run started (its child, by pid); xvfb-run then stops its Xvfb and ends.
  xvfb=$(pgrep -P "$spy" -x Xvfb)
  for child in $(pgrep -P "$spy" -f lcm.spy.Spy); do kill -TERM "$child" 2>/dev/null; done
  wait "$spy" 2>/dev/null
  # When xvfb-run fails to clean up ("problem while cleaning up temporary directory") its Xvfb
  # lives on, holding every descriptor it inherited (e.g. a lock of `flock ... ctest`).
  for pid in $xvfb; do kill -TERM "$pid" 2>/dev/null; done
else
  wait "$spy"
  fail "lcm-spy exited within 5 s (exit code $?)"
fi
cat "$work/spy.out"
grep -q "Found $expected LCM types" "$work/spy.out" || fail "lcm-spy did not report $expected types"
# Anything on stderr but LCM's two start-up notices (IPv6 off, TTL 0) is an error.
if grep -v -E '^\s*$|^LCM: Disabling IPV6 support$|^LCM: TTL set to zero, traffic will not leave localhost\.$' \
  "$work/spy.err" | grep -q .; then
  fail "lcm-spy wrote to stderr: $(head -5 "$work/spy.err")"
fi
[ $failed -eq 0 ] && echo PASS || echo FAILED
exit $failed
