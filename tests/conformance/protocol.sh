# Sourced by tests/conformance/decode and encode: handles `--protocol NAME` (default mip).
# Selects the package of that protocol (its `package` in generated/ir.json) for the language
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
    local root ir pkg
    root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
    ir="$root/generated/ir.json"
    [ -f "$ir" ] || { echo "no $ir (run make)" >&2; exit 2; }
    pkg="$(python3 -c 'import json,sys
ps = json.load(open(sys.argv[1]))["protocols"]
print(next((p["package"] for p in ps if p["name"] == sys.argv[2]), ""))
if not any(p["name"] == sys.argv[2] for p in ps):
    sys.exit("unknown protocol %r (expected one of: %s)" % (sys.argv[2], ", ".join(p["name"] for p in ps)))' "$ir" "$proto")" || exit 2
    export C_PACKAGE="$pkg" CPP_PACKAGE="$pkg" PY_PACKAGE="$pkg" RUST_PACKAGE="$pkg"
}
