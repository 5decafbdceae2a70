#!/usr/bin/env bash
# Re-renders every golden image and writes it over the committed one (tests/*/golden/). Review the new
# images (git diff --stat, look at them) before committing. Needs a configured build/ (run-tests.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --build build -j"$(nproc)"
POSTFX_ACCEPT_GOLDENS=1 ctest --test-dir build --output-on-failure -R 'Golden' "$@"
git status --short -- 'tests/*/golden/*'
