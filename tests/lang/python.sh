#!/usr/bin/env bash
# Build, test and run the generated Python packages.
#   tests/lang/python.sh build                        byte-compile every package under generated/python/ into build/python/
#   tests/lang/python.sh test                         ruff check, mypy --strict of every package (the golden
#                                                     tree's: tests/golden), the runtime's unit tests in place
#                                                     (generator/targets/python/runtime/tests/), then pytest of
#                                                     every package; each twice: with the C accelerator (built
#                                                     by `ext`) and forced pure (<PKG>_PURE=1); then `consumer`
#   tests/lang/python.sh consumer                     every package built into an sdist and a wheel (python -m
#                                                     build), installed with pip --no-index into clean
#                                                     virtualenvs (with the accelerator, and from the sdist with
#                                                     no C compiler) and used from outside the tree, mypy --strict
#                                                     of a typed consumer (tests/consumer/test_python_package.py)
#   tests/lang/python.sh ext                          build every package with its C accelerator in place
#                                                     into build/python/ext/<package>/ (prints the directory)
#   tests/lang/python.sh decode FILE [--device ID]    python -m <package> decode (FILE may be -)
#   tests/lang/python.sh encode                       python -m <package> encode (stdin -> stdout)
#   tests/lang/python.sh session --connect ADDRESS ...  python -m <package>.session_tool (docs/conformance.md section 7)
#   tests/lang/python.sh example FILE                 the package's examples/getting_started.py FILE
#   tests/lang/python.sh configure ADDRESS [COUNT]    the package's examples/configure_and_stream.py
#   tests/lang/python.sh app NAME [ARGS...]          an application program, tests/apps/python/NAME.py (tests/apps/README.md)
# The package for decode/encode/example is $PY_PACKAGE (default: mipcodec). Works from any directory.
# decode/encode run the pure-Python code straight from generated/python/<package>; bytecode
# is cached under build/python/pycache (PYTHONPYCACHEPREFIX), never inside generated/. The optional
# C accelerator (<package>/codec/_speedups*.c) is built by the package's own setup.py (build_ext --inplace)
# in a copy under build/python/ext/, never in generated/ and without installing anything.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
PACKAGE="${PY_PACKAGE:-mipcodec}"
# shellcheck source=tests/lang/lock.sh
. "$ROOT/tests/lang/lock.sh"
if [ -x "$ROOT/.venv/bin/python" ]; then PY="$ROOT/.venv/bin/python"; else PY="$(command -v python3)"; fi
if [ -x "$ROOT/.venv/bin/ruff" ]; then RUFF="$ROOT/.venv/bin/ruff"; else RUFF="$(command -v ruff || true)"; fi
MYPY_CACHE="$ROOT/build/python/mypy-cache"
export PYTHONPYCACHEPREFIX="$ROOT/build/python/pycache"
unset PYTHONDONTWRITEBYTECODE  # the cache lives in build/, not in the sources

packages() {
    local d
    for d in "$ROOT"/generated/python/*/; do
        [ -f "$d/pyproject.toml" ] && basename "$d"
    done
}

usage() {
    echo "usage: tests/lang/python.sh build | ext | test | consumer | decode FILE [--device ID] | encode | session --connect ADDRESS ... | example FILE | configure ADDRESS [COUNT] | app NAME [ARGS...]" >&2
    exit 2
}

# Runs python with the package importable: run_py ARGS...
run_py() {
    local src="$ROOT/generated/python/$PACKAGE"
    if [ ! -d "$src/$PACKAGE" ]; then
        echo "tests/lang/python.sh: no generated package $src (run make)" >&2
        exit 2
    fi
    PYTHONPATH="$src${PYTHONPATH:+:$PYTHONPATH}" exec "$PY" "$@"
}

run_cli() {
    run_py -m "$PACKAGE" "$@"
}

# The digest of package $1's sources (generated/python/$1) and of the Python that builds it.
source_digest() {
    {
        "$PY" -c 'import sys; print(sys.version, sys.executable)'
        (cd "$ROOT/generated/python/$1" && find . -type f ! -name '*.pyc' -print0 | sort -z | xargs -0 sha256sum)
    } | sha256sum | cut -d' ' -f1
}

# Copies package $1 to build/python/ext/$1 (timestamps kept, so unchanged _speedups*.c are not
# recompiled) and builds its C accelerator in place there; fails when it did not build. A copy
# built from the same sources by the same Python (its .built file holds their digest) is left as
# it is: tests running side by side (pytest workers) each ask for the build, and one must never
# rewrite the tree while another runs the package from it. Run under the tree's lock (locked).
build_ext() {
    local pkg="$1" out="$ROOT/build/python/ext/$1" digest
    digest="$(source_digest "$pkg")"
    if [ -f "$out/.built" ] && [ "$(cat "$out/.built")" = "$digest" ]; then
        return
    fi
    mkdir -p "$out"
    rm -f "$out/.built"
    find "$out" -name '*.py' -delete
    cp -Rp "$ROOT/generated/python/$pkg/." "$out/"
    (cd "$out" && PYTHONPYCACHEPREFIX= "$PY" setup.py -q build_ext --inplace \
        --build-temp "$ROOT/build/python/ext-tmp/$pkg" >"$out/build.log" 2>&1) || {
        cat "$out/build.log" >&2
        echo "tests/lang/python.sh: building $pkg/codec/_speedups*.c failed" >&2
        exit 1
    }
    if ! ls "$out/$pkg"/codec/_speedups*.so >/dev/null 2>&1; then
        cat "$out/build.log" >&2
        echo "tests/lang/python.sh: $pkg/codec/_speedups*.c did not build (a C compiler and the Python headers, e.g. Debian python3-dev, are needed)" >&2
        exit 1
    fi
    # Byte-compiled beside the sources, as pip installs a package: the timed runs of the bench
    # (tests/bench: the CPU seconds of `python -m <package> export`) start as an installed package
    # does, not compiling every module again (about 0.3 s of CPU a run when PYTHONDONTWRITEBYTECODE
    # is set).
    PYTHONPYCACHEPREFIX= "$PY" -m compileall -q "$out/$pkg" >&2
    echo "$digest" >"$out/.built"
}

[ $# -ge 1 ] || usage
cmd="$1"
shift
case "$cmd" in
build)
    for pkg in $(packages); do
        out="$ROOT/build/python/$pkg"
        rm -rf "$out"
        mkdir -p "$out"
        cp -R "$ROOT/generated/python/$pkg/." "$out/"
        PYTHONPYCACHEPREFIX= "$PY" -m compileall -q "$out" >&2
    done
    ;;
ext)
    for pkg in $(packages); do
        locked "$ROOT/build/python/ext/$pkg" build_ext "$pkg"
        echo "$ROOT/build/python/ext/$pkg"
    done
    ;;
test)
    [ -n "$RUFF" ] || { echo "tests/lang/python.sh: ruff not found (run make)" >&2; exit 2; }
    (cd "$ROOT" && "$RUFF" check --config ruff.toml generated/python generator/targets/python/runtime)
    # The packages are typed (py.typed): each passes mypy --strict as its consumers run it (the
    # golden tree's package: tests/golden/test_builds.py).
    for dir in "$ROOT"/generated/python/*/; do
        [ -f "$dir/pyproject.toml" ] || continue
        echo "== $(basename "$dir"): mypy --strict"
        (cd "$dir" && "$PY" -m mypy --strict --explicit-package-bases --no-error-summary --cache-dir "$MYPY_CACHE" "$(basename "$dir")" examples/*.py)
    done
    # The runtime's unit tests (generator/targets/python/runtime/tests/), before the generated
    # packages' tests, on the test protocol rendered by the Python back end from tests/runtime_specs/
    # into build/runtime_specs/<framing>/python/testproto/ (docs/runtime-contract.md): with each of
    # its two framings (TESTPROTO_FRAMING), pure and with the C accelerator (built there).
    for framing in a b; do
        echo "== runtime, framing $framing: pure Python (TESTPROTO_PURE=1)"
        (cd "$ROOT" && env TESTPROTO_FRAMING="$framing" TESTPROTO_PURE=1 "$PY" -m pytest -q -p no:cacheprovider generator/targets/python/runtime/tests)
        echo "== runtime, framing $framing: with the C accelerator"
        (cd "$ROOT" && env -u TESTPROTO_PURE TESTPROTO_FRAMING="$framing" "$PY" -m pytest -q -p no:cacheprovider generator/targets/python/runtime/tests)
    done
    for pkg in $(packages); do
        up="$(echo "$pkg" | tr '[:lower:]' '[:upper:]')"
        echo "== $pkg: pure Python (${up}_PURE=1)"
        (cd "$ROOT" && env "${up}_PURE=1" PYTHONPATH="$ROOT/generated/python/$pkg" "$PY" -m pytest -q -p no:cacheprovider "generated/python/$pkg/tests")
        echo "== $pkg: with the C accelerator (build/python/ext/$pkg)"
        locked "$ROOT/build/python/ext/$pkg" build_ext "$pkg"
        (cd "$ROOT/build/python/ext/$pkg" && env -u "${up}_PURE" "${up}_EXPECT_ACCELERATED=1" PYTHONPATH="$ROOT/build/python/ext/$pkg" "$PY" -m pytest -q -p no:cacheprovider tests)
    done
    "$0" consumer
    ;;
consumer)
    echo "== consumer: sdist and wheel of every package installed into clean virtualenvs (no index)"
    (cd "$ROOT" && "$PY" -m pytest -q -p no:cacheprovider tests/consumer/test_python_package.py)
    ;;
decode)
    [ $# -ge 1 ] || usage
    file="$1"
    shift
    run_cli decode "$@" "$file"
    ;;
encode)
    run_cli encode "$@"
    ;;
session)
    run_py -m "$PACKAGE.session_tool" "$@"
    ;;
example)
    run_py "$ROOT/generated/python/$PACKAGE/examples/getting_started.py" "$@"
    ;;
configure)
    run_py "$ROOT/generated/python/$PACKAGE/examples/configure_and_stream.py" "$@"
    ;;
app)
    [ $# -ge 1 ] || usage
    name="$1"
    shift
    if [ ! -f "$ROOT/tests/apps/python/$name.py" ]; then
        echo "tests/lang/python.sh: no application tests/apps/python/$name.py" >&2
        exit 2
    fi
    run_py "$ROOT/tests/apps/python/$name.py" "$@"
    ;;
*)
    usage
    ;;
esac
