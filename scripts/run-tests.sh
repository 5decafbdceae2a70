#!/usr/bin/env bash
# Builds postfx with warnings as errors and runs every test (host-only and GPU tests on lavapipe, under
# the Khronos validation layer). Installs missing Debian packages first. Build folder: build/.
# Then the scene loader under libFuzzer for 30 s on every core (tests/demo/fuzz/run_fuzz.sh), and the
# tests built with AddressSanitizer and UndefinedBehaviorSanitizer, in build-asan/
# (scripts/run-sanitizer-tests.sh: every test but the whole-image comparisons); POSTFX_SKIP_SANITIZERS=1
# skips that part for a quick local run (.ci/run never skips it). Arguments go to both ctest runs
# (e.g. -R Fog). Each step prints its wall-clock and CPU time, and the end sums them up: CI must stay
# under 20 minutes on two cores (docs/reliability.md, "CI time").
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/steps.sh
step "install-deps" scripts/install-deps.sh test
step "check-format" scripts/check-format.sh
jobs=$(nproc)
# Every part on (the demo's command may have turned tests off in the same build folder).
# POSTFX_DEBUG_INFO: the debug information of RelWithDebInfo, -g unless set. .ci/run sets -g1 (line
# tables and functions, enough for a backtrace): nobody runs a debugger on CI, and the machine code is
# the same (GCC's -g options never change it) while compiling takes about a quarter less time.
configure() {
    cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 ${POSTFX_DEBUG_INFO:--g} -DNDEBUG" -DPOSTFX_WERROR=ON \
        -DPOSTFX_BUILD_DEMO=ON -DPOSTFX_BUILD_BENCH=ON -DPOSTFX_BUILD_TESTS=ON >/dev/null
}
step "build: configure" configure
step "build: compile" cmake --build build -j"$jobs"
# Tests that need a Vulkan device run on Mesa's lavapipe unless POSTFX_DEVICE picks another.
# Each test runs once: the tests labelled sanitized (the discovered gtest tests but the whole-image
# comparisons, tests/CMakeLists.txt) run in the sanitizer build below, which checks them for memory
# errors and undefined behaviour too; without it (POSTFX_SKIP_SANITIZERS=1) they run here.
main_skip=(-LE '^sanitized$')
if [[ "${POSTFX_SKIP_SANITIZERS:-}" == 1 ]]; then
    main_skip=()
fi
step "build: tests" ctest --test-dir build --output-on-failure -j"$jobs" "${main_skip[@]}" "$@"
# The scene loader under libFuzzer (docs/scene-format.md, "Fuzzing").
step "fuzz: build and 30 s" tests/demo/fuzz/run_fuzz.sh
if [[ "${POSTFX_SKIP_SANITIZERS:-}" == 1 ]]; then
    echo "run-tests: POSTFX_SKIP_SANITIZERS=1, the sanitizer build is skipped"
else
    step "sanitizers: build and tests" scripts/run-sanitizer-tests.sh "$@"
fi
steps_summary "run-tests"
