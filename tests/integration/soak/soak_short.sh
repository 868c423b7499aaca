#!/usr/bin/env bash
# The soak's short version (90 s of the repeating mission, 30 s windows): scripts/soak judges it.
#   soak_short.sh BUILD_DIR WORK_DIR        (in a private network namespace)
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
rm -rf "$2"
exec bash "$root/scripts/soak" --build "$1" --out "$2" --minutes 1.5
