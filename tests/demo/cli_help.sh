#!/bin/sh
# postfx-render --help: exits 0 and describes its EXR output as the writer writes it, 32-bit float RGBA
# (demo/host/image_io.cpp; DemoImageIo reads a written file's pixel format back), never half.
# usage: cli_help.sh POSTFX_RENDER
set -u
render=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
failures=0

if ! "$render" --help >"$dir/out" 2>"$dir/err"; then
    echo "FAIL --help: exit status $?"
    cat "$dir/err"
    failures=$((failures + 1))
fi
exr=$(grep '^ *\.exr ' "$dir/out")
if [ -z "$exr" ]; then
    echo "FAIL --help: no line describing .exr output:"
    cat "$dir/out"
    failures=$((failures + 1))
elif ! printf '%s\n' "$exr" | grep -q '32-bit float'; then
    echo "FAIL --help: the .exr line does not say 32-bit float: $exr"
    failures=$((failures + 1))
elif printf '%s\n' "$exr" | grep -qi 'half'; then
    echo "FAIL --help: the .exr line speaks of half floats: $exr"
    failures=$((failures + 1))
else
    echo "ok   --help: $exr"
fi

if [ "$failures" -ne 0 ]; then
    echo "$failures failure(s)"
    exit 1
fi
