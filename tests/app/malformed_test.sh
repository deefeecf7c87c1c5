#!/usr/bin/env bash
# The malformed-scene corpus (tests/malformed/cases.txt): `raytex render` on each scene must
# exit with 2, print exactly the expected one-line message and write no output file. Every
# scene file in tests/malformed/ must have a case, and there must be at least 40.
# Usage: malformed_test.sh RAYTEX SOURCE_DIR
set -u
raytex=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")  # absolute: the cases run in the corpus
dir=$2/tests/malformed
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
passed=0
failed=0
fail() {
  failed=$((failed + 1))
  echo "FAIL $*"
}

cd "$dir" || exit 1
declare -A listed
while IFS=$'\t' read -r file expected; do
  case $file in '#'* | '') continue ;; esac
  listed[$file]=1
  out=$("$raytex" render "$file" -o "$tmp/out.png" 2>&1)
  rc=$?
  if [ "$rc" -ne 2 ]; then
    fail "$file: exit $rc (want 2)"
  elif [ "$out" != "$expected" ]; then
    fail "$file: printed"
    echo "  $out"
    echo "  want $expected"
  elif [ -e "$tmp/out.png" ]; then
    fail "$file: wrote an output file"
  else
    passed=$((passed + 1))
  fi
  rm -f "$tmp/out.png"
done <cases.txt

for file in *.cfg; do
  [ -n "${listed[$file]:-}" ] || fail "$file has no case in cases.txt"
done
[ "${#listed[@]}" -ge 40 ] || fail "only ${#listed[@]} cases (want at least 40)"

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
