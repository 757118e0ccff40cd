"""A spec that one back end cannot express is a spec error like any other (issue 36): one located
line `file:line:column: error: ...` and exit status 1, never a traceback.

Two enums GpsMode and GPSMode are two names in the spec and in C++, Python and Rust, but both
become the one C type <prefix>_gps_mode_t (C names types in snake case, docs/design.md), so the
C target's name check (generator/name_check.py, issue 37) refuses them at the second one's `name:`,
naming the first's, before the back end renders anything."""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
FIXTURE = ROOT / "tests" / "generator" / "fixtures" / "everything"


def _spec_with_enums(tmp_path: Path, *names: str) -> Path:
    spec = tmp_path / "spec"
    shutil.copytree(FIXTURE, spec)
    commands = spec / "demo" / "commands.yaml"
    text = commands.read_text(encoding="utf-8")
    added = "".join(
        f"  - name: {n}\n    type: u8\n    values: [{{name: v_{i}, value: 0}}]\n" for i, n in enumerate(names)
    )
    assert "\nenums:\n" in text
    commands.write_text(text.replace("\nenums:\n", "\nenums:\n" + added, 1), encoding="utf-8")
    return spec


def _generate(spec: Path, out: Path, langs: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "generator", "generate", "--spec", str(spec), "--out", str(out), "--langs", langs],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=300,
    )


def test_c_name_clash_is_one_located_line_and_exit_1(tmp_path: Path) -> None:
    spec = _spec_with_enums(tmp_path, "GpsMode", "GPSMode")
    r = _generate(spec, tmp_path / "out", "c")
    assert r.returncode == 1, r.stderr
    lines = r.stderr.splitlines()
    assert len(lines) == 1, r.stderr
    assert "Traceback" not in r.stderr
    # The enums are the file's first two (lines 7 and 10 after `enums:` at line 6): the error is
    # at the second one's `name:` value and names the first's.
    m = re.fullmatch(r"spec/demo/commands\.yaml:(\d+):(\d+): error: C: (.*)", lines[0])
    assert m, lines[0]
    assert (int(m[1]), int(m[2])) == (10, 11), lines[0]
    assert "democ_gps_mode_t" in m[3] and "type GpsMode" in m[3] and "type GPSMode" in m[3]
    assert "(the first at spec/demo/commands.yaml:7:11)" in m[3]
    assert not (tmp_path / "out" / "c").exists()  # nothing was written


def test_the_same_spec_renders_in_the_languages_that_keep_the_names_apart(tmp_path: Path) -> None:
    # The clash is the C back end's alone: it is not a front-end rule.
    spec = _spec_with_enums(tmp_path, "GpsMode", "GPSMode")
    r = _generate(spec, tmp_path / "out", "python")
    assert r.returncode == 0, r.stderr
    assert (tmp_path / "out" / "python" / "democodec").is_dir()


def test_distinct_names_render_in_c(tmp_path: Path) -> None:
    # The control: two enums whose C names differ pass the C back end.
    spec = _spec_with_enums(tmp_path, "GpsMode", "GnssMode")
    r = _generate(spec, tmp_path / "out", "c")
    assert r.returncode == 0, r.stderr
    header = (tmp_path / "out" / "c" / "democodec" / "include" / "democodec" / "types.h").read_text()
    assert "democ_gps_mode_t" in header and "democ_gnss_mode_t" in header
