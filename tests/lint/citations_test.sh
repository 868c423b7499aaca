#!/usr/bin/env bash
# citations.sh passes on the repository and fails on a repository whose comments cite the
# design brief or a missing document.
#   citations_test.sh SOURCE_DIR WORK_DIR
set -u
root="$1" work="$2"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
bash "$here/citations.sh" "$root" || { echo "FAIL: the repository cites a missing document"; exit 1; }
rm -rf "$work" && mkdir -p "$work" && cd "$work" && git init -q . || exit 2
for bad in '// as in DESIGN §3' '// see MISSING.md'; do
  echo "$bad" > bad.cpp
  git add bad.cpp
  out="$(bash "$here/citations.sh" "$work")"
  status=$?
  [ "$status" -eq 1 ] && grep -q "cites" <<<"$out" || { echo "FAIL: not caught (exit $status): $bad"; exit 1; }
done
echo "PASS"
