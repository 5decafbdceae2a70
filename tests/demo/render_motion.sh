#!/bin/sh
# postfx-render --frames N on a moving scene (docs/scene-format.md#motion): the last of N frames differs
# from the same scene standing still (the camera walked and turned; PNG, whose files hold no time stamp);
# --reference renders the last frame's reference; --reference=path path-traces a cloud scene's clouds and
# writes their standard error beside the output; --print-plan runs. 32x18 pixels (16x9 path-traced). That each frame is
# exactly its state is DemoRendererMotion's (gpu_tests).
# usage: render_motion.sh POSTFX_RENDER SCENE_DIR
set -u
render=$1
scenes=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
failures=0

fail() {
    echo "FAIL $1"
    failures=$((failures + 1))
}

# run NAME ARGS...: postfx-render ARGS must succeed; its stdout is left in $dir/NAME.out.
run() {
    name=$1
    shift
    if "$render" "$@" >"$dir/$name.out" 2>"$dir/$name.err"; then
        echo "ok   $name: $(tail -n 1 "$dir/$name.out")"
    else
        fail "$name: exit status $?"
        cat "$dir/$name.err"
    fi
}

moving="$scenes/fog_walk.json"
# The same scene standing still: velocity and yaw rate 0.
sed -e 's/"velocity": \[[^]]*\]/"velocity": [0, 0, 0]/' -e 's/"yaw_rate": [0-9.e-]*/"yaw_rate": 0/' \
    "$moving" >"$dir/still.json"
grep -q '"yaw_rate": 0' "$dir/still.json" || fail "still.json: the sed did not stop the camera"

size="--size 32x18"
run moving-6 "$moving" $size --frames 6 --validation -o "$dir/moving-6.png"
run still-6 "$dir/still.json" $size --frames 6 -o "$dir/still-6.png"
grep -q "6 frames" "$dir/moving-6.out" || fail "moving-6: stdout does not say 6 frames"
cmp -s "$dir/moving-6.png" "$dir/still-6.png" && fail "frame 5 of the moving scene equals the still scene's"

run reference "$moving" $size --frames 6 --reference --reference-steps 8 -o "$dir/reference.png"
grep -q "frame 5 with the CPU references" "$dir/reference.out" || fail "reference: not of frame 5"

run path "$scenes/clouds_noon.json" --size 16x9 --reference=path --reference-steps 8 --path-samples 2 \
    -o "$dir/path.exr"
grep -q "2 paths/pixel, mean relative standard error" "$dir/path.out" || fail "path: no standard error printed"
[ -s "$dir/path.stderr.exr" ] || fail "path: no path.stderr.exr beside the output"

run plan "$moving" $size --frames 2 --print-plan
grep -q '"passes"' "$dir/plan.out" || fail "plan: no passes printed"

if [ "$failures" -ne 0 ]; then
    echo "$failures failure(s)"
    exit 1
fi
echo "all passed"
