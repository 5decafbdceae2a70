#!/usr/bin/env bash
# Checks that the tests labelled image_comparison (tests/CMakeLists.txt, postfx_image_comparison_tests),
# which the sanitizer build skips (scripts/run-sanitizer-tests.sh), run no line of postfx's or the demo's
# code that the sanitizer build's other tests leave unrun. A coverage build (build-cov/: gcc --coverage
# at -O1, the sanitizer build's targets) runs both sets of tests, each into a gcov tree of its own, and
# the lines of postfx/ and demo/ that only the image comparisons ran are listed; any fails the check.
# Not part of CI (about 15 minutes on two cores): run it after marking a test (docs/reliability.md,
# "Sanitizers"). Output: build-cov/gcov/{kept,images}.lines, file:line of every line each set ran.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
jobs=$(nproc)
cmake -S . -B build-cov -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-O1 -DCMAKE_CXX_FLAGS=--coverage \
    -DCMAKE_EXE_LINKER_FLAGS=--coverage -DPOSTFX_BUILD_DEMO=ON -DPOSTFX_BUILD_BENCH=OFF -DPOSTFX_BUILD_TESTS=ON \
    -DPOSTFX_BUILD_EXAMPLES=OFF >/dev/null
cmake --build build-cov -j"$jobs" --target postfx unit_tests gpu_tests stability_tests glm_config_tests \
    postfx-render
out=build-cov/gcov
rm -rf "$out"
mkdir -p "$out"
# The sanitizer build's tests (not the window's, not the package consumers': the sanitizer build has
# neither), without and with the image comparisons.
not_sanitized='^(demo_window_screenshot|package_consumer_.*)$'
echo "check-image-comparisons: the tests that the sanitizer build runs ($out/kept.log)"
GCOV_PREFIX=$root/$out/kept ctest --test-dir build-cov -j"$jobs" -E "$not_sanitized" -LE '^image_comparison$' \
    >"$out/kept.log"
echo "check-image-comparisons: the image comparisons ($out/images.log)"
GCOV_PREFIX=$root/$out/images ctest --test-dir build-cov -j"$jobs" -L '^image_comparison$' >"$out/images.log"

# covered TREE: file:line of each line of postfx/ and demo/ that ran, from the counts under TREE (each
# .gcda at TREE/<the object's absolute path>; its .gcno is copied from beside the object).
covered() {
    find "$1" -name '*.gcda' | while read -r gcda; do
        object=${gcda#"$1"}
        cp "${object%.gcda}.gcno" "${gcda%.gcda}.gcno"
        (cd "$(dirname "$gcda")" && gcov -t "$(basename "$gcda")" 2>/dev/null)
    done | awk -v root="$root/" '
        /^ *-: *0:Source:/ {
            file = substr($0, index($0, "Source:") + 7)
            keep = index(file, root "postfx/") == 1 || index(file, root "demo/") == 1
            next
        }
        keep && /^ *[0-9]+\*?: *[0-9]+:/ {  # a count (not -, ##### or =====): the line ran
            split($0, field, ":")
            print substr(file, length(root) + 1) ":" field[2] + 0
        }' | sort -u
}
covered "$out/kept" >"$out/kept.lines"
covered "$out/images" >"$out/images.lines"
only=$(comm -13 "$out/kept.lines" "$out/images.lines")
echo "check-image-comparisons: the sanitizer build's tests run $(wc -l <"$out/kept.lines") lines of postfx/ and" \
    "demo/, the image comparisons $(wc -l <"$out/images.lines")"
if [[ -n $only ]]; then
    echo "check-image-comparisons: lines that only image comparisons run (unmark the cheapest test that runs them):"
    printf '%s\n' "$only"
    exit 1
fi
echo "check-image-comparisons: none that only image comparisons run"
