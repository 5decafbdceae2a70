#!/usr/bin/env bash
# Screenshot test of the windowed demo under Xvfb, without any X11 tool but Xvfb itself:
#   1. postfx-render renders the default scene at 640x360 (20 frames) to reference.png (CPU tonemap);
#   2. Xvfb runs on a free display (-displayfd) with a 640x360x24 screen whose framebuffer is the
#      XWD file DIR/Xvfb_screen0 (-fbdir); with no window manager the window sits at 0,0 and fills it;
#   3. postfx-demo --size 640x360 --frames 20 --no-ui --validation --hold presents 20 frames (GPU
#      tonemap, blit to the swapchain) and keeps the window until its stdin (a fifo) is closed;
#   4. the screen is converted to screenshot.png (repeated until two conversions agree, so that the
#      last present has reached the framebuffer), the demo is released and must exit 0 (no validation
#      message), and compare_png checks screenshot.png against reference.png: mean |diff| < 2 levels per
#      channel and < 1% of pixels off by more than 8 levels (GPU vs CPU float math of the same tonemap
#      on the same half-float radiance; the shader rounds like the CPU), and the screenshot not blank.
# usage: window_screenshot_test.sh POSTFX_DEMO POSTFX_RENDER XWD_TO_PNG COMPARE_PNG OUT_DIR
# Exit 0 pass, 1 fail, 77 skip (Xvfb not installed). screenshot.png, reference.png, diff.png and the
# logs stay in OUT_DIR.
set -u

if [[ $# -ne 5 ]]; then
    echo "usage: $0 POSTFX_DEMO POSTFX_RENDER XWD_TO_PNG COMPARE_PNG OUT_DIR" >&2
    exit 1
fi
demo=$1 render=$2 xwd_to_png=$3 compare_png=$4 out=$5
size=640x360
frames=20

xvfb=$(command -v Xvfb) || {
    echo "SKIP: Xvfb is not installed"
    exit 77
}

mkdir -p "$out" || exit 1
rm -f "$out"/{screenshot,reference,diff}.png "$out"/{demo,xvfb,render}.log
tmp=$(mktemp -d) || exit 1
xvfb_pid=
demo_pid=

cleanup() {
    exec 3>&-  # releases a held demo
    if [[ -n $demo_pid ]] && kill -0 "$demo_pid" 2>/dev/null; then
        kill "$demo_pid" 2>/dev/null
        wait "$demo_pid" 2>/dev/null
    fi
    if [[ -n $xvfb_pid ]]; then
        kill "$xvfb_pid" 2>/dev/null
        wait "$xvfb_pid" 2>/dev/null
    fi
    rm -rf "$tmp"
}
trap cleanup EXIT
trap 'exit 1' INT TERM HUP

fail() {
    echo "FAIL: $*"
    for log in "$out/demo.log" "$out/xvfb.log"; do
        [[ -s $log ]] && { echo "--- $log"; tail -n 30 "$log"; }
    done
    [[ -f $out/screenshot.png ]] && echo "screenshot: $out/screenshot.png"
    [[ -f $out/reference.png ]] && echo "reference:  $out/reference.png"
    [[ -f $out/diff.png ]] && echo "diff (|a-b| x8): $out/diff.png"
    exit 1
}

# 1. The reference, rendered headless with the CPU tonemap.
"$render" -o "$out/reference.png" --size "$size" --frames "$frames" >"$out/render.log" 2>&1 ||
    fail "postfx-render failed: $(cat "$out/render.log")"

# 2. Xvfb on a display number it picks itself; it writes the number to fd 4 once it accepts clients.
: >"$tmp/displayfd"
"$xvfb" -displayfd 4 -screen 0 "${size}x24" -fbdir "$tmp" -nolisten tcp 4>"$tmp/displayfd" \
    >"$out/xvfb.log" 2>&1 &
xvfb_pid=$!
for ((i = 0; i < 300; ++i)); do
    [[ $(wc -l <"$tmp/displayfd") -ge 1 ]] && break
    kill -0 "$xvfb_pid" 2>/dev/null || fail "Xvfb exited at start"
    sleep 0.1
done
display=$(head -n 1 "$tmp/displayfd")
[[ $display =~ ^[0-9]+$ ]] || fail "Xvfb did not report its display number within 30 s"
[[ -f $tmp/Xvfb_screen0 ]] || fail "Xvfb wrote no framebuffer file $tmp/Xvfb_screen0"
echo "Xvfb on :$display"

# 3. The demo, held after its last frame until fd 3 (the fifo's write end) is closed.
mkfifo "$tmp/hold" || fail "mkfifo failed"
env -u WAYLAND_DISPLAY DISPLAY=":$display" "$demo" --size "$size" --frames "$frames" --no-ui --validation \
    --hold <"$tmp/hold" >"$out/demo.log" 2>&1 &
demo_pid=$!
exec 3>"$tmp/hold"
for ((i = 0; i < 3000; ++i)); do
    grep -q "holding the window" "$out/demo.log" && break
    if ! kill -0 "$demo_pid" 2>/dev/null; then
        wait "$demo_pid"
        rc=$?
        demo_pid=
        fail "postfx-demo exited with $rc before presenting $frames frames"
    fi
    sleep 0.1
done
grep -q "holding the window" "$out/demo.log" || fail "postfx-demo did not present $frames frames within 300 s"

# 4. The screen, once two conversions 0.2 s apart agree.
stable=0
for ((i = 0; i < 25; ++i)); do
    sleep 0.2
    "$xwd_to_png" "$tmp/Xvfb_screen0" "$tmp/shot.png" >/dev/null || fail "xwd_to_png failed"
    if [[ -f $tmp/prev.png ]] && cmp -s "$tmp/shot.png" "$tmp/prev.png"; then
        stable=1
        break
    fi
    mv "$tmp/shot.png" "$tmp/prev.png"
done
[[ $stable == 1 ]] || fail "the screen kept changing while the demo held its last frame"
cp "$tmp/shot.png" "$out/screenshot.png"

exec 3>&-  # end of the demo's stdin: it exits
wait "$demo_pid"
rc=$?
demo_pid=
[[ $rc == 0 ]] || fail "postfx-demo exited with $rc"
cat "$out/demo.log"

"$compare_png" "$out/screenshot.png" "$out/reference.png" --diff "$out/diff.png" --max-mean 2 --over 8 \
    --max-over-fraction 0.01 || fail "the window differs from postfx-render's image"
echo "PASS"
