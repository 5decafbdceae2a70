#!/usr/bin/env bash
# Builds the demo and runs it on its built-in default scene. With a display it opens a window; without
# one it renders the scene to an image and says where. Installs missing Debian packages first.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh build
# Tests off: GoogleTest is a test dependency, not installed by `install-deps.sh build`.
cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPOSTFX_BUILD_TESTS=OFF >/dev/null
cmake --build build -j"$(nproc)" --target postfx-demo
exec build/demo/postfx-demo "$@"
