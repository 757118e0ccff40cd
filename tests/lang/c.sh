#!/usr/bin/env bash
# Build, test and run the generated C packages (generated/c/<package>/ -> build/c/<package>/).
#   tests/lang/c.sh build                         configure and build every package
#   tests/lang/c.sh test                          the runtime's own tests in place, then build every
#                                                 package and run its googletest binary
#   tests/lang/c.sh runtime                       the runtime's own tests only, against the test protocol
#                                                 rendered from tests/runtime_specs/ (both framings)
#   tests/lang/c.sh decode FILE|- [--device ID]   run <package>-decode (builds first if needed)
#   tests/lang/c.sh encode                        run <package>-encode: JSON lines on stdin -> bytes
#   tests/lang/c.sh example FILE                  run <package>-getting-started FILE (builds first if needed)
#   tests/lang/c.sh session --connect ADDRESS ...  run <package>-session (docs/conformance.md section 8)
#   tests/lang/c.sh configure ADDRESS [COUNT]     run <package>-configure-and-stream (examples/configure_and_stream.c,
#                                                 built with the package's posix module when missing or out of date)
#   tests/lang/c.sh app NAME [ARGS...]            build tests/apps/c/NAME.c against the package (tests/apps/c/CMakeLists.txt,
#                                                 build/c-apps/) and run it with ARGS (tests/apps/README.md)
# decode/encode/example/configure use the package $C_PACKAGE (default: mipcodec). Works from any directory; build
# output goes to stderr so that decode/encode keep stdout clean.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
PACKAGE="${C_PACKAGE:-mipcodec}"
# shellcheck source=tests/lang/lock.sh
. "$ROOT/tests/lang/lock.sh"

packages() {
    local d
    for d in "$ROOT"/generated/c/*/; do
        if [ -f "$d/CMakeLists.txt" ]; then basename "$d"; fi
    done
}

# The package's <PKG>_WERROR option (OFF for consumers), ON in the project's own builds.
werror() {
    echo "$(tr '[:lower:]' '[:upper:]' <<<"$1")_WERROR=ON"
}

# The package's tests, tools and examples: OFF unless asked for (docs/packaging.md); the project's
# own builds ask. asked PACKAGE WHAT... prints -D<PKG>_BUILD_<WHAT>=ON, one per line.
asked() {
    local P w
    P="$(tr '[:lower:]' '[:upper:]' <<<"$1")"
    shift
    for w in "$@"; do echo "-D${P}_BUILD_${w}=ON"; done
}

build_one() {
    local src="$ROOT/generated/c/$1" out="$ROOT/build/c/$1"
    if [ ! -f "$out/build.ninja" ]; then
        # shellcheck disable=SC2046 # one argument per line of asked
        cmake -G Ninja -S "$src" -B "$out" -DCMAKE_BUILD_TYPE=Debug -D"$(werror "$1")" $(asked "$1" TESTS TOOLS EXAMPLES) >&2
    fi
    cmake --build "$out" >&2
}

ensure_built() {
    local out="$ROOT/build/c/$PACKAGE"
    if [ -x "$out/$PACKAGE-decode" ] && [ -x "$out/$PACKAGE-encode" ] &&
        cmake --build "$out" --target "${PACKAGE}_c_decode" "${PACKAGE}_c_encode" >/dev/null 2>&1; then
        return
    fi
    build_one "$PACKAGE"
}

# The runtime's own tests (generator/targets/c/runtime/tests/; no regeneration of generated/):
# its formatting checked, then for each framing of the test protocol rendered by the C back end
# from tests/runtime_specs/ (docs/runtime-contract.md) into build/runtime_specs/<framing>/c/
# testproto/, the tests copied beside it with the package's names and one googletest binary built
# against that package (build dir build/c-runtime/<framing>/). No hand-written stand-ins.
runtime_tests() {
    local runtime="$ROOT/generator/targets/c/runtime" framing out tests build
    local format="${CLANG_FORMAT:-$ROOT/.venv/bin/clang-format}" py="$ROOT/.venv/bin/python"
    [ -x "$py" ] || py="$(command -v python3)"
    find "$runtime" -name '*.[ch]' -o -name '*.[ch]pp' | sort |
        xargs "$format" --style="file:$ROOT/.clang-format" --dry-run -Werror
    for framing in a b; do
        out="$(cd "$ROOT" && "$py" -m tests.runtime_specs.render --tests c "$framing")"
        tests="$out/tests-c"
        build="$ROOT/build/c-runtime/$framing"
        if [ ! -f "$build/build.ninja" ]; then
            cmake -G Ninja -S "$tests" -B "$build" -DCMAKE_BUILD_TYPE=Debug -DPACKAGE_DIR="$out/c/testproto" >&2
        fi
        cmake --build "$build" >&2
        echo "== runtime, framing $framing" >&2
        "$build/runtime_tests" --gtest_brief=1
    done
}

# The same tests built with AddressSanitizer and UndefinedBehaviorSanitizer (any report fails),
# then the sanitized decoder over a stream of random bytes mixed with the library's own packets.
sanitized() {
    local src="$ROOT/generated/c/$1" out="$ROOT/build/c-sanitize/$1"
    local san="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
    if [ ! -f "$out/build.ninja" ]; then
        # shellcheck disable=SC2046 # one argument per line of asked
        cmake -G Ninja -S "$src" -B "$out" -DCMAKE_BUILD_TYPE=Debug -D"$(werror "$1")" $(asked "$1" TESTS TOOLS) -DCMAKE_C_FLAGS="$san" \
            -DCMAKE_CXX_FLAGS="$san" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >&2
    fi
    cmake --build "$out" >&2
    "$out/$1-tests" --gtest_brief=1
    python3 - "$out/noise.bin" "$ROOT/generated/ir.json" "$1" <<'PY'
import json, random, sys
proto = next(p for p in json.load(open(sys.argv[2]))["protocols"] if p["package"] == sys.argv[3])
sync = bytes(proto["framing"]["sync"])
rng = random.Random(20261121)
chunks = []
for _ in range(4000):
    r = rng.random()
    if r < 0.5:
        chunks.append(bytes(rng.randrange(256) for _ in range(rng.randrange(8))))
    else:  # a sync pair and a header followed by random bytes: false and truncated packets
        chunks.append(sync + bytes([rng.randrange(256), rng.randrange(256)]) + bytes(rng.randrange(256) for _ in range(rng.randrange(40))))
open(sys.argv[1], "wb").write(b"".join(chunks))
PY
    "$out/$1-decode" "$out/noise.bin" | "$out/$1-encode" | cmp - "$out/noise.bin"
    echo "c.sh: $1 sanitized tests and noise round trip passed" >&2
}

# The getting-started example (examples/getting_started.c), built when missing or out of date.
ensure_example() {
    local out="$ROOT/build/c/$PACKAGE"
    if [ -x "$out/$PACKAGE-getting-started" ] &&
        cmake --build "$out" --target "${PACKAGE}_c_getting_started" >/dev/null 2>&1; then
        return
    fi
    build_one "$PACKAGE"
}

# The session tool (docs/conformance.md section 8), built when missing or out of date.
ensure_session() {
    local out="$ROOT/build/c/$PACKAGE"
    if [ ! -x "$out/$PACKAGE-session" ] || ! cmake --build "$out" --target "${PACKAGE}_c_session" >/dev/null 2>&1; then
        build_one "$PACKAGE"
    fi
}

# Configures package $1 when needed and builds only its target $2.
build_target() {
    local src="$ROOT/generated/c/$1" out="$ROOT/build/c/$1"
    if [ ! -f "$out/build.ninja" ]; then
        # shellcheck disable=SC2046 # one argument per line of asked
        cmake -G Ninja -S "$src" -B "$out" -DCMAKE_BUILD_TYPE=Debug -D"$(werror "$1")" $(asked "$1" TESTS TOOLS EXAMPLES) >&2
    fi
    cmake --build "$out" --target "$2" >&2
}

# An application program of tests/apps/c/ (tests/apps/README.md): its own small CMake project over the
# package (add_subdirectory), only the program's target built.
app() {
    local name="$1" src="$ROOT/tests/apps/c" out="$ROOT/build/c-apps"
    if [[ ! "$name" =~ ^[A-Za-z0-9_]+$ ]] || [ ! -f "$src/$name.c" ]; then
        echo "c.sh: no application tests/apps/c/$name.c" >&2
        exit 2
    fi
    # Quiet unless it fails (warnings are errors): the program's own stderr stays clean.
    mkdir -p "$out"
    if ! { [ -f "$out/build.ninja" ] || cmake -G Ninja -S "$src" -B "$out" -DCMAKE_BUILD_TYPE=Debug; } >"$out/app-build.log" 2>&1 ||
        ! cmake --build "$out" --target "$name" >>"$out/app-build.log" 2>&1; then
        cat "$out/app-build.log" >&2
        echo "c.sh: building tests/apps/c/$name.c failed" >&2
        exit 1
    fi
}

usage() {
    echo "usage: tests/lang/c.sh build | test | runtime | decode FILE [--device ID] | encode | example FILE | session --connect ADDRESS ... | configure ADDRESS [COUNT] | app NAME [ARGS...]" >&2
    exit 2
}

[ $# -ge 1 ] || usage
cmd="$1"
shift
case "$cmd" in
runtime)
    runtime_tests
    ;;
build)
    for pkg in $(packages); do build_one "$pkg"; done
    ;;
test)
    runtime_tests
    for pkg in $(packages); do
        build_one "$pkg"
        # The library never allocates: no allocator symbol may be referenced by it.
        if nm -u "$ROOT/build/c/$pkg/lib$pkg.a" | grep -wE 'malloc|calloc|realloc|free|aligned_alloc|posix_memalign'; then
            echo "c.sh: lib$pkg.a references the heap allocator (listed above)" >&2
            exit 1
        fi
        "$ROOT/build/c/$pkg/$pkg-tests"
        sanitized "$pkg"
    done
    ;;
decode)
    [ $# -ge 1 ] || usage
    locked "$ROOT/build/c/$PACKAGE" ensure_built
    exec "$ROOT/build/c/$PACKAGE/$PACKAGE-decode" "$@"
    ;;
encode)
    locked "$ROOT/build/c/$PACKAGE" ensure_built
    exec "$ROOT/build/c/$PACKAGE/$PACKAGE-encode" "$@"
    ;;
session)
    out="$ROOT/build/c/$PACKAGE"
    locked "$out" ensure_session
    exec "$out/$PACKAGE-session" "$@"
    ;;
configure)
    locked "$ROOT/build/c/$PACKAGE" build_target "$PACKAGE" "${PACKAGE}_c_configure_and_stream"
    exec "$ROOT/build/c/$PACKAGE/$PACKAGE-configure-and-stream" "$@"
    ;;
app)
    [ $# -ge 1 ] || usage
    locked "$ROOT/build/c-apps" app "$1"
    exec "$ROOT/build/c-apps/$1" "${@:2}"
    ;;
example)
    locked "$ROOT/build/c/$PACKAGE" ensure_example
    exec "$ROOT/build/c/$PACKAGE/$PACKAGE-getting-started" "$@"
    ;;
*)
    usage
    ;;
esac
