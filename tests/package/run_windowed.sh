#!/usr/bin/env bash
# Runs a windowed program (the arguments) on an X server of its own: Xvfb on a display number it picks
# itself (-displayfd, so that tests running at once never race for one), stopped when the program exits.
# usage: run_windowed.sh PROGRAM [ARGS...]
# Exit: the program's; 77 (ctest: skipped) when Xvfb is not installed.
set -u
xvfb=$(command -v Xvfb) || {
    echo "SKIP: Xvfb is not installed (Debian: xvfb)"
    exit 77
}
tmp=$(mktemp -d) || exit 1
"$xvfb" -displayfd 3 -screen 0 640x480x24 -nolisten tcp 3>"$tmp/display" >"$tmp/xvfb.log" 2>&1 &
xvfb_pid=$!
trap 'kill "$xvfb_pid" 2>/dev/null; wait "$xvfb_pid" 2>/dev/null; rm -rf "$tmp"' EXIT
for ((i = 0; i < 300; ++i)); do
    [[ -s $tmp/display ]] && break
    kill -0 "$xvfb_pid" 2>/dev/null || {
        cat "$tmp/xvfb.log"
        echo "FAIL: Xvfb exited at start"
        exit 1
    }
    sleep 0.1
done
display=$(head -n 1 "$tmp/display")
[[ $display =~ ^[0-9]+$ ]] || {
    echo "FAIL: Xvfb reported no display within 30 s"
    exit 1
}
env -u WAYLAND_DISPLAY DISPLAY=":$display" "$@"
