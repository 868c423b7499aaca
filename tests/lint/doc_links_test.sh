#!/usr/bin/env bash
# doc_links.py passes on the repository's README and docs/, and fails, naming the rule, on a page
# with a broken relative link, a link to a heading that is not there, an ./sdlqr command that does
# not exist, an executable no build file names, and a repository file that does not exist.
#   doc_links_test.sh SOURCE_DIR WORK_DIR
set -u
root="$1" work="$2"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
source "$here/../support/checker_test.sh" /usr/bin/python3 "$here/doc_links.py"

# negative RULE LINE: a copy of ./sdlqr, a docs/ page with a heading, config/ with one file, and a
# README holding LINE; doc_links.py must exit 1 naming the rule on README.md's line 3.
negative() {
  rm -rf "$work" && mkdir -p "$work/docs" "$work/config"
  cp "$root/sdlqr" "$work/sdlqr"
  printf 'set_target_properties(x PROPERTIES OUTPUT_NAME sdlqr-analyze)\n' >"$work/CMakeLists.txt"
  printf '# Page\n\n## A section\n' >"$work/docs/page.md"
  : >"$work/config/quad.yaml"
  printf '# sdlqr\n\n%s\n\n[page](docs/page.md#a-section), `config/quad.yaml`, `./sdlqr demo`, `sdlqr-analyze`\n' "$2" >"$work/README.md"
  expect_caught "$1" "^README.md:3: $1 " "$work"
  if [ "$(grep -c '^README.md' <<<"$CAUGHT_OUT")" != 1 ]; then
    echo "FAIL (negative) $1: the page's valid link, file and command were flagged too:"
    echo "$CAUGHT_OUT"
    failed=1
  fi
}
expect_repository_passes "the README or docs/ point at what does not exist" "$root"
negative broken-link 'See [the design](docs/design.md).'
negative broken-anchor 'See [a section](docs/page.md#no-such-section).'
negative unknown-command 'Run `./sdlqr fly hover_jumps`.'
negative unknown-executable 'Judge it with `sdlqr-analyse run.lcmlog`.'
negative missing-file 'The vehicle file is `config/quad999.yaml`.'
[ "$failed" -eq 0 ] && echo PASS
exit "$failed"
