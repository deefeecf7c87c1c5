#!/usr/bin/env bash
# Output that never destroys, end to end: -o as a device, a FIFO, a symlink, the scene's own
# files; modes, long names, signals and file size limits during the write; stdout write errors
# and the top-level handler. Device nodes are made with mknod in a temporary directory (root
# only; skipped with a message otherwise), never the system's.
# Usage: output_test.sh RAYTEX SOURCE_DIR
set -u
source "$(dirname "$0")/cli_checks.sh"
is_png() { test "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a; }
no_temp() { test "$(ls -A "$1" | grep -c 'tmp-')" -eq 0; }

# A copy of the example scene (scene, include, image) that the tests may try to overwrite.
mkdir -p "$tmp/scenes" "$tmp/textures"
cp "$src/scenes/textures.cfg" "$src/scenes/texture_include.cfg" "$tmp/scenes/"
cp "$src/textures/earth.jpg" "$src/textures/uv_grid.png" "$tmp/textures/"
mkdir "$tmp/orig"
cp -r "$tmp/scenes" "$tmp/textures" "$tmp/orig/"
scene=$tmp/scenes/textures.cfg
small=(--width 32 --height 24)

# Device nodes: written through, never replaced. (1, 3) is a null device, (1, 7) a full one.
mkdir "$tmp/dev"
if mknod "$tmp/dev/null" c 1 3 2>/dev/null && mknod "$tmp/dev/full" c 1 7 2>/dev/null; then
  expect dev-null 0 '' -- "$raytex" render "$scene" "${small[@]}" -o "$tmp/dev/null"
  check dev-null-still-a-device test -c "$tmp/dev/null"
  expect dev-full 1 "^raytex: cannot write '$tmp/dev/full': No space left on device$" -- \
    "$raytex" render "$scene" "${small[@]}" -o "$tmp/dev/full"
  check dev-full-still-a-device test -c "$tmp/dev/full"
  check dev-no-temp no_temp "$tmp/dev"
  # Standard output that cannot be written: exit 1 and one line, for every command.
  for command in "--help" "--version" "devices" "render $scene ${small[*]} -o $tmp/s.png --stats" \
    "render $scene ${small[*]} -o $tmp/s.png --stats --reference" "bench $scene ${small[*]} --runs 1" \
    "bench $scene ${small[*]} --runs 1 --json"; do
    # shellcheck disable=SC2086
    expect "stdout-full: $command" 1 '^raytex: cannot write to standard output: No space left on device$' -- \
      env FULL="$tmp/dev/full" ERR="$tmp/stderr.txt" bash -c \
      '"$@" >"$FULL" 2>"$ERR"; rc=$?; cat "$ERR"; [ "$(wc -l <"$ERR")" -eq 1 ] || exit 99; exit $rc' \
      _ "$raytex" $command
  done
  # The viewer's messages (--stats when it quits), on a virtual display.
  display=""
  for n in $(seq 121 150); do [ -e /tmp/.X11-unix/X$n ] || { display=":$n"; break; }; done
  if command -v Xvfb >/dev/null && [ -n "$display" ]; then
    Xvfb "$display" -screen 0 320x240x24 >/dev/null 2>&1 &
    xvfb=$!
    for _ in $(seq 100); do [ -e "/tmp/.X11-unix/X${display#:}" ] && break; sleep 0.05; done
    expect "stdout-full: view" 1 '^raytex: cannot write to standard output: No space left on device$' -- \
      env DISPLAY="$display" FULL="$tmp/dev/full" bash -c '"$@" >"$FULL"' _ "$raytex" view "$scene" \
      "${small[@]}" -o "$tmp/view.png" --frames 2 --stats
    kill "$xvfb"
    wait "$xvfb" 2>/dev/null
  else
    echo "skip: no Xvfb: the viewer's stdout check not run"
  fi
else
  echo "skip: cannot mknod device nodes in $tmp (not root?): device and stdout checks not run"
fi

# A FIFO: with no reader, an error at once rather than a wait; with one, it gets the PNG.
mkfifo "$tmp/fifo"
expect fifo-no-reader 1 "^raytex: cannot write '$tmp/fifo': no process is reading it$" -- \
  timeout 60 "$raytex" render "$scene" "${small[@]}" -o "$tmp/fifo"
cat "$tmp/fifo" >"$tmp/from-fifo.png" &
reader=$!
expect fifo-reader 0 '' -- timeout 60 "$raytex" render "$scene" "${small[@]}" -o "$tmp/fifo"
wait "$reader"
check fifo-gets-png is_png "$tmp/from-fifo.png"
check fifo-still-a-fifo test -p "$tmp/fifo"

# A link to a pipe, as /dev/stdout is (/proc/self/fd/1 -> "pipe:[N]"): written through to it.
ln -s /proc/self/fd/1 "$tmp/stdout-link"
"$raytex" render "$scene" "${small[@]}" -o "$tmp/stdout-link" --reference | cat >"$tmp/piped.png"
check stdout-link-pipe is_png "$tmp/piped.png"
check stdout-link-still-a-link test -L "$tmp/stdout-link"

# A symlink is followed: its target is replaced, the link stays.
mkdir "$tmp/real"
echo old >"$tmp/real/a.png"
ln -s real/a.png "$tmp/link.png"
expect symlink 0 '' -- "$raytex" render "$scene" "${small[@]}" -o "$tmp/link.png" --reference
check symlink-still-a-link test -L "$tmp/link.png"
check symlink-target-png is_png "$tmp/real/a.png"

# The scene's own files are refused before rendering (exit 2), and left as they were (restored
# after each try, so that one failure does not spoil the checks after it).
unchanged() {  # unchanged NAME: the scene's files are as copied; restores them if not
  check "$1-unchanged" diff -rq "$tmp/orig/scenes" "$tmp/scenes"
  check "$1-images-unchanged" diff -rq "$tmp/orig/textures" "$tmp/textures"
  cp "$tmp/orig/scenes/"* "$tmp/scenes/" && cp "$tmp/orig/textures/"* "$tmp/textures/"
}
for cmd in "render" "render --reference" "bench" "view"; do
  # shellcheck disable=SC2086
  expect "clash-scene: $cmd" 2 "^raytex: refusing to write '$scene': it is the scene file \\('$scene'\\)$" -- \
    "$raytex" $cmd "$scene" "${small[@]}" -o "$scene"
  unchanged "clash-scene: $cmd"
  # shellcheck disable=SC2086
  expect "clash-include: $cmd" 2 "it is a file the scene includes \\('$tmp/scenes/texture_include.cfg'\\)$" -- \
    "$raytex" $cmd "$scene" "${small[@]}" -o "$tmp/scenes/texture_include.cfg"
  unchanged "clash-include: $cmd"
  # shellcheck disable=SC2086
  expect "clash-image: $cmd" 2 "^raytex: refusing to write '$tmp/scenes/../textures/earth.jpg': it is an image the scene uses \\('$tmp/textures/earth.jpg'\\)$" -- \
    "$raytex" $cmd "$scene" "${small[@]}" -o "$tmp/scenes/../textures/earth.jpg"
  unchanged "clash-image: $cmd"
done
ln "$scene" "$tmp/hardlink.png"
expect clash-hardlink 2 "^raytex: refusing to write '$tmp/hardlink.png': it is the scene file \\('$scene'\\)$" -- \
  "$raytex" render "$scene" "${small[@]}" -o "$tmp/hardlink.png"
unchanged clash-hardlink

# An existing output keeps its mode; a name of 255 bytes is written (the temp name is cut).
echo old >"$tmp/private.png"
chmod 600 "$tmp/private.png"
expect mode 0 '' -- "$raytex" render "$scene" "${small[@]}" -o "$tmp/private.png" --reference
check mode-kept test "$(stat -c %a "$tmp/private.png")" = 600
long=$(printf 'n%.0s' $(seq 251)).png
expect long-name 0 '' -- "$raytex" render "$scene" "${small[@]}" -o "$tmp/$long" --reference
check long-name-png is_png "$tmp/$long"

# A signal in the middle of a write (the test hook stops the process there), for every signal
# whose default action ends the process: nothing is left beside the old output, the exit status
# is the signal's, and the old output stays. The file being written has no name (O_TMPFILE);
# with RAYTEX_TEST_NAMED_TEMP=1 it is a named temporary, as where the file system refuses
# O_TMPFILE, which the signal handler removes. An EXR, written as its rows come.
mkdir "$tmp/sig"
for named in 0 1; do
  for sig in INT TERM HUP QUIT ALRM USR1 USR2 PIPE XCPU VTALRM PROF; do
    echo old >"$tmp/sig/out.exr"
    if [ "$named" = 1 ]; then hook=(RAYTEX_TEST_NAMED_TEMP=1); else hook=(); fi
    env --default-signal RAYTEX_TEST_PAUSE_IN_WRITE=1 "${hook[@]}" \
      "$raytex" render "$scene" "${small[@]}" -o "$tmp/sig/out.exr" --reference >/dev/null 2>&1 &
    pid=$!
    for _ in $(seq 200); do
      [ "$(ps -o stat= -p "$pid" 2>/dev/null | cut -c1)" = T ] && break
      sleep 0.05
    done
    check "signal-$sig-$named-stopped-mid-write" test "$(ls -A "$tmp/sig" | grep -c 'tmp-')" -eq "$named"
    if [ "$(ps -o stat= -p "$pid" 2>/dev/null | cut -c1)" = T ]; then
      kill -s "$sig" "$pid"
      kill -s CONT "$pid"
    fi
    wait "$pid" 2>/dev/null
    rc=$?
    check "signal-$sig-$named-status" test "$rc" -eq $((128 + $(kill -l "$sig")))
    check "signal-$sig-$named-nothing-left" test "$(ls -A "$tmp/sig")" = out.exr
    check "signal-$sig-$named-old-output" grep -qx old "$tmp/sig/out.exr"
  done
done

# A file size limit: SIGXFSZ is ignored, so it is a write error (exit 1, one line), no temp file.
mkdir "$tmp/fsize"
expect file-size-limit 1 "^raytex: cannot write '$tmp/fsize/out.png': File too large$" -- \
  bash -c 'ulimit -f 1; exec "$0" render "$1" -o "$2" --width 320 --height 240 --reference' \
  "$raytex" "$scene" "$tmp/fsize/out.png"
check file-size-limit-no-file test "$(ls -A "$tmp/fsize" | wc -l)" -eq 0

# Out of host memory: the 8192x8192 float64 reference image (1.5 GiB) does not fit in 1 GB of
# address space. One line and exit 1, not SIGABRT.
# (Not under ASan, tests/sanitize/run.sh: its shadow memory needs terabytes of address space.)
if [ "${RAYTEX_SANITIZED:-0}" != 1 ]; then
  expect host-out-of-memory 1 '^raytex: out of memory$' -- \
    bash -c 'ulimit -v 1000000; exec "$0" render "$1" -o "$2" --width 8192 --height 8192 --reference' \
    "$raytex" "$scene" "$tmp/oom.png"
  check host-out-of-memory-no-file test ! -e "$tmp/oom.png"
fi

# --help names the new exit reasons.
expect help-exit-codes 0 '^     an output file or standard output not written' -- "$raytex" --help
expect help-output 0 'FIFO is written through' -- "$raytex" --help

finish
