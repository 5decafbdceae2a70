#!/usr/bin/env bash
# Installs the Debian 12 packages postfx needs that are not installed yet (apt-get; sudo when not root).
# Usage: scripts/install-deps.sh [build|test]   (test adds what the test suite alone needs)
# openimageio-tools: OpenImageIO's CMake config refuses to load without /usr/bin/iconvert.
# libasan8 libubsan1: the run-time libraries of g++'s -fsanitize=address,undefined (the sanitizer build,
# scripts/run-sanitizer-tests.sh); gcc-12 depends on them already, named here so that the need is visible.
set -euo pipefail
packages=(
    cmake g++ make pkg-config
    libvulkan-dev vulkan-validationlayers mesa-vulkan-drivers glslang-tools
    libglm-dev libglfw3-dev libopenimageio-dev openimageio-tools nlohmann-json3-dev libimgui-dev
)
if [[ "${1:-build}" == test ]]; then
    # clang, libclang-rt-14-dev: the scene loader's fuzz target (libFuzzer's runtime, tests/demo/fuzz);
    # libasan8, libubsan1: gcc's sanitizer runtimes for the sanitizer build (scripts/run-sanitizer-tests.sh).
    packages+=(libgtest-dev clang-format xvfb xauth clang libclang-rt-14-dev libasan8 libubsan1)
fi
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then exit 0; fi
echo "install-deps: installing ${missing[*]}"
sudo=""
if [[ $(id -u) != 0 ]]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
