#!/usr/bin/env bash
# Proves the header rules of core/CMakeLists.txt: core's public headers (every header outside a
# module's internal/ folder) include no internal header and no VTK, OctoMap, Embree or PROJ header;
# app/ and widgets/ include no internal header; only the simulator itself, the command line
# and tests include sim/.
set -euo pipefail
root="$1"
cd "$root"

# Public headers that still break the rule, each with the reason it is waiting. The check
# names any that has since moved, so that the list only shrinks.
pending=()

status=0
fail() {
  echo "FAIL: $1 (above)"
  status=1
}
is_pending() {
  local file="$1" p
  for p in "${pending[@]}"; do
    [ "$file" = "$p" ] && return 0
  done
  return 1
}

include='^\s*#\s*include\s*[<"]'
mapfile -t public_headers < <(find core -name '*.h' -not -path '*/internal/*' | sort)
offending=()
for header in "${public_headers[@]}"; do
  if grep -nHE "${include}([^\">]*/)?internal/|${include}(vtk|octomap/|embree|proj\.h)" "$header"; then
    is_pending "$header" && echo "  (pending: $header)" || offending+=("$header")
  fi
done
[ ${#offending[@]} -eq 0 ] ||
  fail "public core headers include an internal, VTK, OctoMap, Embree or PROJ header: ${offending[*]}"

if grep -rnE "${include}([^\">]*/)?internal/" app widgets; then
  fail "app/ or widgets/ include a core internal header"
fi

if grep -rnE "${include}sim/" core widgets app --exclude-dir=sim --exclude-dir=cli; then
  fail "only core/sim, app/cli and tests may include the simulator (sim/)"
fi

for p in "${pending[@]}"; do
  [ -e "$p" ] || echo "note: $p has moved: remove it from the pending list of $0"
done
[ $status -eq 0 ] && echo "OK: public core headers keep VTK, OctoMap, Embree, PROJ and internals out"
exit $status
