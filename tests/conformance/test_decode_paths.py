"""The new decode paths of issue 38 against the conformance corpus (docs/conformance.md §5).

C, C++ and Rust each have three decoders of a data packet: the general `decode_field` dispatch,
the straight-line decoder of the packet's set and the layout cache. Their `decode` tools take
`--decoder general|straight|cached`; with straight or cached the data packets go through that
decoder and its typed members are written by the same JSON writer, so the lines must be the
corpus's expected lines byte for byte:

- every case of the corpus (tests/vectors and tests/streams, the cases `test_cross_language.py`
  decodes), one process per case and decoder, the tool run directly once the runner built it
  (going through tests/conformance/decode per case would cost a build check per process);
- each protocol's mixed stream (every case, seeded garbage between them, as in
  `test_cross_language.py`), through tests/conformance/decode: the layout cache sees the same
  shapes again and decodes them from its shapes, and that output must equal the general one.

Python's decode has one decoder and refuses the option as any unknown option (exit 2).
"""

import os
import random
import subprocess
from pathlib import Path

import pytest

from generator.spec import load_spec
from generator.vectors import load_corpus
from tests.helpers.langs import langs

ROOT = Path(__file__).resolve().parents[2]
IR = load_spec()
VECTORS = load_corpus(IR, ROOT)
PACKAGES = {p["name"]: p["package"] for p in IR["protocols"]}
TYPED_LANGS = [lang for lang in ("c", "cpp", "rust") if lang in langs()]
DECODERS = ("straight", "cached")


def decode(lang: str, path: Path, *extra: str, protocol: str = "mip") -> subprocess.CompletedProcess:
    return subprocess.run(
        [str(ROOT / "tests/conformance/decode"), lang, str(path), *extra, "--protocol", protocol], capture_output=True
    )


def tool(lang: str, package: str) -> Path:
    """The decode tool where the language's runner (tests/lang/LANG.sh) builds it."""
    return (
        ROOT
        / {
            "c": f"build/c/{package}/{package}-decode",
            "cpp": f"build/cpp/{package}/{package}-decode",
            "rust": f"build/rust/target/release/{package}-decode",  # rust.sh's CARGO_TARGET_DIR
        }[lang]
    )


@pytest.fixture(scope="module")
def case_files(tmp_path_factory):
    d = tmp_path_factory.mktemp("cases")
    out = {}
    for i, c in enumerate(VECTORS):
        p = d / f"{i}.bin"
        p.write_bytes(bytes.fromhex(c["hex"]))
        out[c["name"]] = p
    return out


@pytest.mark.parametrize("lang", TYPED_LANGS)
def test_every_case_decodes_alike_with_the_straight_and_cached_decoders(lang, case_files):
    failures = []
    runs = 0
    for protocol, package in PACKAGES.items():
        cases = [c for c in VECTORS if c["protocol"] == protocol]
        if not cases:
            continue
        # Through the runner once: builds the tool, and the option reaches it.
        first = decode(lang, case_files[cases[0]["name"]], "--decoder", "cached", protocol=protocol)
        assert first.returncode == 0, f"{lang} decode --decoder cached: {first.stderr.decode(errors='replace')}"
        exe = tool(lang, package)
        assert exe.is_file(), f"{exe} not built by tests/lang/{lang}.sh"
        for c in cases:
            want = "".join(line + "\n" for line in c["expect"])
            device = ("--device", c["device"]) if c.get("device") else ()
            for decoder in DECODERS:
                proc = subprocess.run(
                    [str(exe), "--decoder", decoder, *device, str(case_files[c["name"]])], capture_output=True
                )
                runs += 1
                got = proc.stdout.decode(errors="replace")
                if proc.returncode != 0 or got != want:
                    failures.append(
                        f"{c['name']} ({c['file']}:{c['line']}) --decoder {decoder}, exit {proc.returncode}"
                        f" {proc.stderr.decode(errors='replace').strip()}\n  want {want!r}\n  got  {got!r}"
                    )
    assert runs >= 2 * 700
    assert not failures, f"{len(failures)} of {runs} runs fail in {lang}:\n" + "\n".join(failures[:20])


@pytest.fixture(scope="module")
def mixed_streams(tmp_path_factory):
    """Per protocol: its cases in order with seeded garbage between them (test_cross_language.py's
    stream), then the same cases again, so that the layout cache meets every shape twice."""
    seed = int(os.environ.get("CONFORMANCE_SEED", "20261121"))
    out = {}
    for proto in IR["protocols"]:
        rng = random.Random(seed)
        parts = []
        for _ in range(2):
            for c in VECTORS:
                if c["protocol"] == proto["name"]:
                    parts.append(bytes(rng.randrange(256) for _ in range(rng.randrange(0, 6))))
                    parts.append(bytes.fromhex(c["hex"]))
        p = tmp_path_factory.mktemp("stream") / f"mixed-{proto['name']}-{seed}.bin"
        p.write_bytes(b"".join(parts))
        out[proto["name"]] = p
    return out


@pytest.mark.parametrize("lang", TYPED_LANGS)
@pytest.mark.parametrize("protocol", list(PACKAGES))
def test_mixed_stream_decodes_alike_with_every_decoder(lang, protocol, mixed_streams):
    stream = mixed_streams[protocol]
    general = decode(lang, stream, protocol=protocol)
    assert general.returncode == 0, general.stderr.decode(errors="replace")
    assert general.stdout.count(b'"set":') >= 2 * len(
        [c for c in VECTORS if c["protocol"] == protocol and not c["rejected"]]
    )
    for decoder in ("general",) + DECODERS:
        for extra in ((), ("--samples",)):
            got = decode(lang, stream, "--decoder", decoder, *extra, protocol=protocol)
            want = general if not extra else decode(lang, stream, *extra, protocol=protocol)
            assert got.returncode == 0, f"--decoder {decoder}: {got.stderr.decode(errors='replace')}"
            assert got.stdout == want.stdout, f"{lang} --decoder {decoder} {' '.join(extra)} differs on {stream.name}"


@pytest.mark.parametrize("lang", TYPED_LANGS + ["python"])
def test_an_unknown_decoder_is_a_usage_error(lang, tmp_path):
    f = tmp_path / "empty.bin"
    f.write_bytes(b"")
    proc = decode(lang, f, "--decoder", "fastest")
    assert proc.returncode == 2
    assert proc.stdout == b""
    err = proc.stderr.decode(errors="replace")
    first = err.strip().splitlines()[0]
    assert "fastest" in first or "--decoder" in first, err
    assert "Traceback" not in err and "panicked" not in err
