#!/usr/bin/env bash
# check-cli-reference.sh CLI GUI PAGE: fails when the user guide's command reference (PAGE)
# differs from what make-cli-reference.sh writes for the current programs.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
if ! diff -u "$3" <("$here/make-cli-reference.sh" "$1" "$2"); then
  echo "FAIL: $3 is out of date: $here/make-cli-reference.sh CLI GUI > $3" >&2
  exit 1
fi
echo "OK: $3 matches the programs' --help"
