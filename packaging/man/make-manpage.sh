#!/usr/bin/env bash
# make-manpage.sh HELP2MAN PROGRAM NAME INCLUDE.h2m OUT.1.gz [--verbs]
# The man page of PROGRAM from its --help and --version (help2man), with the sections of
# INCLUDE.h2m; with --verbs, a COMMANDS section holding `PROGRAM VERB --help` for every verb
# its --help lists under Subcommands. Compressed with gzip -9n (Debian policy: no name, no
# time stamp). The page's date is the changelog's, so that rebuilding gives the same file.
set -euo pipefail
help2man=$1 program=$2 name=$3 include=$4 out=$5 verbs=${6:-}
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

includes=(--include "$include")
if [ "$verbs" = --verbs ]; then
  {
    echo "[COMMANDS]"
    "$program" --help | sed -n '/^Subcommands:/,$p' | sed -n 's/^  \([a-z][a-z-]*\) .*/\1/p' |
      while read -r verb; do
        echo ".SS \"$(basename "$program") $verb\""
        echo ".nf"
        # roff: a backslash is \e, a line starting with . or ' is escaped with \&.
        "$program" "$verb" --help | sed -e 's/\\/\\e/g' -e "s/^\([.']\)/\\\\\&\1/"
        echo ".fi"
      done
  } > "$tmp/commands.h2m"
  grep -q '^\.SS' "$tmp/commands.h2m" || { echo "no verbs found in $program --help" >&2; exit 1; }
  includes+=(--include "$tmp/commands.h2m")
fi

if command -v dpkg-parsechangelog >/dev/null; then
  SOURCE_DATE_EPOCH=$(dpkg-parsechangelog -l "$here/../changelog" -S Timestamp)
  export SOURCE_DATE_EPOCH
fi
# The page is named after the program file, also where --version says "SonarCarve 0.1.0".
version=$("$program" --version | head -n 1 | awk '{print $NF}')
"$help2man" --no-info --section 1 --name "$name" "${includes[@]}" \
  --version-string "$(basename "$program") $version" --output "$tmp/page.1" "$program"
gzip -9n < "$tmp/page.1" > "$out"
