#!/bin/sh
# Fails when an effect's code names another effect's (docs/architecture.md, "Layers"): a file in
# postfx/src/<effect>/ or shaders/<effect>/ that includes a header of another effect's folder, or a file of
# the core or the common layer (postfx/src/core, postfx/src/common, shaders/core, shaders/common) that
# includes any effect's header. Effects read each other's resources through common/ only. $1: the source
# root. Only the registry (postfx/src/effects.cpp) names every effect.
set -eu
root=$1
effects=$(cd "$root/postfx/src" && find . -mindepth 1 -maxdepth 1 -type d ! -name core ! -name common |
    sed 's#^\./##' | sort)
[ -n "$effects" ] || { echo "no effect folders under $root/postfx/src"; exit 1; }
bad=0
# Lines `#include "<folder>/..."` of the files under $1, with their file and line.
includes() { grep -rnE '^[[:space:]]*#[[:space:]]*include[[:space:]]+"[a-z_]+/' "$1" 2>/dev/null || true; }
for tree in postfx/src shaders; do
    for dir in $effects core common; do
        [ -d "$root/$tree/$dir" ] || continue
        hits=$(includes "$root/$tree/$dir" | while IFS= read -r line; do
            target=$(printf '%s\n' "$line" | sed -E 's/.*#[[:space:]]*include[[:space:]]+"([a-z_]+)\/.*/\1/')
            for e in $effects; do
                if [ "$target" = "$e" ] && [ "$target" != "$dir" ]; then printf '%s\n' "$line"; fi
            done
        done)
        if [ -n "$hits" ]; then
            echo "$tree/$dir includes another effect's header:"
            printf '%s\n' "$hits" | sed "s#^$root/##"
            bad=1
        fi
    done
done
[ $bad = 0 ] || exit 1
echo "effects include only their own headers, the core's and the common layer's: $(echo $effects)"
