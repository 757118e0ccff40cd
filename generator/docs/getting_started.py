"""The "getting started" page per language.

The code on these pages is cut from the example program each language back end generates into
its package (`examples/getting_started.*`, between `[build-command]` / `[parse-stream]` /
`[read-file]` and `[end]` comment lines). That program is built and run by the test suite
(tests/conformance/test_getting_started.py), so the snippets are code that compiles and works.
The output shown comes from the golden vectors, never from running the code here.
"""

from __future__ import annotations

import json
import re

from ..examples import END, PARTS, PROGRAM, SESSION_PARTS, SESSION_PROGRAM, example_command, session_example
from ..targets import TARGETS
from .model import CONFIGURE_ANCHOR, LANG_TITLES, Docs, Page, code, hx

EXTENSIONS = {name: TARGETS[name].EXTENSION for name in TARGETS}  # the target registry's languages
EXAMPLE_FILES = {lang: f"{lang}/{{pkg}}/examples/{PROGRAM}.{ext}" for lang, ext in EXTENSIONS.items()}
SESSION_EXAMPLE_FILES = {lang: f"{lang}/{{pkg}}/examples/{SESSION_PROGRAM}.{ext}" for lang, ext in EXTENSIONS.items()}
TITLES = {"build-command": "Build a command", "parse-stream": "Parse a stream", "read-file": "Decode a capture"}
# The variable that picks the package of tests/lang/<lang>.sh (default mipcodec).
RUN_PACKAGE_VARS = {"c": "C_PACKAGE", "cpp": "CPP_PACKAGE", "python": "PY_PACKAGE", "rust": "RUST_PACKAGE"}
SESSION_TITLES = {
    "connect": "Connect and identify the device",
    "configure": "Write and read a setting",
    "stream": "Enable the data stream and handle its fields",
}


def snippet(source: str, part: str) -> str:
    """The lines between the `[part]` marker comment and the next `[end]`, dedented."""
    lines = source.splitlines()
    start = next((i for i, ln in enumerate(lines) if ln.strip().endswith(f"[{part}]")), None)
    if start is None:
        raise ValueError(f"example has no [{part}] marker")
    end = next(i for i in range(start + 1, len(lines)) if lines[i].strip().endswith(f"[{END}]"))
    body = lines[start + 1 : end]
    while body and not body[-1].strip():
        body.pop()
    while body and not body[0].strip():
        body.pop(0)
    indent = min((len(ln) - len(ln.lstrip()) for ln in body if ln.strip()), default=0)
    return "\n".join(ln[indent:] for ln in body)


def _setup(lang: str, pkg: str, files: dict[str, str]) -> tuple[str, str]:
    """(text, code) telling how to vendor and build the package."""
    if lang == "c":
        return (
            f"Copy `generated/c/{pkg}/` into your tree (C99, no allocation, no dependencies) and add it to your"
            f" CMake build (or install it and use `find_package({pkg} CONFIG REQUIRED)` or pkg-config: see"
            " the package's README). Its tests, tools and examples stay off when it is not the top-level"
            " project:",
            f"add_subdirectory(third_party/{pkg})\n"
            f"target_link_libraries(your_app PRIVATE {pkg}::c)   # {pkg}::c_json for canonical JSON lines",
        )
    if lang == "cpp":
        return (
            f"Copy `generated/cpp/{pkg}/` into your tree (a C++17 library: CMake builds it) and add it to your CMake build (or"
            f" install it and use `find_package({pkg} CONFIG REQUIRED)` or pkg-config: see the package's README):",
            f"add_subdirectory(third_party/{pkg})\ntarget_link_libraries(your_app PRIVATE {pkg}::cpp)",
        )
    if lang == "python":
        return (
            f"Install `generated/python/{pkg}/` (Python 3.9+, no dependencies, typed for mypy; its optional C "
            "accelerator is compiled when a C compiler is there), or build a wheel and an sdist once and install "
            f"from them anywhere, offline too (`generated/python/{pkg}/README.md` has the details):",
            f"pip install ./generated/python/{pkg}\n"
            f"# or: python -m build --outdir dist generated/python/{pkg}\n"
            f"#     pip install --no-index --find-links dist {pkg}\n"
            f"python -m {pkg} decode capture.bin   # canonical JSON lines",
        )
    msrv = re.search(r'^rust-version = "([^"]+)"', files.get(f"rust/{pkg}/Cargo.toml", ""), re.M)
    since = f"Rust {msrv.group(1)} or newer, " if msrv else ""
    return (
        f"Copy `generated/rust/{pkg}/` into your tree ({since}no dependencies) and depend on it by path; "
        "for `no_std` firmware (no allocator), turn off the default `std` feature:",
        f'[dependencies]\n{pkg} = {{ path = "third_party/{pkg}" }}\n'
        f'# no_std: {pkg} = {{ path = "third_party/{pkg}", default-features = false }}',
    )


def _include(lang: str, pkg: str, source: str) -> str:
    """The include or import lines of the example program that name the package."""
    lines = [ln for ln in source.splitlines() if pkg in ln and ln.startswith(("#include", "import", "from", "use "))]
    return "\n".join(lines)


def _example_vector(docs: Docs, p: dict) -> dict | None:
    """The golden vector whose packet is exactly the example command with no values."""
    s, f = example_command(p)
    want = {"set": s["id"], "fields": [{"descriptor": f["id"], "name": f["name"], "values": {}}]}
    for v in docs.vectors:
        if v["protocol"] != p["name"] or v["rejected"] or len(v["expect"]) != 1:
            continue
        obj = json.loads(v["expect"][0])
        obj.pop("offset", None)
        if obj == want:
            return v
    return None


def configure_section(docs: Docs, pg: Page, lang: str) -> None:
    """The "Configure the device and stream data" section of a language's page: the parts of
    `examples/configure_and_stream.<ext>` of each protocol's package (generator/examples.py
    session_example), or a note where that language's package does not have the program yet."""
    if not any(session_example(p) is not None for p in docs.ir["protocols"]):
        return
    pg.h(2, "Configure the device and stream data", CONFIGURE_ANCHOR)
    pg.p(
        "Talking to a device goes through the package's command session: each command is sent, its ack "
        "or NACK (and the reply fields that come with it) is matched, a command that gets no answer times "
        "out, and every data packet that arrives meanwhile goes to the handlers. The snippets are cut from "
        f"the example program `examples/{SESSION_PROGRAM}` of each package, which the test suite runs "
        "against a scripted device over TCP (`tests/conformance/test_configure_example.py`)."
    )
    for p in docs.ir["protocols"]:
        ex = session_example(p)
        if ex is None:
            continue
        pkg = p["package"]
        rel = SESSION_EXAMPLE_FILES[lang].format(pkg=pkg)
        source = docs.examples.get(rel)
        pg.h(3, f"{p['title']} ({pkg})", f"{CONFIGURE_ANCHOR}-{p['name']}")
        if source is None:
            pg.p(f"The {LANG_TITLES[lang]} session example of `{pkg}` is not generated yet.")
            continue
        devices = {d["id"]: d["title"] for d in p["devices"]}
        pg.p(
            f"Run as `{SESSION_PROGRAM} ADDRESS [COUNT]`, ADDRESS `tcp:HOST:PORT` or a serial device path; "
            f"written for the {devices.get(ex['device'], ex['device'])}."
        )
        for part in SESSION_PARTS:
            pg.h(4, SESSION_TITLES[part], f"{CONFIGURE_ANCHOR}-{p['name']}-{part}")
            if part == "connect":
                pg.p(
                    "Open the transport with the device model selected: a command the model does not support is "
                    "refused before it is sent. Each call gives the typed reply or fails (a NACK with its error "
                    "code, a timeout, a refusal)."
                )
            elif part == "configure":
                pg.p(f"Write {ex['setting']['field']['title']}, then read it back.")
            else:
                pg.p(
                    "Register one handler per data descriptor, choose the fields of the data message "
                    f"({ex['format']['field']['title']}), enable the stream ({ex['enable']['field']['title']}) "
                    "and receive: the handlers run while the program waits."
                )
            pg.code(snippet(source, part), lang)
        pg.p(f"The whole program: `generated/{rel}`.")
        simulator_section(pg, lang, p, ex)


# How an outside user builds and runs the configure-and-stream example from the package's own
# directory (no repository): {pkg} the package, ADDRESS the simulator's address. Checked by
# tests/docs/test_outside_user.py (the Python and C commands run against the simulator there).
OUTSIDE_RUN = {
    # only the example run (--target): the package's other examples are not needed for it
    "c": "cmake -S . -B build -D{PKG}_BUILD_EXAMPLES=ON && cmake --build build --target {pkg}-configure-and-stream\n"
    "build/{pkg}-configure-and-stream ADDRESS 5",
    "cpp": "cmake -S . -B build -D{PKG}_BUILD_EXAMPLES=ON && cmake --build build --target {pkg}-configure-and-stream\n"
    "build/{pkg}-configure-and-stream ADDRESS 5",
    "python": "python examples/configure_and_stream.py ADDRESS 5",
    "rust": "cargo run --features serial --example configure_and_stream -- ADDRESS 5",
}


def simulator_section(pg: Page, lang: str, p: dict, ex: dict) -> None:
    """How to run the example against the simulated device: from the package (an outside user,
    after `pip install` of the Python package that carries the simulator), then in this repository."""
    pg.h(4, "Run it against the simulator", f"{CONFIGURE_ANCHOR}-{p['name']}-simulator")
    pkg = p["package"]
    title = next((d["title"] for d in p["devices"] if d["id"] == ex["device"]), ex["device"])
    pg.p(
        f"Without the hardware, run the program against the simulated {title}: it answers every command as "
        "the device does, keeps the setting the program writes and streams the data it enables "
        "(docs/simulator.md). The simulator comes with the Python package; start it, then give the address "
        "it prints first to the program. From the package's directory (`generated/"
        f"{lang}/{pkg}`, or wherever you vendored it), with the Python package installed"
        + (" (the crate's `serial` feature is what serial ports and pseudo-terminals need):" if lang == "rust" else ":")
    )
    sim = f"python -m {pkg}.sim --device {ex['device']}"
    run = OUTSIDE_RUN[lang].format(pkg=pkg, PKG=pkg.upper())
    pg.code(
        f"pip install 'generated/python/{pkg}[serial]'   # the Python package's directory, sdist or wheel\n"
        f"{sim} --listen tcp:127.0.0.1:0 &   # prints tcp:127.0.0.1:PORT\n"
        + run.replace("ADDRESS", "tcp:127.0.0.1:PORT"),
        "sh",
        outside=f"cd generated/{lang}/{pkg}",
    )
    pg.p(
        f"In this repository, `tests/lang/{lang}.sh configure ADDRESS [COUNT]` builds and runs this example and "
        "`tests/conformance/simulate` starts the simulator (`tests/conformance/test_simulator_examples.py` runs "
        "both, over TCP and a pseudo-terminal):"
    )
    select = "" if pkg == "mipcodec" else f"{RUN_PACKAGE_VARS[lang]}={pkg} "
    sim = f"tests/conformance/simulate --protocol {p['name']} --device {ex['device']}"
    run = f"{select}tests/lang/{lang}.sh configure"
    pg.code(
        f"{sim} --listen tcp:127.0.0.1:0 &   # prints tcp:127.0.0.1:PORT\n"
        f"{run} tcp:127.0.0.1:PORT 5\n"
        f"{sim} --listen pty &               # prints the pty's path, e.g. /dev/pts/3\n"
        f"{run} /dev/pts/3 5",
        "sh",
        outside="not run: repository commands (tests/conformance/test_simulator_examples.py runs them)",
    )


def add_pages(docs: Docs) -> None:
    for lang in docs.api:
        pg = docs.add(
            Page(f"getting-started/{lang}.md", f"Getting started in {LANG_TITLES[lang]}", [("Reference", "README.md")])
        )
        pg.p(
            "Every snippet on this page is cut from the example program generated into the package "
            "(`examples/getting_started`), which the test suite builds and runs on a stream of golden vectors "
            "(`tests/conformance/test_getting_started.py`). The packages of the other protocols have the same API "
            "under their own names."
        )
        for p in docs.ir["protocols"]:
            pkg = p["package"]
            rel = EXAMPLE_FILES[lang].format(pkg=pkg)
            source = docs.examples.get(rel)
            pg.h(2, f"{p['title']} ({pkg})", p["name"])
            text, setup = _setup(lang, pkg, docs.examples)
            pg.p(text)
            # for the outside-user test (docs/conformance.md §11): capture.bin is the page's placeholder for
            # a device log; a CMake or Cargo snippet is built as a project around the package's example
            pg.code(
                setup,
                "cmake" if lang in ("c", "cpp") else ("toml" if lang == "rust" else "sh"),
                outside="files capture.bin" if lang == "python" else "project",
            )
            include = _include(lang, pkg, source or "")
            if include:
                pg.p("and include the package's umbrella header:" if lang in ("c", "cpp") else "and import it:")
                pg.code(include, lang)
            if source is None:
                pg.p(f"The example program `generated/{rel}` is not generated.")
                continue
            s, f = example_command(p)
            v = _example_vector(docs, p)
            for part in PARTS:
                title = TITLES[part]
                pg.h(3, title, f"{p['name']}-{part}")
                if part == "build-command":
                    link = pg.link_to(docs.field_path(p, s, f))
                    pg.p(
                        f"Builds [{f['title']}]({link}) ({hx(s['id'])},{hx(f['id'])}) with the typed value and the packet builder."
                    )
                elif part == "parse-stream":
                    pg.p(
                        "Feed bytes as they arrive, in chunks of any size: the parser keeps at most one packet, "
                        "reports every skipped byte run, and resynchronises after garbage."
                    )
                else:
                    pg.p("Read a capture file in blocks and feed them to the same parser, then flush at end of input.")
                pg.code(snippet(source, part), lang)
                if part == "build-command" and v:
                    pg.p(
                        f"Prints the bytes of the golden vector {code(v['name'])} ({v['sources'][0]['manual'] + ':' + str(v['sources'][0]['line']) if v['sources'] else 'derived'}):"
                    )
                    pg.code(f"command {v['hex']}", "text")
            pg.p(
                f"The whole program: `generated/{rel}`. The package's `decode` tool prints canonical JSON lines for any capture."
            )
        configure_section(docs, pg, lang)
