# Shared by the command-line test scripts (cli_test.sh, output_test.sh): sourced after the
# script's usage line with its arguments RAYTEX SOURCE_DIR. Sets raytex and src (absolute: some
# checks run in other directories), a temporary directory tmp removed at exit, and the pass and
# fail counters that expect, check and finish keep.
raytex=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
src=$(cd "$2" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
passed=0
failed=0

# expect NAME CODE PATTERN -- command...: exit code CODE and stderr+stdout matching PATTERN.
expect() {
  local name=$1 code=$2 pattern=$3
  shift 4
  local out rc
  out=$("$@" 2>&1)
  rc=$?
  if [ "$rc" -eq "$code" ] && grep -qE -- "$pattern" <<<"$out"; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
    echo "FAIL $name: exit $rc (want $code), output:"
    echo "$out" | head -5
  fi
}
check() {  # check NAME CONDITION...
  local name=$1
  shift
  if "$@"; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAIL $name"; fi
}
finish() {  # the closing line; the exit status says whether every check passed
  echo "$passed passed, $failed failed"
  [ "$failed" -eq 0 ]
}
