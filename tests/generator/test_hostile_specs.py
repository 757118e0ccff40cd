"""The hostile spec corpus (tests/generator/hostile_specs.py, issue 28) through the generator's
command line: each case exits 1 with `file:line:column: error:` lines only (and the closing count),
within seconds, the whole corpus in one process under a 2 GB address-space limit."""

from __future__ import annotations

import json
import re
import resource
import subprocess
import sys
from pathlib import Path

import pytest

from tests.generator.hostile_specs import corpus

ROOT = Path(__file__).resolve().parents[2]
LOCATED = re.compile(r"^spec/mscip/[a-z_]+\.yaml:[1-9][0-9]*:[1-9][0-9]*: error: \S")
SECONDS = 20  # per case, a guard against hangs; the slowest (250,000 values) takes 2 to 6 s
PEAK_MB = 1024


@pytest.fixture(scope="module")
def results(tmp_path_factory) -> dict:
    def limit() -> None:
        resource.setrlimit(resource.RLIMIT_AS, (2 << 30, 2 << 30))

    proc = subprocess.run(
        [sys.executable, "-m", "tests.generator.hostile_specs", str(tmp_path_factory.mktemp("hostile"))],
        cwd=ROOT,
        capture_output=True,
        text=True,
        preexec_fn=limit,
        timeout=600,
    )
    assert proc.returncode == 0, proc.stderr[-3000:]
    return json.loads(proc.stdout)


@pytest.mark.parametrize("case", sorted(corpus()))
def test_hostile_spec_is_refused_with_located_errors(results: dict, case: str) -> None:
    r = results["cases"][case]
    assert r["status"] == 1, r
    *errors, summary = r["stderr"]
    assert errors and all(LOCATED.match(line) for line in errors), r["stderr"]
    assert re.fullmatch(r"\d+ error\(s\) in the spec; nothing was generated\.", summary) or (
        len(r["stderr"]) == 1 and LOCATED.match(summary)
    ), r["stderr"]
    assert all(len(line) < 1000 for line in r["stderr"]), "a message quotes too much of the input"
    assert r["seconds"] < SECONDS, r["seconds"]


def test_the_corpus_runs_in_bounded_memory(results: dict) -> None:
    assert results["peak_rss_kb"] < PEAK_MB * 1024, results["peak_rss_kb"]


@pytest.mark.parametrize(
    ("case", "expected"),
    [
        ("nul_bytes", "protocol.yaml:1:13: error: invalid YAML: character U+0000 is not allowed"),
        ("huge_file", "protocol.yaml:1:1: error: the file is larger than 4194304 bytes"),
        ("empty", "protocol.yaml:1:1: error: empty file"),
        ("binary_junk", "error: the file is not UTF-8"),
        ("set_id_nan", "imu_data.yaml:4:6: error: set: nan has the wrong type (expected integer)"),
        (
            "field_id_huge",
            "error: fields[scaled_accel].id: 9999999999999999999999999999999999999999... (400 characters) is out of range",
        ),
        ("struct_cycle", "zz_hostile.yaml:7:12: error: type 'A' contains itself"),
        ("struct_chain_deep", "error: type 'S32' is nested more than 32 types deep (S0 > S1 > ...)"),
        ("u8_300", "zz_hostile.yaml:12:13: error: hostile.f: the largest encoding is 300 bytes of field data (a 300)"),
        ("four_matrices", "error: hostile.f: the largest encoding is 288 bytes of field data"),
        ("alias_bomb", "error: the file expands to more than 200000 values"),
    ],
)
def test_what_the_message_says(results: dict, case: str, expected: str) -> None:
    assert any(expected in line for line in results["cases"][case]["stderr"]), results["cases"][case]["stderr"]
