#!/usr/bin/env bash
# Installs the Debian 12 packages raytex builds and tests with (all from Debian; nothing
# downloaded). Runs apt-get as root, or through sudo when not root.
set -euo pipefail
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends \
  build-essential cmake ninja-build pkg-config \
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers glslang-tools \
  libglm-dev libglfw3-dev libstb-dev zlib1g-dev libpng-dev libjpeg-dev libopenexr-dev libgtest-dev \
  clang libclang-rt-dev \
  xvfb xdotool x11-apps >/dev/null
# libpng-dev, libjpeg-dev (libjpeg-turbo): image decoding that refuses corrupt files;
# libopenexr-dev: EXR scanlines written band by band, layers, half floats (tinyexr writes whole images);
# clang, libclang-rt-dev: the parser's fuzz test (libFuzzer, ASan and UBSan runtimes);
# xvfb, xdotool, x11-apps: the viewer's test (a virtual X display, keys, xwd captures).
echo "raytex dependencies installed"
