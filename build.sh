#!/usr/bin/env bash
# The two commands of the README:
#   ./build.sh render [glint flags]   install what is missing, build, render glint.png
#   ./build.sh test                   install what is missing, build, run every test
# Debian packages that are missing are installed with apt-get (through sudo
# when not root). Builds go to build/ (Release, optimised from a profile of
# training renders by cmake/pgo-build.sh), build-asan/ (the tests again
# under ASan and UBSan) and build-fuzz/ (libFuzzer targets for the scene
# loader, the model importer, the texture decoder and the command line's
# flags, each run for GLINT_FUZZ_SECONDS, default 60).
set -euo pipefail
cd "$(dirname "$0")"

PACKAGES=(gcc make cmake pkg-config libembree-dev zlib1g-dev libpng-dev libjpeg62-turbo-dev libyaml-dev libassimp-dev
          libopenexr-dev libcmocka-dev clang libclang-rt-14-dev openexr openmpi-bin libopenmpi-dev
          libsdl2-dev libx11-dev xvfb xdotool imagemagick povray)

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

# render_seeds DIR: fuzz_render's seeds, made in DIR from the NFF and YAML
# seeds, each behind the byte that picks its reader (tests/fuzz/fuzz_render.c):
# 'n' (even) for NFF, 'y' (odd) for YAML; and its dictionary, both readers'.
render_seeds() {
    local dir=$1 f
    mkdir -p "$dir/corpus"
    for f in tests/fuzz/corpus/nff/*; do
        { printf n; cat "$f"; } >"$dir/corpus/n-${f##*/}"
    done
    for f in tests/fuzz/corpus/scene/*; do
        if [ -f "$f" ]; then
            { printf y; cat "$f"; } >"$dir/corpus/y-${f##*/}"
        else
            cp -R "$f" "$dir/corpus/" # what the seeds include, by name
        fi
    done
    cat tests/fuzz/nff.dict tests/fuzz/scene.dict >"$dir/render.dict"
}

# fuzz NAME MAX_LEN [FLAGS...]: runs build-fuzz/fuzz_NAME for GLINT_FUZZ_SECONDS
# on copies of tests/fuzz/corpus/NAME (render_seeds' for render) and
# tests/fuzz/regressions/NAME, from inside the corpus copy (so relative
# includes find seeds), with tests/fuzz/NAME.dict, when present the
# LeakSanitizer suppressions tests/fuzz/NAME.supp, and any further libFuzzer
# FLAGS. A failing input is left in build-fuzz/artifacts-NAME/, the log in
# build-fuzz/fuzz-NAME.log.
fuzz() {
    local name=$1 max_len=$2 top=$PWD
    shift 2
    local dir=build-fuzz/run-$name dict=$PWD/tests/fuzz/$name.dict
    rm -rf "$dir" "build-fuzz/artifacts-$name"
    mkdir -p "$dir/regressions" "build-fuzz/artifacts-$name"
    if [ "$name" = render ]; then
        render_seeds "$dir"
        dict=$PWD/$dir/render.dict
    else
        cp -R "tests/fuzz/corpus/$name" "$dir/corpus"
    fi
    [ ! -d "tests/fuzz/regressions/$name" ] || cp -R "tests/fuzz/regressions/$name/." "$dir/regressions/"
    local lsan=""
    [ ! -f "tests/fuzz/$name.supp" ] || lsan="suppressions=$top/tests/fuzz/$name.supp"
    if ! (cd "$dir/corpus" && LSAN_OPTIONS="$lsan" UBSAN_OPTIONS=print_stacktrace=1 \
            "$top/build-fuzz/fuzz_$name" -max_total_time="${GLINT_FUZZ_SECONDS:-60}" -max_len="$max_len" \
            -rss_limit_mb=2048 -timeout=10 -dict="$dict" \
            -artifact_prefix="$top/build-fuzz/artifacts-$name/" -print_final_stats=1 "$@" . ../regressions) \
            >"build-fuzz/fuzz-$name.log" 2>&1; then
        tail -n 60 "build-fuzz/fuzz-$name.log"
        echo "fuzz $name: FAILED; input in build-fuzz/artifacts-$name/, log in build-fuzz/fuzz-$name.log" >&2
        exit 1
    fi
    echo "fuzz $name: $(sed -n 's/^Done \([0-9]*\) runs in \([0-9]*\).*/\1 runs in \2 s/p' "build-fuzz/fuzz-$name.log")," \
        "$(sed -n 's/^stat::average_exec_per_sec: *//p' "build-fuzz/fuzz-$name.log") exec/s, no crash"
}

# same_images A B: glint programs A and B (one optimised for this processor
# from a profile, one a generic sanitizer build at -O2) render the default
# scene and every example scene to the same bytes: no optimisation or vector
# width changes an image. A scene both refuse alike (a model missing with
# the shared data folder) is skipped.
same_images() {
    local a=$1 b=$2 out=build/same-images scenes=("") n=0
    mkdir -p "$out"
    for f in scenes/*.yaml scenes/models/*.yaml; do
        scenes+=("$f")
    done
    for f in "${scenes[@]}"; do
        local args=(-w 160 -h 120 --threads 2 --quiet --frame 12) # an animated scene's frame 12; a still's only
        [ -z "$f" ] || args=("$f" "${args[@]}")
        local sa=0 sb=0
        "$a" "${args[@]}" -o "$out/a.ppm" 2>/dev/null || sa=$?
        "$b" "${args[@]}" -o "$out/b.ppm" 2>/dev/null || sb=$?
        if [ "$sa" -ne "$sb" ]; then
            echo "same images: ${f:-the default scene} exits $sa with $a, $sb with $b" >&2
            exit 1
        fi
        [ "$sa" -eq 0 ] || continue
        if ! cmp -s "$out/a.ppm" "$out/b.ppm"; then
            echo "same images: ${f:-the default scene} renders differently with $a and $b" >&2
            exit 1
        fi
        n=$((n + 1))
    done
    echo "same images: $n scenes render the same bytes with $a and $b"
}

case "${1:-}" in
render)
    shift
    install_missing
    PGO_TARGETS="glint glint-mpi" cmake/pgo-build.sh build -DGLINT_MPI=ON
    ./build/glint -o glint.png "$@"
    ;;
test)
    install_missing
    # The same profile-guided build as render, so the tests check what users run.
    cmake/pgo-build.sh build -DGLINT_WERROR=ON -DGLINT_MPI=ON
    ctest --test-dir build --output-on-failure -j "$(nproc)"
    build build-asan -DGLINT_WERROR=ON -DGLINT_MPI=ON -DGLINT_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo
    ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
        ctest --test-dir build-asan --output-on-failure -j "$(nproc)"
    same_images build/glint build-asan/glint
    # Fuzz the scene loader, the model importer, the texture decoder, the
    # flags and the render of what the scene readers accept for a bounded
    # time each (tests/fuzz/README.md); a crash, leak or
    # timeout fails the test. The flags' parser prints as glint does: its
    # stdout and stderr are closed (libFuzzer's own messages still show).
    CC=clang build build-fuzz -DGLINT_WERROR=ON -DGLINT_FUZZ=ON -DGLINT_MPI=OFF -DGLINT_BUILD_TESTS=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo
    fuzz scene 8192
    fuzz nff 8192
    fuzz mesh 16384
    fuzz texture 16384
    fuzz cli 4096 -close_fd_mask=3
    fuzz render 8192
    ;;
*)
    echo "usage: ./build.sh render [glint flags] | ./build.sh test" >&2
    exit 2
    ;;
esac
