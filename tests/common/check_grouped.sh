#!/bin/sh
# Fails when the test executable $1 holds a test that the filter $2 (the negation of every group's suite
# patterns, tests/CMakeLists.txt) still lists: a suite whose name starts with no group's name, so ctest
# labels its tests "ungrouped" instead of with their group.
set -eu
list=$("$1" --gtest_list_tests --gtest_filter="$2")
if printf '%s\n' "$list" | grep -q '^  '; then
    echo "suites of no group in $1 (name them after their group, tests/CMakeLists.txt):"
    printf '%s\n' "$list" | grep -v '^  ' | grep -v '^Running main'
    exit 1
fi
echo "every suite in $1 belongs to a group"
