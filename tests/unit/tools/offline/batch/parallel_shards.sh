#!/usr/bin/env bash
# Four shards of a batch through GNU parallel (as docs/batches.md, Batches, runs them over ssh), merged:
# flights.csv, summary.txt and batch.yaml must equal the single run's bit for bit.
# usage: parallel_shards.sh SDLQR_BATCH SPEC WORK_DIR
set -euo pipefail
batch="$1" spec="$2" work="$3"
if ! command -v parallel >/dev/null; then
  echo "GNU parallel is not installed (Debian package parallel; ./sdlqr setup installs it)" >&2
  [ "${CI:-}" = true ] && exit 1
  exit 77
fi
rm -rf "$work"
mkdir -p "$work"
"$batch" "$spec" --out "$work/single" --jobs 2 --no-progress >/dev/null
parallel --will-cite --halt now,fail=1 -j 4 \
  "$batch" "$spec" --shard {}/4 --out "$work/shard-{}" --jobs 1 --no-progress ">/dev/null" ::: 1 2 3 4
"$batch" merge "$spec" --out "$work/merged" "$work"/shard-{1,2,3,4} >/dev/null
for file in flights.csv summary.txt batch.yaml; do
  cmp "$work/single/$file" "$work/merged/$file" || { echo "merged $file differs from the single run's" >&2; exit 1; }
done
rows=$(($(wc -l <"$work/merged/flights.csv") - 1))
[ "$rows" -eq 20 ] || { echo "expected 20 rows, merged $rows" >&2; exit 1; }
# Negative: a merge missing a shard is refused, naming it (exit 1).
status=0
refusal="$("$batch" merge "$spec" --out "$work/incomplete" "$work"/shard-{1,2,3} 2>&1)" || status=$?
if [ "$status" -ne 1 ] || ! grep -q "shard 4/4 missing" <<<"$refusal"; then
  echo "a merge of 3 of 4 shards: exit $status, expected 1 naming shard 4/4: $refusal" >&2
  exit 1
fi
echo "4 shards through GNU parallel merged into the single run's $rows rows, bit for bit"
