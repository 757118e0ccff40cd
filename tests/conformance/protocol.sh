# Sourced by tests/conformance/decode and encode: handles `--protocol NAME` (default mip).
# Selects the package of that protocol (`package:` in spec/NAME/protocol.yaml) for the language
# scripts, and leaves the other arguments in ARGS.
select_protocol() {
    local proto="mip" a
    ARGS=()
    while [ $# -gt 0 ]; do
        a="$1"; shift
        case "$a" in
        --protocol) [ $# -ge 1 ] || { echo "--protocol needs a NAME (mip, mscip)" >&2; exit 2; }; proto="$1"; shift ;;
        --protocol=*) proto="${a#--protocol=}" ;;
        *) ARGS+=("$a") ;;
        esac
    done
    local root file pkg
    root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
    file="$root/spec/$proto/protocol.yaml"
    if [ ! -f "$file" ]; then
        echo "unknown protocol '$proto' (expected one of: $(cd "$root/spec" && ls -d */ | tr -d / | grep -v schema | tr '\n' ' '))" >&2
        exit 2
    fi
    # The package name is the protocol file's top-level `package:` key.
    pkg="$(sed -n 's/^package:[[:space:]]*\([A-Za-z0-9_]*\).*/\1/p' "$file")"
    [ -n "$pkg" ] || { echo "$file has no package" >&2; exit 2; }
    export C_PACKAGE="$pkg" CPP_PACKAGE="$pkg" PY_PACKAGE="$pkg" RUST_PACKAGE="$pkg"
}
