"""The runtime test protocol rendered by the real back ends, for the runtimes' unit tests.

Each runtime's unit tests (generator/targets/<lang>/runtime/tests/) run against the package the
back end renders from a tiny spec, not against hand-written stand-ins of the generated modules
(docs/runtime-contract.md). The spec, protocol `testproto` (tests/runtime_specs/README.md), comes
in two framings: framing_a/ (MIP-like framing, little-endian values) and framing_b/ (the other
branch of each framing choice: its protocol.yaml over framing a's sets and fields).

    python -m tests.runtime_specs.render LANG FRAMING      (FRAMING: a or b; from the project root)

renders the LANG package into build/runtime_specs/<FRAMING>/ and prints that directory (the package
is <dir>/<lang>/testproto/); with --tests (C, C++) it also copies the runtime's tests beside it, into
<dir>/tests-<lang>/, with the package's names. Only changed files are written, so builds
there stay incremental.
Exit status: 0 rendered, 1 the generator failed (its located message on stderr), 2 bad arguments.
"""

from __future__ import annotations

import shutil
import sys
from pathlib import Path

import generator.targets

ROOT = Path(__file__).resolve().parents[2]
SPECS = Path(__file__).resolve().parent
FRAMINGS = ("a", "b")
LANGS = tuple(generator.targets.NAMES)  # the target registry, never a list of its own
PROTOCOL = "testproto"
OUT = ROOT / "build" / "runtime_specs"


def spec_dir(framing: str) -> Path:
    """The spec directory of a framing: framing a's as it is; framing b's assembled under
    build/runtime_specs/spec_b/ from framing a's files and framing b's protocol.yaml."""
    if framing == "a":
        return SPECS / "framing_a"
    out = OUT / "spec_b"
    proto = out / PROTOCOL
    proto.mkdir(parents=True, exist_ok=True)
    wanted = {p.name: p for p in sorted((SPECS / "framing_a" / PROTOCOL).glob("*.yaml"))}
    wanted.update({p.name: p for p in sorted((SPECS / "framing_b" / PROTOCOL).glob("*.yaml"))})
    for old in proto.glob("*.yaml"):
        if old.name not in wanted:
            old.unlink()
    for name, src in wanted.items():
        dst = proto / name
        if not dst.exists() or dst.read_bytes() != src.read_bytes():
            shutil.copyfile(src, dst)
    return out


def render(lang: str, framing: str) -> Path:
    """Renders the LANG package of a framing with the generator's command line (python -m generator
    --spec DIR --out DIR --only LANG) into build/runtime_specs/<framing>/ and returns that directory
    (the package: <dir>/<lang>/testproto/). RuntimeError when the generator fails (its located
    message went to stderr)."""
    from generator.__main__ import main as generate

    if lang not in LANGS or framing not in FRAMINGS:
        raise ValueError(f"render({lang!r}, {framing!r}): expected a language of {LANGS} and a framing of {FRAMINGS}")
    out = OUT / framing
    status = generate(["--spec", str(spec_dir(framing)), "--out", str(out), "--only", lang])
    if status:
        raise RuntimeError(f"rendering the runtime test protocol (framing {framing}, {lang}) failed: status {status}")
    return out


def copy_tests(lang: str, out: Path) -> Path:
    """The runtime's own tests of a language whose runtime is written with neutral names (C:
    codec_/CODEC_, codec/; C++: protopkg), the top-level files of generator/targets/<lang>/runtime/
    tests/, copied into <out>/tests-<lang>/ (beside the package's <out>/<lang>/, which the generator
    owns and clears of files it did not render) with the test package's names, as the back end
    copies the runtime into a package (its runtime_replacements). Returns that directory."""
    if lang == "c":
        from generator.targets.c.backend import c_prefix, runtime_replacements

        replacements = runtime_replacements(c_prefix(PROTOCOL), PROTOCOL)
    elif lang == "cpp":
        from generator.targets.cpp.backend import ident, runtime_names

        replacements = runtime_names(PROTOCOL, ident(PROTOCOL))
    else:
        raise ValueError(f"copy_tests({lang!r}): only c and cpp")
    src = ROOT / "generator" / "targets" / lang / "runtime" / "tests"
    dst = out / f"tests-{lang}"
    dst.mkdir(parents=True, exist_ok=True)
    for f in sorted(src.iterdir()):
        if not f.is_file():
            continue
        text = f.read_text(encoding="utf-8")
        for old, new in replacements:
            text = text.replace(old, new)
        target = dst / f.name
        if not target.exists() or target.read_text(encoding="utf-8") != text:
            target.write_text(text, encoding="utf-8")
    return dst


def main(argv: list[str]) -> int:
    tests = argv[:1] == ["--tests"]
    argv = argv[1:] if tests else argv
    if len(argv) != 2 or argv[0] not in LANGS or argv[1] not in FRAMINGS:
        print(f"usage: python -m tests.runtime_specs.render [--tests] {{{','.join(LANGS)}}} {{a,b}}", file=sys.stderr)
        return 2
    try:
        out = render(argv[0], argv[1])
        if tests:
            copy_tests(argv[0], out)
    except RuntimeError as e:
        print(f"tests/runtime_specs/render.py: {e}", file=sys.stderr)
        return 1
    print(out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
