#!/usr/bin/env bash
# The sanitizer part of the tests (scripts/run-tests.sh runs it after the main build): postfx, the demo
# host and the tests built with AddressSanitizer (LeakSanitizer included) and UndefinedBehaviorSanitizer
# in build-asan/, then the host-only tests and the GPU tests on lavapipe under the validation layer,
# but for the whole-image comparisons (label image_comparison, below).
# Any report ends the process that raised it with a non-zero status, so it fails its test (and CI).
# Driver-internal leaks are suppressed by tests/sanitizers/lsan.supp (its comment says which and why).
# Usage: scripts/run-sanitizer-tests.sh [ctest arguments, e.g. -R Core]
#        POSTFX_SANITIZE_ALL_TESTS=1 scripts/run-sanitizer-tests.sh   (the image comparisons too)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/steps.sh
jobs=$(nproc)
# -O1: a sanitized -O0 build makes the CPU fog references several times slower; -O1 keeps the stack
# traces exact. -g1: line tables and functions, inlined ones included, which is all that a sanitizer's
# stack trace shows (the same frames, files and lines as -g); it compiles about a third faster than -g,
# which also describes types and variables for a debugger.
# No benchmark (it tests postfx-bench's report, not memory; its GPU code is postfx's), no
# examples and no windowed demo: the three test programs, postfx-render (its command line on bad input)
# and the library are built, so that CI stays under 20 minutes; the window's screenshot test runs in the
# main build.
configure() {
    cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" \
        -DPOSTFX_SANITIZE=address,undefined -DPOSTFX_WERROR=ON -DPOSTFX_BUILD_DEMO=ON \
        -DPOSTFX_BUILD_BENCH=OFF -DPOSTFX_BUILD_TESTS=ON -DPOSTFX_BUILD_EXAMPLES=OFF >/dev/null
}
step "sanitizers: configure" configure
step "sanitizers: compile" cmake --build build-asan -j"$jobs" --target postfx unit_tests gpu_tests \
    stability_tests glm_config_tests postfx-render
# halt_on_error: the first report ends the process (the build adds -fno-sanitize-recover=all, which
# UBSan also needs at run time); detect_leaks: LeakSanitizer at exit, with the drivers' leaks suppressed.
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:abort_on_error=0:exitcode=23"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0"
# Not run here: the tests labelled image_comparison (`ctest --test-dir build-asan -N -L image_comparison`
# lists them; tests/CMakeLists.txt, postfx_image_comparison_tests): a whole scene on the device against
# the CPU reference, a closed form or a golden image. Sanitizers find memory errors and undefined
# behaviour in the C++, not wrong pixels, and the tests that do run here (unit, API, range,
# fault-injection, leak, lifecycle, stability) run every line of host code that these run
# (scripts/check-image-comparisons.sh checks it; docs/reliability.md, "Sanitizers"); they took a quarter
# of the sanitized test time. The main build runs every one of them.
skip=(-LE '^image_comparison$')
if [[ "${POSTFX_SANITIZE_ALL_TESTS:-}" == 1 ]]; then
    skip=()
fi
step "sanitizers: tests" ctest --test-dir build-asan --output-on-failure -j"$jobs" \
    -E '^demo_window_screenshot$' "${skip[@]}" "$@"
steps_summary "run-sanitizer-tests"
