#!/usr/bin/env bash
# scripts/deploy stops cleanly: SIGTERM mid-flight ends every process and host (exit 143, the log
# written), and nothing is left in the caller's network namespace. A deployment it cannot build
# is refused before anything starts (exit 2, naming the key).
#   teardown.sh BUILD_DIR WORK_DIR SCENARIO DEPLOYMENT
set -uo pipefail
build="$1" work="$2" scenario="$3" deployment="$4"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
rm -rf "$work"
mkdir -p "$work"
fail() { echo "FAIL teardown: $*"; cat "$work/deploy.out" 2>/dev/null | tail -20; exit 1; }

sed 's#ttl=1#ttl=0#' "$deployment" >"$work/ttl0.yaml"
out="$("$root/scripts/deploy" --deploy "$work/ttl0.yaml" --build "$build" "$scenario" 2>&1)"
status=$?
[ "$status" -eq 2 ] && grep -q "lcm_url: needs ttl=1" <<<"$out" || fail "a ttl=0 deployment over hosts: exit $status: $out"
out="$("$root/scripts/deploy" --deploy "$deployment" --build "$build" --link-down nowhere:1:1 "$scenario" 2>&1)"
status=$?
[ "$status" -eq 2 ] && grep -q "no host 'nowhere'" <<<"$out" || fail "--link-down of an unknown host: exit $status: $out"
echo "ok   refused: a ttl=0 deployment over three hosts, a link of an unknown host (exit 2)"

links_before="$(ip -o link | cut -d: -f2 | sort)"
"$root/scripts/deploy" --deploy "$deployment" --build "$build" --no-calibrate --log "$work/flight.lcmlog" "$scenario" \
  >"$work/deploy.out" 2>&1 &
deploy_pid=$!
for _ in $(seq 1 300); do
  grep -q "every process is up" "$work/deploy.out" && break
  kill -0 "$deploy_pid" 2>/dev/null || fail "deploy ended before every process was up"
  sleep 0.1
done
grep -q "every process is up" "$work/deploy.out" || fail "no process up after 30 s"
# Mid-flight: the simulator has started (the launcher says so; this script is outside the run's
# network namespace and cannot hear its clock).
for _ in $(seq 1 300); do
  grep -q "launch: scenario" "$work/deploy.out" && break
  sleep 0.1
done
grep -q "launch: scenario" "$work/deploy.out" || fail "the simulator never started"
kill -TERM "$deploy_pid"
wait "$deploy_pid"
status=$?
[ "$status" -eq 143 ] || fail "deploy exit code $status after SIGTERM, expected 143"
pids="$(sed -n 's/.*launch: started [^ ]* (pid \([0-9]*\)).*/\1/p' "$work/deploy.out")"
[ "$(wc -w <<<"$pids")" -ge 7 ] || fail "expected 7 started processes, saw: $pids"
sleep 1  # the parked host processes poll for the script every 0.5 s
for pid in $pids; do kill -0 "$pid" 2>/dev/null && fail "process $pid still running after deploy ended"; done
leftover="$(pgrep -f "while kill -0 $deploy_pid" || true)"
[ -z "$leftover" ] || fail "host namespaces still held by $leftover"
[ "$(ip -o link | cut -d: -f2 | sort)" = "$links_before" ] || fail "the caller's interfaces changed"
[ -s "$work/flight.lcmlog" ] || fail "no log written"
echo "ok   SIGTERM: exit 143, all $(wc -w <<<"$pids") processes and every host gone, the caller's interfaces untouched, log written"
