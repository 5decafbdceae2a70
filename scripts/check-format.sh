#!/usr/bin/env bash
# Fails when a C++ or GLSL source differs from what clang-format (.clang-format at the root) makes of it.
set -euo pipefail
cd "$(dirname "$0")/.."
files=$(git ls-files '*.h' '*.cpp' 2>/dev/null || find postfx demo tests bench -name '*.h' -o -name '*.cpp')
# shellcheck disable=SC2086
clang-format --dry-run --Werror $files
