#!/usr/bin/env bash
# Proves that includes only point down (docs/architecture.md, "Layers"): app -> widgets -> core,
# and inside core from a module to modules of a lower layer only. Modules of one layer are
# siblings: neither includes the other. Inside io/, io/files/ (plain file utilities) includes
# no other io/ folder, and io/mesh/, io/run/ and io/pickle/ include only io/files/.
#   include_layers.sh ROOT
set -euo pipefail
cd "$1"

# The layer of each core module: a module includes only modules of a lower layer.
declare -A layer=(
  [common]=0
  [sonar]=1
  [geo]=2
  [io]=3
  [geometry]=4 [denoise]=4
  [carve]=5 [eval]=5 [model]=5
  [occlusion]=6 [sim]=6
  [mesh]=7 [fit]=7
  [pipeline]=8
  [session]=9
)

status=0
fail() {
  echo "FAIL: $1"
  status=1
}

# Every folder of core/ has a layer: a new module must be placed.
for dir in core/*/; do
  module=$(basename "$dir")
  [ -n "${layer[$module]+x}" ] || fail "core/$module has no layer in $0"
done

include_re='^\s*#\s*include\s*"([a-z_]+)/([^"]*)"'
while IFS= read -r -d '' file; do
  from=${file#core/}
  from=${from%%/*}
  from_layer=${layer[$from]:-}
  [ -n "$from_layer" ] || continue
  while IFS= read -r line; do
    [[ $line =~ $include_re ]] || continue
    to=${BASH_REMATCH[1]}
    rest=${BASH_REMATCH[2]}
    if [ "$to" = "$from" ]; then
      if [ "$from" = io ]; then
        sub_from=$(echo "$file" | cut -d/ -f3)
        sub_to=${rest%%/*}
        [ "$sub_to" = "$rest" ] && sub_to=""  # a header at io/'s root
        case "$sub_from" in
          files) [ "$sub_to" = files ] || fail "$file includes io/$rest: io/files/ is the lowest" ;;
          mesh | run | pickle)
            [ "$sub_to" = "$sub_from" ] || [ "$sub_to" = files ] ||
              fail "$file includes io/$rest: io/$sub_from/ includes only io/files/"
            ;;
        esac
      fi
      continue
    fi
    to_layer=${layer[$to]:-}
    [ -n "$to_layer" ] || continue  # not a core module (a third-party header)
    if [ "$to_layer" -ge "$from_layer" ]; then
      fail "$file includes $to/$rest: $from (layer $from_layer) may include only lower layers, $to is layer $to_layer"
    fi
  done <"$file"
done < <(find core -name '*.h' -print0 -o -name '*.cpp' -print0)

# widgets/ never includes the applications' headers; core never includes widgets' or app's.
app_headers=$(find app -name '*.h' -printf '%f\n' | sort -u)
widget_headers=$(find widgets -name '*.h' -printf '%f\n' | sort -u)
for header in $app_headers; do
  if grep -rnE "^\s*#\s*include\s*[<\"]$header[\">]" widgets core; then
    fail "widgets/ or core/ include the application's $header (above)"
  fi
done
for header in $widget_headers; do
  if grep -rnE "^\s*#\s*include\s*[<\"]$header[\">]" core; then
    fail "core/ includes the widget header $header (above)"
  fi
done

[ $status -eq 0 ] && echo "OK: every include points down (app -> widgets -> core, core by layers)"
exit $status
