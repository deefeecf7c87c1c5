#!/usr/bin/env bash
# No function in host/ runs over 60 lines from its signature to its closing brace
# (docs/architecture.md): a function longer than that is split into named steps. A definition is
# found by its layout (clang-format's): a signature starting in column 0, its body closed by a
# "}" in column 0. Tables of data (initialisers ending "= {") are not functions.
# Usage: function_length_test.sh SOURCE_DIR
set -u
limit=60
awk -v limit="$limit" '
  FNR == 1 { start = 0 }
  start == 0 && /^[A-Za-z_][^;]*\(/ && !/^(namespace|struct|enum|class|union|typedef|using|static_assert)/ && !/= *\{ *$/ {
    if (/[;}] *$/) next  # a declaration, or a function on one line
    start = FNR; name = $0; body = /\{ *$/; next
  }
  start > 0 && !body && /;$/ { start = 0; next }  # a declaration over several lines
  start > 0 && /\{ *$/ { body = 1 }
  start > 0 && /^\}/ {
    n = FNR - start + 1
    if (n > limit) { printf "%s:%d: %d lines: %s\n", FILENAME, start, n, name; bad = 1 }
    start = 0; next
  }
  END { exit bad }
' "$1"/host/*/*.cpp
rc=$?
[ "$rc" -eq 0 ] && echo "every function in host/ is at most $limit lines"
exit "$rc"
