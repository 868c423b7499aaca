#!/usr/bin/env bash
# Every document a source comment cites by name exists in the repository, and no comment cites
# the design brief that is not in it ("DESIGN §n"). Exit 1 naming each offending line.
#   citations.sh SOURCE_DIR
set -u
root="$1"
cd "$root" || exit 2
status=0
sources=$(git ls-files '*.cpp' '*.hpp' '*.h' '*.lcm' '*.sh' '*.py' '*.yaml' '*.txt' 'sdlqr' 'scripts/*' 2>/dev/null)
[ -n "$sources" ] || { echo "citations: no sources found under $root"; exit 2; }
# shellcheck disable=SC2086
while IFS= read -r hit; do
  echo "cites a document not in the repository: $hit"
  status=1
done < <(grep -HnE 'DESIGN( ?§|\.md)' $sources | grep -v '^tests/lint/')
# shellcheck disable=SC2086
while IFS=: read -r file line doc; do
  [ -e "$doc" ] || [ -e "$(dirname "$file")/$doc" ] || { echo "$file:$line: cites $doc, which does not exist"; status=1; }
done < <(grep -HnoE '\b[A-Z][A-Z_]+\.md\b' $sources | grep -v '^tests/lint/')
[ $status -eq 0 ] && echo "citations: every cited document exists ($(echo "$sources" | wc -l) files)"
exit $status
