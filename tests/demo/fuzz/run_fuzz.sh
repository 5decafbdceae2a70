#!/usr/bin/env bash
# Fuzzes the demo's scene loader (fuzz_scene_loader.cpp, libFuzzer with AddressSanitizer and
# UndefinedBehaviorSanitizer) for SECONDS on every core, after building it with clang in BUILD_DIR.
# usage: tests/demo/fuzz/run_fuzz.sh [SECONDS] [BUILD_DIR]      (default 30 s, build-fuzz/)
#   CI (scripts/run-tests.sh) runs the default; a long run: tests/demo/fuzz/run_fuzz.sh 3600
# Workers: one per core (nproc; POSTFX_FUZZ_WORKERS=N to choose), libFuzzer's -jobs=N -workers=N: N
# fuzzers of SECONDS each that share the corpus (each one reads what the others add): on CI's two cores,
# 30 s of two workers run about as many inputs as 60 s of one.
# Seeds: the committed scenes (demo/scenes, tests/fog/stability/scenes) and the regression inputs
# (tests/demo/fuzz/regressions); the grown corpus is kept in BUILD_DIR/fuzz-corpus between runs. Any
# sanitizer report, crash or oracle failure (a scene that loads but would not render, an error that is not
# one line naming a key path) stops that worker with its input in BUILD_DIR/fuzz-crashes/ and fails the
# script: add that input to tests/demo/fuzz/regressions/ (README.md there) when fixing it.
set -euo pipefail
seconds=${1:-30}
root=$(cd "$(dirname "$0")/../../.." && pwd)
build=$(mkdir -p "${2:-$root/build-fuzz}" && cd "${2:-$root/build-fuzz}" && pwd)
here=$root/tests/demo/fuzz
workers=${POSTFX_FUZZ_WORKERS:-$(nproc)}

CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPOSTFX_WERROR=ON \
    -DPOSTFX_BUILD_DEMO=ON -DPOSTFX_BUILD_BENCH=OFF -DPOSTFX_BUILD_TESTS=OFF -DPOSTFX_BUILD_EXAMPLES=OFF \
    -DPOSTFX_INSTALL=OFF -DPOSTFX_BUILD_FUZZERS=ON >/dev/null
cmake --build "$build" -j"$(nproc)" --target fuzz_scene_loader

mkdir -p "$build/fuzz-corpus" "$build/fuzz-crashes"
export ASAN_OPTIONS=halt_on_error=1:detect_leaks=1:abort_on_error=0
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
# -max_len: a few KB reach every key; larger inputs only slow the run. -timeout, -rss_limit_mb: a slow
# or huge input is a finding too. Worker I logs to BUILD_DIR/fuzz-I.log (libFuzzer names them in its
# working directory); the parent copies each into BUILD_DIR/fuzz.log when the worker ends.
log=$build/fuzz.log
rm -f "$build"/fuzz-[0-9]*.log
set +e
(cd "$build" && "$build/tests/demo/fuzz/fuzz_scene_loader" -jobs="$workers" -workers="$workers" \
    -max_total_time="$seconds" -dict="$here/scene.dict" -max_len=8192 -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$build/fuzz-crashes/" \
    "$build/fuzz-corpus" "$root/demo/scenes" "$root/tests/fog/stability/scenes" "$here/regressions") \
    >"$log" 2>&1
status=$?
set -e
# The progress lines (NEW, REDUCE, RELOAD, pulse, new functions) stay in the logs; each worker's start,
# report and stats are shown (the parent's log when no worker started).
shopt -s nullglob
worker_logs=("$build"/fuzz-[0-9]*.log)
for worker_log in "${worker_logs[@]:-$log}"; do
    echo "run_fuzz: ${worker_log#"$build"/}"
    grep -v -E '^#[0-9]+[[:space:]]+(NEW|REDUCE|RELOAD|pulse|INITED)|NEW_FUNC|# Uses: |recommended dict' \
        "$worker_log" | tail -n 30 || true
done
runs=$(cat "${worker_logs[@]:-$log}" | sed -n 's/^stat::number_of_executed_units: *//p' |
    awk '{ s += $1 } END { print s + 0 }')
if [[ $status -ne 0 ]]; then
    echo "run_fuzz: fuzz_scene_loader failed (status $status); the input is in $build/fuzz-crashes/" >&2
    exit 1
fi
echo "run_fuzz: no finding in $seconds s on $workers workers, $runs inputs ($log)"
