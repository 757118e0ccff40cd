"""Spec files come from outside (overlays, vendor updates): malformed input is one located error
line and exit status 1, never a traceback or an exhausted machine (issue 28)."""

from __future__ import annotations

import resource
import subprocess
import sys
from pathlib import Path

import pytest

from generator import yamlpos
from generator.diagnostics import SpecError

ROOT = Path(__file__).resolve().parents[2]


def _bomb(levels: int = 9, fan: int = 9) -> str:
    """A 'billion laughs' file: each level lists the previous one `fan` times (fan**levels values)."""
    lines = ['l0: &l0 ["x", "x", "x", "x", "x", "x", "x", "x", "x"]']
    for i in range(1, levels):
        lines.append(f"l{i}: &l{i} [" + ", ".join([f"*l{i - 1}"] * fan) + "]")
    return "\n".join(lines) + "\n"


CASES = {
    "not_utf8": (b'protocol: x\nname: "\xff\xfe"\n', "2:8: error: the file is not UTF-8 (byte 0xFF)"),
    "deep": (("x: " + "[" * 5000 + "]" * 5000 + "\n").encode(), "error: values nested deeper than 64 levels"),
    "alias_bomb": (_bomb().encode(), "error: the file expands to more than 200000 values"),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_malformed_file_is_one_located_error(tmp_path: Path, case: str) -> None:
    data, expected = CASES[case]
    f = tmp_path / "bad.yaml"
    f.write_bytes(data)
    with pytest.raises(SpecError) as e:
        yamlpos.load(str(f), "bad.yaml")
    assert expected in str(e.value)
    assert str(e.value).startswith("bad.yaml:")


def test_aliases_within_limits_still_load(tmp_path: Path) -> None:
    f = tmp_path / "ok.yaml"
    f.write_text(_bomb(levels=3, fan=3))  # 3 ** 3 values: aliases are legitimate YAML
    data, _ = yamlpos.load(str(f))
    assert data["l2"] == [[["x"] * 9] * 3] * 3


@pytest.mark.parametrize("case", sorted(CASES))
def test_cli_prints_one_line_under_a_memory_limit(tmp_path: Path, case: str) -> None:
    spec = tmp_path / "spec" / "demo"
    spec.mkdir(parents=True)
    (spec / "protocol.yaml").write_bytes(CASES[case][0])

    def limit() -> None:  # 3 GB of address space: the alias bomb used to need 24 GB
        resource.setrlimit(resource.RLIMIT_AS, (3 << 30, 3 << 30))

    proc = subprocess.run(
        [sys.executable, "-m", "generator", "--spec", str(tmp_path / "spec"), "--validate-only"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        preexec_fn=limit,
        timeout=120,
    )
    assert proc.returncode == 1, proc.stderr
    assert "Traceback" not in proc.stderr
    errors = [line for line in proc.stderr.splitlines() if ": error: " in line]
    assert len(errors) == 1 and CASES[case][1].split("error: ")[1] in errors[0], proc.stderr
