#!/usr/bin/env bash
# Runs node_mavlink_check.mjs (our MAVLink frames against node-mavlink, both ways) with the pinned
# npm packages of the root package-lock.json (`./sdlqr setup` runs npm ci).
#   node_mavlink_check.sh SOURCE_DIR MAVLINK_VECTORS
set -uo pipefail
source="$1" vectors="$2"
. "$source/tests/support/prerequisite.sh"
command -v node >/dev/null || missing_prerequisite "node" "Debian nodejs, ./sdlqr setup"
[ -f "$source/node_modules/node-mavlink/package.json" ] ||
  missing_prerequisite "node_modules/node-mavlink" "npm ci at the repository root, ./sdlqr setup"
node "$source/tests/integration/px4/node_mavlink_check.mjs" "$vectors"
