#!/usr/bin/env bash
# The scenes of docs/tutorial.md as written there: each ```cfg block after a
# "<!-- step N -->" line goes to OUT_DIR/step-N.cfg. Prints the step numbers.
# Usage: tutorial_steps.sh TUTORIAL_MD OUT_DIR
set -eu
mkdir -p "$2"
awk -v out="$2" '
  /^<!-- step [0-9]+ -->$/ { step = $3; want = 1; next }
  want && /^```cfg$/ { file = out "/step-" step ".cfg"; printf "" >file; inside = 1; want = 0; print step; next }
  inside && /^```$/ { close(file); inside = 0; next }
  inside { print >file }
' "$1"
