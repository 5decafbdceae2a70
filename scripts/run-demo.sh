#!/usr/bin/env bash
# Builds the demo and runs it on the showcase scene (demo/scenes/showcase.json: sky, clouds, froxel fog with
# the sun's shafts and local lights, every effect at once), or on the scene file given. With a display it
# opens a window; without one it renders the scene to an image and says where. Installs missing Debian
# packages first. Other arguments go to postfx-demo (--size, --frames, --no-ui, --validation).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh build
# Tests off: GoogleTest is a test dependency, not installed by `install-deps.sh build`.
cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPOSTFX_BUILD_TESTS=OFF >/dev/null
cmake --build build -j"$(nproc)" --target postfx-demo
for arg in "$@"; do
    [[ $arg == *.json ]] && exec build/demo/postfx-demo "$@"
done
exec build/demo/postfx-demo demo/scenes/showcase.json "$@"
