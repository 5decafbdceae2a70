#!/usr/bin/env bash
# Fails when a C++ or GLSL source differs from what clang-format (.clang-format at the root) makes of it.
# GLSL (.comp .vert .frag .glsl, and the .h headers GLSL and C++ share) is formatted as C++, which
# clang-format assumes for these extensions; each shader folder's .clang-format keeps #include order (a
# shader declares before use) and says which constructs are kept between clang-format off and on.
set -euo pipefail
cd "$(dirname "$0")/.."
patterns=('*.h' '*.cpp' '*.comp' '*.vert' '*.frag' '*.glsl')
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    files=$(git ls-files "${patterns[@]}")
else
    files=$(find postfx demo tests bench shaders -name '*.h' -o -name '*.cpp' -o -name '*.comp' \
        -o -name '*.vert' -o -name '*.frag' -o -name '*.glsl')
fi
# shellcheck disable=SC2086
clang-format --dry-run --Werror $files
