"""Every field round-trips in every language, for values generated from the spec.

`samples.py` builds, from the IR alone, packets that exercise every function selector, enum
value, union member, optional parameter and counted-array length (0, 1, maximum) of every
command, response and data field. For each device group:

1. every language's `encode` turns the JSON lines into bytes, and the four byte streams must be
   identical (the languages agree on every byte);
2. every language's `decode` turns those bytes back into exactly the JSON lines that went in
   (offsets aside), so encode -> decode -> encode gives the same bytes.
"""

import re
import subprocess
from pathlib import Path

import pytest

from generator.spec import load_spec
from tests.conformance.samples import field_samples
from tests.helpers.langs import langs

ROOT = Path(__file__).resolve().parents[2]
LANGS = langs()  # the target registry (generator/targets/__init__.py)
PROTOCOLS = {p["name"]: p for p in load_spec()["protocols"]}
SAMPLES = {name: field_samples(p) for name, p in PROTOCOLS.items()}
# (protocol, device group): the samples of one protocol for one device ("" = any device).
GROUPS = sorted({(name, s.device or "") for name, samples in SAMPLES.items() for s in samples})
OFFSET = re.compile(r'^\{"offset":\d+,')


def _group(group: tuple) -> list:
    protocol, device = group
    return [s for s in SAMPLES[protocol] if (s.device or "") == device]


def _gid(group: tuple) -> str:
    return f"{group[0]}-{group[1] or 'any'}"


def _run(tool: str, lang: str, data: bytes, *args: str, protocol: str = "mip") -> subprocess.CompletedProcess:
    return subprocess.run(
        [str(ROOT / "tests/conformance" / tool), lang, *args, "--protocol", protocol], input=data, capture_output=True
    )


def _strip(line: str) -> str:
    return OFFSET.sub('{"offset":0,', line)


@pytest.mark.parametrize("protocol", sorted(PROTOCOLS))
def test_samples_cover_the_spec(protocol):
    """The generator of samples reaches every field layout of the spec (so a new set is tested)."""
    proto = PROTOCOLS[protocol]
    layouts = {(s["name"], f["id"], v["device"]) for s in proto["sets"] for f in s["fields"] for v in f["variants"]}
    names = {s["id"]: s["name"] for s in proto["sets"]}
    shared = [s["name"] for s in proto["sets"] if s["shared"]]
    reached = {(names[s.set_id], s.descriptor, s.device) for s in SAMPLES[protocol]}
    reached |= {(n, d, dev) for (_, d, dev) in reached for n in shared}
    assert layouts <= reached, sorted(layouts - reached)[:20]


@pytest.fixture(scope="module")
def encoded(tmp_path_factory):
    """{device group: {lang: bytes}} plus the JSON text that went in."""
    d = tmp_path_factory.mktemp("roundtrip")
    out = {}
    for g in GROUPS:
        samples = _group(g)
        text = "".join(s.json_line(0) + "\n" for s in samples)
        (d / f"samples-{_gid(g)}.jsonl").write_text(text)
        per_lang = {}
        for lang in LANGS:
            proc = _run("encode", lang, text.encode(), protocol=g[0])
            errors = proc.stderr.decode(errors="replace").splitlines()
            # Name the samples the encoder refused (messages start with "line N:").
            named = []
            for e in errors:
                m = re.match(r"\D*(\d+)", e)
                if m and 1 <= int(m.group(1)) <= len(samples):
                    named.append(f"{samples[int(m.group(1)) - 1].what}: {e}")
                else:
                    named.append(e)
            assert proc.returncode == 0, f"{lang} encode refused {len(errors)} samples:\n" + "\n".join(named[:30])
            per_lang[lang] = proc.stdout
        out[g] = (samples, text, per_lang)
    return out


@pytest.mark.parametrize("group", GROUPS, ids=_gid)
def test_languages_encode_identical_bytes(encoded, group):
    samples, _, per_lang = encoded[group]
    ref = per_lang["python"]
    assert ref, "no bytes"
    for lang in LANGS:
        assert per_lang[lang] == ref, f"{lang} bytes differ from python for group {_gid(group)}"


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("group", GROUPS, ids=_gid)
def test_decode_gives_back_the_samples(encoded, group, lang, tmp_path):
    samples, text, per_lang = encoded[group]
    f = tmp_path / "stream.bin"
    f.write_bytes(per_lang["python"])
    args = (str(f),) + (("--device", group[1]) if group[1] else ())
    proc = _run("decode", lang, b"", *args, protocol=group[0])
    assert proc.returncode == 0, proc.stderr.decode(errors="replace")
    got = [_strip(x) for x in proc.stdout.decode().splitlines()]
    want = [_strip(x) for x in text.splitlines()]
    bad = [f"{s.what}:\n  want {w}\n  got  {g}" for s, w, g in zip(samples, want, got) if w != g]
    assert len(got) == len(want), f"{lang}: {len(got)} packets decoded, {len(want)} encoded"
    assert not bad, f"{len(bad)} of {len(want)} samples do not round-trip in {lang}:\n" + "\n".join(bad[:20])
    back = _run("encode", lang, proc.stdout, protocol=group[0])
    assert back.returncode == 0 and back.stdout == per_lang["python"], f"{lang}: decode | encode changed the bytes"
