#!/usr/bin/env bash
# tests/lang/cpp.sh build|test|runtime|decode FILE [--device ID]|encode|session --connect ADDRESS ...|example FILE|configure ADDRESS [COUNT]|app NAME [ARGS...]
# Builds the generated C++ package(s) into build/cpp/<package>/, runs their googletest suites (after
# the runtime's own tests, in place: generator/targets/cpp/runtime/tests/ into build/cpp-runtime/), or
# runs the decode/encode/session tools or the getting-started example (<package>-getting-started FILE),
# building them first when needed; `runtime` runs only the runtime's in-place checks; `app NAME` builds
# the application program tests/apps/cpp/NAME.cpp against the package (tests/apps/README.md; build dir
# build/apps/cpp/<package>) and runs it with ARGS. Works from any directory.
# CPP_PACKAGE selects the package for decode/encode/example/configure/app (default: mipcodec).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
PKG="${CPP_PACKAGE:-mipcodec}"
GEN="$ROOT/generated/cpp"
# shellcheck source=tests/lang/lock.sh
. "$ROOT/tests/lang/lock.sh"

usage() { echo "usage: $0 build|test|runtime|decode FILE [--device ID]|encode|session --connect ADDRESS ...|example FILE|configure ADDRESS [COUNT]|app NAME [ARGS...]" >&2; exit 2; }

packages() {
  local d
  for d in "$GEN"/*/; do
    [ -f "$d/CMakeLists.txt" ] && basename "$d"
  done
}

# The package's <PKG>_WERROR option (OFF for consumers), ON in the project's own builds.
werror() { echo "$(tr '[:lower:]' '[:upper:]' <<<"$1")_WERROR=ON"; }

# The package's tests, tools and examples: OFF unless asked for (docs/packaging.md); the project's
# own builds ask. asked PACKAGE WHAT... prints -D<PKG>_BUILD_<WHAT>=ON, one per line.
asked() {
  local P w
  P="$(tr '[:lower:]' '[:upper:]' <<<"$1")"; shift
  for w in "$@"; do echo "-D${P}_BUILD_${w}=ON"; done
}

configure() { # package
  local src="$GEN/$1" out="$ROOT/build/cpp/$1"
  [ -f "$src/CMakeLists.txt" ] || { echo "cpp.sh: $src is missing; run 'python -m generator --only cpp'" >&2; exit 2; }
  if [ ! -f "$out/build.ninja" ]; then
    # shellcheck disable=SC2046 # one argument per line of asked
    cmake -G Ninja -S "$src" -B "$out" -D"$(werror "$1")" $(asked "$1" TESTS TOOLS EXAMPLES) >&2
  fi
}

# The hand-written runtime (generator/targets/cpp/runtime/), checked where it is edited, without
# regenerating generated/: clang-format clean, then for each framing of the test protocol rendered
# by the C++ back end from tests/runtime_specs/ (docs/runtime-contract.md) into
# build/runtime_specs/<framing>/cpp/testproto/, the runtime's tests copied beside it with the
# package's names, built against it (strict warnings, AddressSanitizer and
# UndefinedBehaviorSanitizer; build/cpp-runtime/<framing>/) and run. No hand-written stand-ins.
runtime_tests() {
  local rt="$ROOT/generator/targets/cpp/runtime" fmt py framing out build t
  fmt="${CLANG_FORMAT:-$ROOT/.venv/bin/clang-format}"
  [ -x "$fmt" ] || fmt="$(command -v clang-format)"
  py="$ROOT/.venv/bin/python"
  [ -x "$py" ] || py="$(command -v python3)"
  (cd "$ROOT" && "$fmt" --style=file --dry-run --Werror "$rt"/include/protopkg/*.hpp "$rt"/tools/*.cpp \
    "$rt"/package_tests/* "$rt"/tests/*.cpp "$rt"/tests/*.hpp)
  for framing in a b; do
    out="$(cd "$ROOT" && "$py" -m tests.runtime_specs.render --tests cpp "$framing")"
    build="$ROOT/build/cpp-runtime/$framing"
    if [ ! -f "$build/build.ninja" ]; then
      cmake -G Ninja -S "$out/tests-cpp" -B "$build" -DPACKAGE_DIR="$out/cpp/testproto" \
        -DCMAKE_CXX_FLAGS="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer" \
        -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >&2
    fi
    cmake --build "$build" >&2
    for t in "$build"/runtime-tests*; do
      echo "== runtime, framing $framing: $(basename "$t")" >&2
      "$t" --gtest_brief=1
    done
  done
}

build_app() { # build-dir name: the program NAME of tests/apps/cpp/ (its own CMake project)
  [ -f "$1/build.ninja" ] || cmake -G Ninja -S "$ROOT/tests/apps/cpp" -B "$1" -DAPP_PACKAGE="$PKG"
  cmake --build "$1" --target "$2"
}

build() { # package [targets...]
  local pkg="$1"; shift
  configure "$pkg"
  cmake --build "$ROOT/build/cpp/$pkg" ${1:+--target "$@"} >&2
}

tool() { # decode|encode|session|getting-started
  local exe="$ROOT/build/cpp/$PKG/$PKG-$1"
  # Always let ninja check (a no-op when up to date), so a regenerated package is rebuilt.
  locked "$ROOT/build/cpp/$PKG" build "$PKG" "${PKG}_cpp_${1//-/_}" >/dev/null 2>"$ROOT/build/cpp/.$PKG-$1.log" || { cat "$ROOT/build/cpp/.$PKG-$1.log" >&2; exit 2; }
  echo "$exe"
}

[ $# -ge 1 ] || usage
cmd="$1"; shift
case "$cmd" in
  build)
    for p in $(packages); do build "$p"; done
    ;;
  test)
    runtime_tests
    for p in $(packages); do
      build "$p"
      "$ROOT/build/cpp/$p/$p-tests" "$@"
      # The same suite under AddressSanitizer and UndefinedBehaviorSanitizer (any report fails).
      san="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
      out="$ROOT/build/cpp-sanitize/$p"
      if [ ! -f "$out/build.ninja" ]; then
        # Only the suite: the tools and examples are built (unsanitized) above.
        # shellcheck disable=SC2046 # one argument per line of asked
        cmake -G Ninja -S "$GEN/$p" -B "$out" -DCMAKE_BUILD_TYPE=Debug -D"$(werror "$p")" $(asked "$p" TESTS) -DCMAKE_CXX_FLAGS="$san" \
          -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" >&2
      fi
      cmake --build "$out" >&2
      "$out/$p-tests" --gtest_brief=1
    done
    ;;
  runtime)
    runtime_tests
    ;;
  decode)
    [ $# -ge 1 ] || usage
    mkdir -p "$ROOT/build/cpp"
    exe="$(tool decode)"
    exec "$exe" "$@"
    ;;
  encode)
    mkdir -p "$ROOT/build/cpp"
    exe="$(tool encode)"
    exec "$exe" "$@"
    ;;
  session)
    # The session conformance tool (docs/conformance.md section 8).
    mkdir -p "$ROOT/build/cpp"
    exe="$(tool session)"
    exec "$exe" "$@"
    ;;
  configure)
    # The configure-and-stream example (examples/configure_and_stream.cpp): ADDRESS [COUNT].
    mkdir -p "$ROOT/build/cpp"
    exe="$(tool configure-and-stream)"
    exec "$exe" "$@"
    ;;
  app)
    # An application program of tests/apps/cpp/ (its own CMake project using the package as a
    # vendored subdirectory), rebuilt when needed, then run with ARGS.
    [ $# -ge 1 ] || usage
    name="$1"; shift
    [ -f "$ROOT/tests/apps/cpp/$name.cpp" ] || { echo "cpp.sh: no program tests/apps/cpp/$name.cpp" >&2; exit 2; }
    out="$ROOT/build/apps/cpp/$PKG"
    mkdir -p "$out"
    locked "$out" build_app "$out" "$name" >"$out/.$name.log" 2>&1 || { cat "$out/.$name.log" >&2; exit 2; }
    exec "$out/$name" "$@"
    ;;
  example)
    mkdir -p "$ROOT/build/cpp"
    exe="$(tool getting-started)"
    exec "$exe" "$@"
    ;;
  *) usage ;;
esac
