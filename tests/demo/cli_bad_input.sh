#!/bin/sh
# postfx-render on bad input (docs/stability.md, "Bad parameters"): each must end with a non-zero exit
# status below 128 (no crash, no abort) and exactly one line on stderr that names the problem.
# usage: cli_bad_input.sh POSTFX_RENDER SCENE_DIR
set -u
render=$1
scenes=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
failures=0

# check NAME EXPECTED_TEXT ARGS...: runs postfx-render ARGS and checks the outcome.
check() {
    name=$1
    expected=$2
    shift 2
    "$render" "$@" >"$dir/out" 2>"$dir/err"
    status=$?
    lines=$(grep -c '' "$dir/err")
    if [ "$status" -eq 0 ] || [ "$status" -ge 128 ]; then
        echo "FAIL $name: exit status $status (expected 1..127)"
        failures=$((failures + 1))
    elif ! grep -q -- "$expected" "$dir/err"; then
        echo "FAIL $name: stderr does not name '$expected':"
        cat "$dir/err"
        failures=$((failures + 1))
    elif [ "$(head -n 1 "$dir/err" | grep -c -- "$expected")" -ne 1 ]; then
        echo "FAIL $name: the first line of stderr does not name '$expected':"
        cat "$dir/err"
        failures=$((failures + 1))
    else
        echo "ok   $name (status $status): $(head -n 1 "$dir/err")"
    fi
    # One line of error, then possibly the usage text for command-line mistakes.
    case "$expected" in
    --*) ;;
    *) if [ "$lines" -ne 1 ]; then
        echo "FAIL $name: $lines lines on stderr, expected 1"
        failures=$((failures + 1))
    fi ;;
    esac
}

# A copy of fog_default.json with one value of effects.fog replaced (sed on the file's own text).
bad_scene() {
    sed "$2" "$scenes/fog_default.json" >"$dir/$1.json"
    echo "$dir/$1.json"
}

check negative-density "effects.fog.density" "$(bad_scene density 's/"density": *[0-9.e-]*/"density": -1/')" -o "$dir/x.png" --size 8x8
check anisotropy-above-one "effects.fog.anisotropy" "$(bad_scene g 's/"anisotropy": *[0-9.e-]*/"anisotropy": 1.5/')" -o "$dir/x.png" --size 8x8
check infinite-density "effects.fog.density" "$(bad_scene inf 's/"density": *[0-9.e-]*/"density": 1e999/')" -o "$dir/x.png" --size 8x8
check steps-zero "effects.fog.steps" "$(bad_scene steps 's/"steps": *[0-9]*/"steps": 0/')" -o "$dir/x.png" --size 8x8
check resolution-scale "effects.fog.resolution_scale" "$(bad_scene scale 's/"steps": 48/"steps": 48, "resolution_scale": 0.1/')" -o "$dir/x.png" --size 8x8
check missing-scene "nope.json" "$dir/nope.json" -o "$dir/x.png" --size 8x8
printf '{ "camera": ' >"$dir/broken.json"
check malformed-json "broken.json" "$dir/broken.json" -o "$dir/x.png" --size 8x8
check zero-size "--size" "$scenes/fog_default.json" -o "$dir/x.png" --size 0x8
# Scene values past the loader's limits (docs/scene-format.md, "Limits"): one line naming the key, not
# a record-time failure of postfx.
check illuminance-above-postfx-bound "sun.illuminance\[0\]: expected a number in \[0, 1e7\]" \
    "$(bad_scene sun 's/"illuminance": *\[[^]]*\]/"illuminance": [2e7, 2e7, 2e7]/')" -o "$dir/x.png" --size 8x8
check ev100-overflows-exposure "camera.ev100: expected a number in \[-30, 30\]" \
    "$(bad_scene ev 's/"ev100": *[0-9.e-]*/"ev100": -3e38/')" -o "$dir/x.png" --size 8x8
# --reference=path and --path-samples (docs/effects/clouds.md, "Path-traced truth").
check path-samples-without-path "--path-samples needs --reference=path" "$scenes/clouds_noon.json" -o "$dir/x.exr" \
    --size 8x8 --reference --path-samples 8
check path-samples-one "--path-samples '1'" "$scenes/clouds_noon.json" -o "$dir/x.exr" --size 8x8 \
    --reference=path --path-samples 1
check reference-unknown-mode "--reference=march" "$scenes/clouds_noon.json" -o "$dir/x.exr" --size 8x8 \
    --reference=march
# An image over the memory budget is refused before anything is allocated: at once.
start=$(date +%s)
check size-over-memory-budget "--size 16384x16384: needs about 32 GiB" "$scenes/fog_default.json" -o "$dir/x.png" \
    --size 16384x16384
if [ $(($(date +%s) - start)) -gt 10 ]; then
    echo "FAIL size-over-memory-budget: took more than 10 s"
    failures=$((failures + 1))
fi

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
