#!/usr/bin/env bash
# The two commands of the README:
#   ./build.sh render [glint flags]   install what is missing, build, render glint.png
#   ./build.sh test                   install what is missing, build, run every test
# Debian packages that are missing are installed with apt-get (through sudo
# when not root). Builds go to build/ (Release) and build-asan/ (sanitizers).
set -euo pipefail
cd "$(dirname "$0")"

PACKAGES=(gcc make cmake pkg-config libembree-dev zlib1g-dev libpng-dev libjpeg62-turbo-dev libyaml-dev libcmocka-dev)

install_missing() {
    local missing=()
    for p in "${PACKAGES[@]}"; do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
    done
    [ ${#missing[@]} -eq 0 ] && return 0
    echo "build.sh: installing ${missing[*]}" >&2
    local sudo=()
    if [ "$(id -u)" -ne 0 ]; then
        command -v sudo >/dev/null || { echo "build.sh: please install as root: apt-get install ${missing[*]}" >&2; exit 1; }
        sudo=(sudo)
    fi
    "${sudo[@]}" apt-get update -qq
    DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq "${missing[@]}" >/dev/null
}

build() { # build DIR [cmake args...]
    local dir=$1; shift
    cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
    cmake --build "$dir" -j "$(nproc)"
}

case "${1:-}" in
render)
    shift
    install_missing
    build build
    ./build/glint -o glint.png "$@"
    ;;
test)
    install_missing
    build build -DGLINT_WERROR=ON
    ctest --test-dir build --output-on-failure -j "$(nproc)"
    build build-asan -DGLINT_WERROR=ON -DGLINT_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo
    ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
        ctest --test-dir build-asan --output-on-failure -j "$(nproc)"
    ;;
*)
    echo "usage: ./build.sh render [glint flags] | ./build.sh test" >&2
    exit 2
    ;;
esac
