#!/usr/bin/env bash
# params-reference.sh CLI PAGE [--update]
# The blocks of PAGE between "<!-- BEGIN generated: sonarcarve-cli ARGS -->" and
# "<!-- END generated -->" are the output of `sonarcarve-cli ARGS` (a YAML fence around
# --yaml output), so that the user guide's parameter tables come from the parameter schema.
# Without --update: fails when PAGE differs from what the program prints (the lint test
# guide_params_reference); with --update: rewrites PAGE.
set -euo pipefail
cli=$1 page=$2 mode=${3:-}

render() {
  local line args skipping=0
  while IFS= read -r line; do
    if [[ $line =~ ^'<!-- BEGIN generated: sonarcarve-cli '(.*)' -->'$ ]]; then
      printf '%s\n' "$line"
      args=${BASH_REMATCH[1]}
      if [[ $args == *--yaml* ]]; then
        # shellcheck disable=SC2086 # the marker's words are the arguments
        printf '```yaml\n%s\n```\n' "$("$cli" $args)"
      else
        # shellcheck disable=SC2086
        "$cli" $args
      fi
      skipping=1
    elif [[ $line == '<!-- END generated -->' ]]; then
      printf '%s\n' "$line"
      skipping=0
    elif ((!skipping)); then
      printf '%s\n' "$line"
    fi
  done <"$page"
}

if [[ $mode == --update ]]; then
  rendered=$(render)
  printf '%s\n' "$rendered" >"$page"
  echo "updated $page"
elif ! diff -u "$page" <(render); then
  echo "FAIL: $page is out of date: $0 CLI $page --update" >&2
  exit 1
else
  echo "OK: $page matches sonarcarve-cli's output"
fi
