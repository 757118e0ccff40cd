#!/usr/bin/env bash
# Build, test and run the generated Python packages.
#   tests/lang/python.sh build                        byte-compile every package under generated/python/ into build/python/
#   tests/lang/python.sh test                         ruff check + pytest of every package
#   tests/lang/python.sh decode FILE [--device ID]    python -m <package> decode (FILE may be -)
#   tests/lang/python.sh encode                       python -m <package> encode (stdin -> stdout)
#   tests/lang/python.sh example FILE                 the package's examples/getting_started.py FILE
# The package for decode/encode/example is $PY_PACKAGE (default: mipcodec). Works from any directory.
# Nothing needs compiling: decode/encode run straight from generated/python/<package>; bytecode
# is cached under build/python/pycache (PYTHONPYCACHEPREFIX), never inside generated/.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
PACKAGE="${PY_PACKAGE:-mipcodec}"
if [ -x "$ROOT/.venv/bin/python" ]; then PY="$ROOT/.venv/bin/python"; else PY="$(command -v python3)"; fi
if [ -x "$ROOT/.venv/bin/ruff" ]; then RUFF="$ROOT/.venv/bin/ruff"; else RUFF="$(command -v ruff || true)"; fi
export PYTHONPYCACHEPREFIX="$ROOT/build/python/pycache"
unset PYTHONDONTWRITEBYTECODE  # the cache lives in build/, not in the sources

packages() {
    local d
    for d in "$ROOT"/generated/python/*/; do
        [ -f "$d/pyproject.toml" ] && basename "$d"
    done
}

usage() {
    echo "usage: tests/lang/python.sh build | test | decode FILE [--device ID] | encode | example FILE" >&2
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
test)
    [ -n "$RUFF" ] || { echo "tests/lang/python.sh: ruff not found (run make)" >&2; exit 2; }
    (cd "$ROOT" && "$RUFF" check --config ruff.toml generated/python)
    for pkg in $(packages); do
        (cd "$ROOT" && PYTHONPATH="$ROOT/generated/python/$pkg" "$PY" -m pytest -q -p no:cacheprovider "generated/python/$pkg/tests")
    done
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
example)
    run_py "$ROOT/generated/python/$PACKAGE/examples/getting_started.py" "$@"
    ;;
*)
    usage
    ;;
esac
