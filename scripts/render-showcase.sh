#!/usr/bin/env bash
# Renders the README's picture from the showcase (demo/scenes/showcase.json) with postfx-render on the
# default Vulkan device (lavapipe here): 960×540, frame 11 of its flight path (the camera moving forward
# and turning, the temporal histories accumulating over the 12 frames), to docs/images/showcase.png.
# usage: scripts/render-showcase.sh [BUILD_DIR]   (default build/; postfx-render must be built there)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
"$build/demo/postfx-render" demo/scenes/showcase.json -o docs/images/showcase.png --size 960x540 --frames 12
ls -l docs/images/showcase.png
