"""Differential testing from the IR: hostile random values and corrupted packets, four languages.

One round of `differential.py` per session, seeded by DIFF_SEED or a fresh random seed (printed
in the report header, at the end of the run and in every failure, with the replay command).
For every device group of every protocol:

1. the values stream (every layout with hostile values, docs/conformance.md §4 text written by
   the test): every `encode` writes exactly the test's bytes, every `decode` prints exactly the
   lines that went in (offsets included), and decode | encode gives back the bytes;
2. the mutants stream (those packets corrupted, checksums recomputed): every `decode` prints
   exactly what the reference decoder (`reference.py`, the contract read independently of the
   generator's templates) prints, error messages included, with and without --samples, and
   decode | encode gives back the bytes in every language;
   C, C++ and Rust decode both streams again with `--decoder straight` and `--decoder cached`
   (the straight-line decoders and the layout cache of issue 38): the same lines;
3. encoder input (§5): both streams' lines respelled (`respell.py`: key order, whitespace,
   escapes, number notation, hex case, other offsets and error texts) encode to the same bytes,
   and lines made invalid among them are refused by every encoder while the others are kept.

The reference decoder is itself checked against every golden vector first, and the round is
checked to reach every layout, enum value, union member, array length class and byte value.
`make differential ROUNDS=N [SEED=S]` runs many rounds.
"""

import shutil
from pathlib import Path

import pytest

from generator.spec import load_spec
from generator.vectors import load_corpus
from tests.conformance.differential import SEED, WORK, build_round, check_group, replay_command
from tests.conformance.reference import Reference

ROOT = Path(__file__).resolve().parents[2]
IR = load_spec()
PROTOCOLS = {p["name"]: p for p in IR["protocols"]}
GROUPS = build_round(list(PROTOCOLS.values()), SEED)
REPLAY = f"seed {SEED}; replay: {replay_command(SEED)}"


def test_reference_decoder_prints_every_golden_vector():
    """The oracle of the mutation pass gives the hand-derived text of every golden vector and stream case."""
    refs = {name: Reference(p) for name, p in PROTOCOLS.items()}
    bad = []
    vectors = load_corpus(IR, ROOT)
    for c in vectors:
        got = refs[c["protocol"]].decode_stream(bytes.fromhex(c["hex"]), c["device"])
        if got != c["expect"]:
            bad.append(f"{c['name']}:\n  want {c['expect']}\n  got  {got}")
    assert len(vectors) > 700
    assert not bad, f"{len(bad)} vectors:\n" + "\n".join(bad[:10])


def test_reference_sample_numbers_match_the_hand_derived_stream():
    """The oracle's §6 sample numbers on the hand-derived continuation stream of test_samples.py."""
    from tests.conformance.test_samples import STREAM

    lines = Reference(PROTOCOLS["mip"]).decode_stream(b"".join(p for p, _ in STREAM), samples=True)
    got = [int(x.split('"sample":')[1].split(",")[0]) if '"sample"' in x else None for x in lines]
    assert got == [n for _, n in STREAM]


def _walk(types: dict, params: list, prefix: str, out: dict) -> None:
    selectors = {p["type"]["selector"] for p in params if p["type"]["kind"] == "union"}
    for p in params:
        t = p["type"]
        path = prefix + p["name"]
        if p["count"] is not None and p["count"]["kind"] != "fixed":
            out["arrays"].add(path)
        if t["kind"] == "enum" and p["name"] not in selectors:
            out["enums"].add(t["name"])
        if t["kind"] == "string":
            out["strings"] = True
        if t["kind"] == "struct":
            _walk(types, types[t["name"]]["params"], path + ("[0]." if p["count"] else "."), out)
        if t["kind"] == "union":
            out["unions"].add(t["name"])
            for m in types[t["name"]]["members"]:
                if m["type"]:
                    _walk(types, types[m["type"]]["params"], path + ".", out)


@pytest.mark.parametrize("protocol", sorted(PROTOCOLS))
def test_round_covers_the_spec(protocol):
    """Enumerated from the IR here, independently of the generator's own walk: every layout in
    every set it can travel in, every named enum value, every union member, every variable array
    at length 0, 1 and maximum, every byte value in strings, function values the layout lacks."""
    proto = PROTOCOLS[protocol]
    types = {t["name"]: t for t in proto["types"]}
    gen = next(g.gen for g in GROUPS if g.protocol == protocol)
    samples = [f for g in GROUPS if g.protocol == protocol for p in g.packets for f in p.fields]
    reached = {(f.set_id, f.descriptor, f.device) for f in samples}
    sets = proto["sets"]
    defined = {s["id"] for s in sets}
    want = set()
    arrays: dict = {}
    enums, unions, strings = set(), set(), False
    for s in sets:
        for f in s["fields"]:
            for v in f["variants"]:
                want.add((s["id"], f["id"], v["device"] if len(f["variants"]) > 1 else None))
                acc = {"arrays": set(), "enums": enums, "unions": unions, "strings": False}
                _walk(types, v["params"], "", acc)
                strings |= acc["strings"]
                arrays[(s["id"], f["id"], v["device"])] = acc["arrays"]
    for r in proto["reserved_fields"]:
        want |= {(s["id"], r["id"], None) for s in sets if s["kind"] == r["applies_to"]}
        assert any(sid not in defined and d == r["id"] for sid, d, _ in reached), f"{r['name']} in an undefined set"
    if proto["shared_data"]:
        shared = next(s for s in sets if s["id"] == proto["shared_data"]["set"])
        data_sets = [s["id"] for s in sets if s["kind"] == "data"]
        want |= {(sid, f["id"], None) for sid in data_sets for f in shared["fields"]}
        shared_ids = {f["id"] for f in shared["fields"]}
        assert any(sid not in defined and d in shared_ids for sid, d, _ in reached), "shared fields in an undefined set"
    assert want <= reached, sorted(want - reached)[:20]

    missing = [(e, v["value"]) for e in sorted(enums) for v in types[e]["values"]]
    missing = [m for m in missing if m not in gen.covered["enum"]]
    assert not missing, f"enum values never generated: {missing[:20]}"
    unknown = [
        e
        for e in sorted(enums)
        if not {v for n, v in gen.covered["enum"] if n == e} - {v["value"] for v in types[e]["values"]}
    ]
    assert not unknown, f"enums never given a value they do not name: {unknown}"
    members = [(u, m["value"]) for u in sorted(unions) for m in types[u]["members"]]
    assert not [m for m in members if m not in gen.covered["union"]]
    lengths: dict = {}
    for layout, path, choice in gen.covered["length"]:
        lengths.setdefault((layout, path), set()).add(choice)
    short = [
        (k, p) for k, paths in arrays.items() for p in paths if not lengths.get((k, p), set()) >= {"zero", "one", "max"}
    ]
    assert not short, f"arrays not generated at length 0, 1 and maximum: {short[:10]}"
    if strings:
        assert gen.covered["bytes"] == set(range(256)), sorted(set(range(256)) - gen.covered["bytes"])
    if proto["function_selector"]:
        texts = "".join(f.values for f in samples)
        assert '"function":0,' in texts or '"function":0}' in texts, "no function selector value 0"


FAILED: list = []


@pytest.fixture(scope="module", autouse=True)
def _keep_failing_streams():
    """The streams of this seed (build/differential/SEED/) stay only when a group failed."""
    yield
    if not FAILED:
        shutil.rmtree(WORK / str(SEED), ignore_errors=True)


@pytest.mark.parametrize("group", GROUPS, ids=lambda g: g.gid)
def test_languages_agree_with_the_contract(group):
    """Values stream and mutants stream of one device group in all four languages."""
    fails, counts = check_group(group, SEED)
    FAILED.extend(fails)
    assert counts["samples"] > 50 and counts["mutants"] > 50, counts
    assert not fails, f"{len(fails)} disagreements ({REPLAY}):\n\n" + "\n\n".join(fails[:10])
