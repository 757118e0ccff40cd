# Sourced by tests/lang/c.sh and cpp.sh: `locked DIR COMMAND...` runs COMMAND (a function of the
# script or a program) holding DIR's build lock (DIR/.build-lock, flock(1) of util-linux), so two
# runs that build the same tree at once take turns: `make test-conformance` runs its tests on
# several pytest workers, and each tool or program builds on first use. Cargo keeps its own lock
# on a target directory (tests/lang/rust.sh needs none); without flock the command runs unlocked.
# The lock is released when COMMAND ends: never held by the tool the script then runs (exec).
locked() {
    local dir="$1"
    shift
    mkdir -p "$dir"
    if command -v flock >/dev/null 2>&1; then
        (
            flock 9
            "$@"
        ) 9>"$dir/.build-lock"
    else
        "$@"
    fi
}
