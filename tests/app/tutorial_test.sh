#!/usr/bin/env bash
# docs/tutorial.md as a new user follows it: each step's scene, as written there, saved as
# mine/first.cfg in a directory beside textures/ and scenes/, rendered at the pictures' size
# (320x240) and compared with the step's picture in docs/tutorial/ as the golden tests compare
# (mean FLIP at most 0.02, at most 0.25 % of the pixels over 0.05 linear); what the tutorial
# shows raytex printing (steps 1 and 4) is what it prints. RAYTEX_UPDATE_GOLDENS=1 rewrites the
# pictures (look at them before committing).
# Usage: tutorial_test.sh RAYTEX SOURCE_DIR
set -u
source "$(dirname "$0")/cli_checks.sh"
doc=$src/docs/tutorial.md
mkdir -p "$tmp/mine"
ln -s "$src/textures" "$tmp/textures"
ln -s "$src/scenes" "$tmp/scenes"
steps=$(bash "$src/tests/app/tutorial_steps.sh" "$doc" "$tmp/steps" | tr '\n' ' ')
check seven-steps test "$steps" = "1 2 3 4 5 6 7 "

# inTutorial FILE: every line of FILE is a line of the tutorial, verbatim.
inTutorial() {
  local line
  while IFS= read -r line; do grep -qxF -- "$line" "$doc" || { echo "not in the tutorial: $line"; return 1; }; done <"$1"
}

# renderStep N: the step's scene as mine/first.cfg, rendered from the directory above mine/.
renderStep() {
  cp "$tmp/steps/step-$1.cfg" "$tmp/mine/first.cfg"
  rm -f "$tmp/mine/first.png"
  (cd "$tmp" && "$raytex" render mine/first.cfg -o mine/first.png --width 320 --height 240) >"$tmp/out.txt" 2>&1
}

# matchesPicture PNG: mine/first.png is PNG within the limits (the comparison printed if not).
matchesPicture() {
  "$raytex" diff "$tmp/mine/first.png" "$1" --threshold 0.05 --fail-flip 0.02 --fail-percent 0.25 >"$tmp/diff.txt" 2>&1 ||
    { cat "$tmp/diff.txt"; return 1; }
}

renderStep 1
check step-1-exit-2 test $? -eq 2
check step-1-no-image test ! -e "$tmp/mine/first.png"
check step-1-message-as-shown inTutorial "$tmp/out.txt"

for n in 2 3 4 5 6 7; do
  renderStep "$n"
  check "step-$n-renders" test $? -eq 0
  # Only notes, never an error; step 4's is shown in the tutorial.
  check "step-$n-notes-only" bash -c "! grep -v ': note: ' '$tmp/out.txt'"
  [ "$n" = 4 ] && check step-4-note-as-shown inTutorial "$tmp/out.txt"
  picture=$src/docs/tutorial/step-$n.png
  if [ "${RAYTEX_UPDATE_GOLDENS:-}" = 1 ]; then
    cp "$tmp/mine/first.png" "$picture"
    echo "wrote $picture: look at it before committing"
  fi
  check "step-$n-matches-picture" matchesPicture "$picture"
done
finish
