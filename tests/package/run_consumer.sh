#!/usr/bin/env bash
# Builds tests/package/consumer/ as a project of its own against postfx, one way, and runs what it built
# (the integration guide's program records fog on the Vulkan device, under the validation layer, and
# checks a pixel against the closed form; so does the tutorial-style host, in a window on Xvfb).
#   run_consumer.sh package      SOURCE BUILD WORK  install BUILD into WORK/prefix, find_package it, and
#                                                   compile version_check.cpp through pkg-config too
#   run_consumer.sh subdirectory SOURCE BUILD WORK  add_subdirectory(SOURCE) as a shared library, and
#                                                   that build installed: it exports postfx's API only,
#                                                   a second consumer finds it with find_package
#   run_consumer.sh fetchcontent SOURCE BUILD WORK  FetchContent (configure only: options, cache, targets)
set -euo pipefail
mode=$1 source=$2 build=$3 work=$4
jobs=$(nproc)
consumer=$source/tests/package/consumer
rm -rf "$work"
mkdir -p "$work"
configure_consumer() {  # extra -D arguments
    cmake -S "$consumer" -B "$work/consumer" -DPOSTFX_EXAMPLES_DIR="$source/examples" "$@" >"$work/configure.log" 2>&1 ||
        { cat "$work/configure.log"; exit 1; }
}
build_and_run() {
    cmake --build "$work/consumer" -j"$jobs" >"$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
    "$work/consumer/version_check"
    "$work/consumer/minimal_host/postfx_minimal_host" --validate
    # Built where GLFW is installed; run where Xvfb is (77: it is not).
    local tutorial=$work/consumer/tutorial_host/postfx_tutorial_host rc=0
    if [[ -x $tutorial ]]; then
        bash "$source/tests/package/run_windowed.sh" "$tutorial" --frames 3 --validate --check || rc=$?
        [[ $rc == 0 || $rc == 77 ]] || exit "$rc"
    fi
}
case $mode in
package)
    cmake --install "$build" --prefix "$work/prefix" >/dev/null
    configure_consumer -DPOSTFX_CONSUME=package -DCMAKE_PREFIX_PATH="$work/prefix"
    build_and_run
    # pkg-config: the flags it gives build a program that links.
    flags=$(PKG_CONFIG_PATH="$work/prefix/lib/pkgconfig" pkg-config --cflags --libs --static postfx)
    # shellcheck disable=SC2086
    c++ -std=c++20 "$consumer/version_check.cpp" -o "$work/version_check_pkgconfig" $flags
    "$work/version_check_pkgconfig"
    ;;
subdirectory)
    # One build of the library serves two ways of consuming it (CI time): the consumer builds postfx as
    # its subdirectory, shared (BUILD_SHARED_LIBS) and installable (POSTFX_INSTALL), and runs what it built
    # against it; then the installed shared library must export postfx's API only, and a second consumer
    # finds it with find_package and runs.
    configure_consumer -DPOSTFX_CONSUME=subdirectory -DPOSTFX_SOURCE_DIR="$source" -DBUILD_SHARED_LIBS=ON \
        -DPOSTFX_INSTALL=ON -DCMAKE_BUILD_TYPE=Release
    build_and_run
    cmake --install "$work/consumer" --prefix "$work/prefix" >/dev/null
    so=$(ls "$work"/prefix/lib/libpostfx.so.* | head -n1)
    # Exported: postfx's API (namespace postfx, not its internal namespaces) and the C++ runtime's
    # template instantiations the API uses; no internal symbol.
    exported=$(nm -D -C --defined-only "$so" | awk '{ $1 = ""; $2 = ""; print substr($0, 3) }')
    internal=$(printf '%s\n' "$exported" | grep -E 'postfx::(core|fog|spirv|detail|reference::detail)::|ContextAccess' || true)
    if [ -n "$internal" ]; then
        echo "libpostfx.so exports internal symbols:"
        printf '%s\n' "$internal" | head -n 20
        exit 1
    fi
    for api in 'postfx::Context::create' 'postfx::Context::record' 'postfx::validateFogSettings' \
        'postfx::version()' 'postfx::reference::renderFog'; do
        printf '%s\n' "$exported" | grep -qF "$api" || { echo "libpostfx.so does not export $api"; exit 1; }
    done
    echo "libpostfx.so exports $(printf '%s\n' "$exported" | grep -c 'postfx::') postfx symbols, no internal one"
    rm -rf "$work/consumer"
    configure_consumer -DPOSTFX_CONSUME=package -DCMAKE_PREFIX_PATH="$work/prefix"
    build_and_run
    ;;
fetchcontent)
    configure_consumer -DPOSTFX_CONSUME=fetchcontent -DFETCHCONTENT_SOURCE_DIR_POSTFX="$source"
    echo "configured: postfx through FetchContent builds the library alone"
    ;;
*)
    echo "unknown mode $mode"
    exit 2
    ;;
esac
