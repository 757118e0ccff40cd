"""Facts of the Rust language and of the generated crate's layout, as data for the back end."""

from __future__ import annotations

from generator.targets import GettingStarted

# Rust keywords: strict and reserved words of the 2021 edition, plus `gen` (reserved in 2024).
# Most can be written as raw identifiers (`r#type`).
KEYWORDS = frozenset(
    """
    as break const continue crate else enum extern false fn for if impl in let loop match mod move
    mut pub ref return self Self static struct super trait true type unsafe use where while
    async await dyn abstract become box do final macro override priv typeof unsized virtual yield
    try gen
    """.split()
)

# Words that cannot be raw identifiers; the back end appends `_` to them instead.
NOT_RAW = frozenset({"crate", "self", "Self", "super", "_"})

# Primitive type of the spec -> Rust type. `char` is the runtime's one-byte character type.
PRIMITIVE_TYPES = {
    "bool": "bool",
    "char": "crate::wire::Char",
    "u8": "u8",
    "u16": "u16",
    "u32": "u32",
    "u64": "u64",
    "s8": "i8",
    "s16": "i16",
    "s32": "i32",
    "s64": "i64",
    "float": "f32",
    "double": "f64",
}

# Module names the crate already uses (runtime, generated modules, and the standard crates a
# module path could shadow); a descriptor set cannot take one of these as its module name.
RESERVED_MODULES = frozenset(
    {
        "bounded",
        "builder",
        "command_api",
        "commands",
        "device",
        "dispatch",
        "error",
        "fields",
        "framing",
        "json",
        "json_read",
        "packets",
        "parser",
        "reserved",
        "samples",
        "clock",
        "session",
        "text",
        "types",
        "wire",
        "std",
        "core",
        "alloc",
    }
)

# Methods of the blocking session API's `device::Device` (runtime/src/device.rs): the typed
# command API's per-set methods (`device.threedm()`) take another name when a set's would clash.
DEVICE_METHODS = frozenset(
    {
        "new",
        "with_timeout_ms",
        "with_check_device",
        "model",
        "now_ms",
        "on_packet",
        "on_field",
        "on_event",
        "run",
        "call",
        "listen",
        "pump",
        "close",
    }
)

# The generated crate's package metadata (Cargo.toml), as `cargo package` and crates.io want it.
# RUST_VERSION is the minimum supported Rust version (MSRV), found by building and testing the
# crates with older toolchains: 1.64 lacks `let ... else` (stable in 1.65), which the runtime
# uses; 1.65 builds the core (`--no-default-features`) and the std crate and passes their tests.
# `.ci/run` builds and tests a crate with exactly this toolchain (tests/lang/rust.sh msrv), and
# clippy's `incompatible_msrv` lint flags a standard-library API newer than it. Raising it is a
# decision (README "Rust"): change it here and in runtime/Cargo.toml (a test compares them).
RUST_VERSION = "1.65"
LICENSE = "MIT"
# crates.io categories (https://crates.io/category_slugs), at most five.
CATEGORIES = ["embedded", "no-std", "no-std::no-alloc", "encoding", "parser-implementations"]
# Keywords besides the protocol's name and its vendor (the first word of its title): at most five
# in all, each ASCII letters, digits, `-` or `_`, starting with a letter, at most 20 characters.
KEYWORDS_COMMON = ["protocol", "codec", "parser"]
# What `cargo package` puts into the .crate: the manifest, README, LICENSE (when present), the
# library, tools, example and tests; nothing else a generator run could leave beside them.
INCLUDE = ["/Cargo.toml", "/README.md", "/LICENSE", "/src/", "/examples/", "/tests/"]


# The getting-started page (generated/docs/getting-started/rust.md); `rust_version` is RUST_VERSION.
GETTING_STARTED = GettingStarted(
    install="Copy `generated/rust/{pkg}/` into your tree (Rust {rust_version} or newer, no dependencies) and depend on it"
    " by path; for `no_std` firmware (no allocator), turn off the default `std` feature:",
    setup='[dependencies]\n{pkg} = {{ path = "third_party/{pkg}" }}\n'
    '# no_std: {pkg} = {{ path = "third_party/{pkg}", default-features = false }}',
    setup_lang="toml",
    setup_outside="project",
    include_intro="and import it:",
    run_package_var="RUST_PACKAGE",
    outside_run="cargo run --features serial --example configure_and_stream -- ADDRESS 5",
    simulator_note=" (the crate's `serial` feature is what serial ports and pseudo-terminals need)",
    variables={"rust_version": RUST_VERSION},
)
