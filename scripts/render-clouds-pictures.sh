#!/usr/bin/env bash
# Renders the pictures of docs/effects/clouds.md ("Pictures") into docs/images/clouds/: the three cloud
# scenes (demo/scenes/clouds_noon.json, clouds_sunset.json, clouds_above.json)
#   <scene>.png          at 960×540, 8 frames (the clouds' temporal accumulation averages 8 jittered
#                        marches; the ground reads the clouds' shadow map from frame 1 on): the slab model;
#   <scene>_octaves.png  the same with Wrenninge's octaves as the scenes had them (4 octaves, 0.6/0.6/0.5);
#   <scene>_path.png     240×135, the clouds path-traced (every scattering order, 64 paths a pixel;
#                        postfx-render --reference=path), beside
#   <scene>_small.png    the real-time frame at the same size.
# Needs postfx-render (build/ or $1); about 5 minutes on lavapipe and two cores (the path tracer most).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
out=docs/images/clouds
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"

for scene in noon sunset above; do
    src="demo/scenes/clouds_$scene.json"
    sed 's|"multiple_scattering": { "model": "slab" }|"multiple_scattering": { "model": "octaves", "octaves": 4, "attenuation": 0.6, "contribution": 0.6, "eccentricity": 0.5 }|' \
        "$src" >"$tmp/octaves.json"
    grep -q '"model": "octaves"' "$tmp/octaves.json"
    "$build/demo/postfx-render" "$src" -o "$out/$scene.png" --size 960x540 --frames 8
    "$build/demo/postfx-render" "$tmp/octaves.json" -o "$out/${scene}_octaves.png" --size 960x540 --frames 8
    "$build/demo/postfx-render" "$src" -o "$out/${scene}_small.png" --size 240x135 --frames 8
    "$build/demo/postfx-render" "$src" -o "$tmp/path.png" --size 240x135 --frames 8 --reference=path \
        --path-samples 64
    mv "$tmp/path.png" "$out/${scene}_path.png"
done
ls -l "$out"
