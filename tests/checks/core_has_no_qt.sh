#!/usr/bin/env bash
# Proves that the engine stays free of Qt: no Qt include in core/ sources, and no Qt library
# among the shared libraries that libsonarcarve_core loads (directly or through a dependency).
set -euo pipefail
lib="$1"
src="$2"
status=0
if grep -rnE '#\s*include\s*[<"](Q[A-Za-z]+|Qt[A-Za-z]*/)' "$src"; then
  echo "FAIL: core/ includes a Qt header (above)"
  status=1
fi
if ldd "$lib" | grep -i 'libQt'; then
  echo "FAIL: $lib loads Qt (above)"
  status=1
fi
[ $status -eq 0 ] && echo "OK: core has no Qt include and loads no Qt library"
exit $status
