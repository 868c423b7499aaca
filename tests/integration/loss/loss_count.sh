#!/usr/bin/env bash
# The loss counters count kernel-dropped messages exactly: nftables drops ~20 % of the IMU port's
# datagrams (random), and the receiving Node's lost.IMU must equal the kernel's drop counter minus
# the drops before its first and after its last handled message (invisible to any seq count),
# with nothing lost elsewhere (handled + kernel drops = sent).
#   loss_count.sh PEER        (run in a private network namespace)
set -uo pipefail
peer="$1"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
sent=2000
SDLQR_ALLOW_PACKET_LOSS=1 "$root/scripts/packet_loss" 20 --port "$("$peer" port)" || exit 1
out="$("$peer" "$sent")" || exit 1
dropped="$(SDLQR_ALLOW_PACKET_LOSS=1 "$root/scripts/packet_loss" --dropped)"
echo "loss_count: sent $sent, kernel dropped $dropped, receiver: $out"
eval "$(tr ' .' '\n_' <<<"$out" | grep -E '^[a-z_A-Z]+=[0-9-]+$')"
expected_lost=$((dropped - first - (sent - 1 - last)))
status=0
[ "$dropped" -gt $((sent / 10)) ] || { echo "FAIL: the kernel dropped too few ($dropped) for the test to mean anything"; status=1; }
[ $((handled + dropped)) -eq "$sent" ] || { echo "FAIL: handled $handled + dropped $dropped != sent $sent"; status=1; }
[ "$lost_IMU" -eq "$expected_lost" ] || { echo "FAIL: lost.IMU $lost_IMU, expected $expected_lost"; status=1; }
[ "$queue_drop_IMU" -eq 0 ] || { echo "FAIL: queue_drop.IMU $queue_drop_IMU, expected 0"; status=1; }
[ "$status" = 0 ] && echo "loss_count: PASS (lost.IMU $lost_IMU = kernel drops inside the received span)"
exit "$status"
