#!/usr/bin/env bash
# Renders the pictures of docs/effects/clouds.md ("Pictures") into docs/images/clouds/: the three cloud
# scenes (demo/scenes/clouds_noon.json, clouds_sunset.json, clouds_above.json) at 960×540, 8 frames (the
# clouds' temporal accumulation averages 8 jittered marches; the ground reads the clouds' shadow map from
# frame 1 on). Needs postfx-render (build/ or $1); about a minute on lavapipe. (The CPU reference,
# postfx-render --reference, takes about 4 minutes per scene at 320×180 on two cores: not rendered here.)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
out=docs/images/clouds
mkdir -p "$out"

for scene in noon sunset above; do
    "$build/demo/postfx-render" "demo/scenes/clouds_$scene.json" -o "$out/$scene.png" --size 960x540 --frames 8
done
ls -l "$out"
