#!/usr/bin/env bash
# Checks that every C++ file of the tree follows .clang-format.
set -euo pipefail
clang_format="$1"
root="$2"
cd "$root"
mapfile -t files < <(find core app widgets tests -name '*.cpp' -o -name '*.h' | sort)
"$clang_format" --dry-run --Werror "${files[@]}"
echo "OK: ${#files[@]} files follow .clang-format"
