"""The "getting started" page per language.

The code on these pages is cut from the example program each language back end generates into
its package (`examples/getting_started.*`, between `[build-command]` / `[parse-stream]` /
`[read-file]` and `[end]` comment lines). That program is built and run by the test suite
(tests/conformance/test_getting_started.py), so the snippets are code that compiles and works.
The output shown comes from the golden vectors, never from running the code here.

What a page says in its language's own words (how to vendor and build the package, the variable
that picks it in tests/lang/<lang>.sh, how to run the example from the package's directory) is
that target's GETTING_STARTED record (generator/targets/<lang>/facts.py): this module branches on
no language name, so a new target gets its own text or an error naming the missing fact.
"""

from __future__ import annotations

import json

from ..examples import END, PARTS, PROGRAM, SESSION_PARTS, SESSION_PROGRAM, example_command, session_example
from ..render import ToolError
from ..targets import TARGETS, GettingStarted
from .model import CONFIGURE_ANCHOR, Docs, Page, code, hx

EXTENSIONS = {name: TARGETS[name].EXTENSION for name in TARGETS}  # the target registry's languages
EXAMPLE_FILES = {lang: f"{lang}/{{pkg}}/examples/{PROGRAM}.{ext}" for lang, ext in EXTENSIONS.items()}
SESSION_EXAMPLE_FILES = {lang: f"{lang}/{{pkg}}/examples/{SESSION_PROGRAM}.{ext}" for lang, ext in EXTENSIONS.items()}
TITLES = {"build-command": "Build a command", "parse-stream": "Parse a stream", "read-file": "Decode a capture"}
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


def target_facts(lang: str) -> GettingStarted:
    """The getting-started record of the registered target lang; a ToolError naming the missing
    fact when its wing has none."""
    fact = getattr(TARGETS[lang], "GETTING_STARTED", None)
    if not isinstance(fact, GettingStarted):
        raise ToolError(
            f"target {lang} has no GETTING_STARTED (a generator.targets.GettingStarted in"
            f" generator/targets/{lang}/facts.py, exported by its __init__): its getting-started page needs it"
        )
    return fact


def say(lang: str, template: str, pkg: str) -> str:
    """One of lang's getting-started texts for the package pkg (GettingStarted's variables filled in)."""
    return template.format(pkg=pkg, PKG=pkg.upper(), **target_facts(lang).variables)


def _example_file(lang: str, program: str, pkg: str) -> str:
    """An example program's path under generated/ in lang's package pkg."""
    return f"{lang}/{pkg}/examples/{program}.{TARGETS[lang].EXTENSION}"


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
        rel = _example_file(lang, SESSION_PROGRAM, pkg)
        source = docs.examples.get(rel)
        pg.h(3, f"{p['title']} ({pkg})", f"{CONFIGURE_ANCHOR}-{p['name']}")
        if source is None:
            pg.p(f"The {TARGETS[lang].TITLE} session example of `{pkg}` is not generated yet.")
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
        + say(lang, target_facts(lang).simulator_note, pkg)
        + ":"
    )
    sim = f"python -m {pkg}.sim --device {ex['device']}"
    # How an outside user builds and runs the example from the package's own directory (no
    # repository): checked by tests/docs/test_outside_user.py (the Python and C commands run there).
    run = say(lang, target_facts(lang).outside_run, pkg)
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
    select = "" if pkg == "mipcodec" else f"{target_facts(lang).run_package_var}={pkg} "
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
            Page(
                f"getting-started/{lang}.md", f"Getting started in {TARGETS[lang].TITLE}", [("Reference", "README.md")]
            )
        )
        pg.p(
            "Every snippet on this page is cut from the example program generated into the package "
            "(`examples/getting_started`), which the test suite builds and runs on a stream of golden vectors "
            "(`tests/conformance/test_getting_started.py`). The packages of the other protocols have the same API "
            "under their own names."
        )
        for p in docs.ir["protocols"]:
            pkg = p["package"]
            rel = _example_file(lang, PROGRAM, pkg)
            source = docs.examples.get(rel)
            pg.h(2, f"{p['title']} ({pkg})", p["name"])
            facts = target_facts(lang)
            pg.p(say(lang, facts.install, pkg))
            # for the outside-user test (docs/conformance.md §11): GettingStarted.setup_outside
            pg.code(say(lang, facts.setup, pkg), facts.setup_lang, outside=facts.setup_outside)
            include = _include(lang, pkg, source or "")
            if include:
                pg.p(say(lang, facts.include_intro, pkg))
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
