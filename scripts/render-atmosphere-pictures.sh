#!/usr/bin/env bash
# Renders the pictures of docs/effects/atmosphere.md ("Pictures") into docs/images/atmosphere/: the LUTs
# (AtmospherePictures.DISABLED_WriteLutPictures in gpu_tests), a sun elevation series of
# demo/scenes/sky_noon.json (the sun at 60°, 20°, 5°, 1°, −1°, −4°, 20° right of the view, each image at
# its own fixed EV100, 320×180, mosaicked 3×2 with oiiotool), the three sky scenes at 480×270, and the
# sunset with each multiple-scattering model and their difference (sunset_models.png). Needs a
# build with gpu_tests and postfx-render (build/ or $1), jq and oiiotool; a minute on lavapipe.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
out=docs/images/atmosphere
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$build/tests/gpu_tests" --gtest_also_run_disabled_tests --gtest_filter='AtmospherePictures.*'

# Elevation (degrees) and the EV100 that puts the frame's average near mid grey.
series=("60 15" "20 14.5" "5 13" "1 12" "-1 10.5" "-4 8")
tiles=()
for entry in "${series[@]}"; do
    read -r elevation ev <<<"$entry"
    jq --argjson e "$elevation" --argjson ev "$ev" '
        ($e * 3.141592653589793 / 180) as $el | (20 * 3.141592653589793 / 180) as $az
        | .sun.direction = [($el | cos) * ($az | sin), ($el | sin), -($el | cos) * ($az | cos)]
        | .camera.ev100 = $ev' demo/scenes/sky_noon.json >"$tmp/sun.json"
    "$build/demo/postfx-render" "$tmp/sun.json" -o "$tmp/sun.png" --size 320x180
    oiiotool "$tmp/sun.png" --text:x=8:y=22:size=18:color=1,1,1:font=DejaVuSans \
        "sun $elevation deg, EV $ev" -o "$tmp/tile_$elevation.png"
    tiles+=("$tmp/tile_$elevation.png")
done
oiiotool "${tiles[@]}" --mosaic:pad=4 3x2 -o "$out/sun_elevation_series.png"

for scene in sky_noon sky_sunset sky_space; do
    "$build/demo/postfx-render" "demo/scenes/$scene.json" -o "$out/$scene.png" --size 480x270
done
# The sunset with the scattering orders (the default) and Hillaire's model, and the difference
# |orders - hillaire| / orders of the linear radiance (luminance), 0 to 20 % mapped black to white.
jq '.effects.atmosphere.multiple_scattering = "hillaire"' demo/scenes/sky_sunset.json >"$tmp/hillaire.json"
"$build/demo/postfx-render" demo/scenes/sky_sunset.json -o "$tmp/orders.exr" --size 480x270
"$build/demo/postfx-render" "$tmp/hillaire.json" -o "$tmp/hillaire.exr" --size 480x270
"$build/demo/postfx-render" demo/scenes/sky_sunset.json -o "$tmp/orders.png" --size 480x270
"$build/demo/postfx-render" "$tmp/hillaire.json" -o "$tmp/hillaire.png" --size 480x270
oiiotool "$tmp/orders.exr" --ch R,G,B --chsum:weight=0.2126,0.7152,0.0722 -o "$tmp/yo.exr"
oiiotool "$tmp/hillaire.exr" --ch R,G,B --chsum:weight=0.2126,0.7152,0.0722 -o "$tmp/yh.exr"
oiiotool "$tmp/yo.exr" "$tmp/yh.exr" --absdiff "$tmp/yo.exr" --addc 1e-9 --div --mulc 5 --clamp:min=0:max=1 \
    --ch 0,0,0 -d uint8 -o "$tmp/difference.png"
oiiotool "$tmp/orders.png" --text:x=8:y=22:size=18:color=1,1,1:font=DejaVuSans "orders (default)" \
    -o "$tmp/t1.png"
oiiotool "$tmp/hillaire.png" --text:x=8:y=22:size=18:color=1,1,1:font=DejaVuSans "hillaire" -o "$tmp/t2.png"
oiiotool "$tmp/difference.png" --text:x=8:y=22:size=18:color=1,0.3,0.3:font=DejaVuSans \
    "|difference| / orders, white = 20 %" -o "$tmp/t3.png"
oiiotool "$tmp/t1.png" "$tmp/t2.png" "$tmp/t3.png" --mosaic:pad=4 3x1 -o "$out/sunset_models.png"
ls -l "$out"
