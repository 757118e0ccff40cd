"""The generator as a tool (issue 24): `mipgen generate` with overlays, `mipgen diff`, `mipgen lint`,
and quiet regenerations (adding one descriptor changes its own files plus indexes)."""

from __future__ import annotations

import copy
import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from generator import wirediff
from generator.cli import main as mipgen
from generator.diagnostics import SpecErrors
from generator.export import ir_to_json
from generator.lint import yaml_traps
from generator.release import load_release
from generator.spec import ROOT, load_spec
from generator.targets import TARGETS

OVERLAY = Path(__file__).parent / "fixtures" / "overlay"


@pytest.fixture(scope="module")
def project_ir():
    return load_spec()


def _overlay_copy(tmp_path: Path) -> Path:
    dest = tmp_path / "overlay"
    shutil.copytree(OVERLAY, dest)
    return dest


# ------------------------------------------------------------------------------ overlays
def test_overlay_adds_a_device_with_its_own_descriptors_and_an_enum_value(project_ir):
    ir = load_spec(overlays=[OVERLAY])
    mip = next(p for p in ir["protocols"] if p["name"] == "mip")
    base = next(p for p in project_ir["protocols"] if p["name"] == "mip")
    assert [d["id"] for d in mip["devices"]] == [d["id"] for d in base["devices"]] + ["gq9_test"]
    sensor = next(s for s in mip["sets"] if s["id"] == 0x80)
    added = {f["name"]: f["devices"] for f in sensor["fields"] if f["id"] in (0x50, 0x51)}
    assert added == {"board_temperature": ["gq9_test"], "vibration": ["gq9_test"]}
    old_fields = next(s for s in base["sets"] if s["id"] == 0x80)["fields"]
    assert len(sensor["fields"]) == len(old_fields) + 2
    ack = next(t for t in mip["types"] if t["name"] == "AckCode")
    assert ack["values"][-1]["name"] == "busy" and ack["values"][-1]["devices"] == ["gq9_test"]
    # The other protocol is untouched.
    assert ir["protocols"][1] == project_ir["protocols"][1]


def test_overlay_redefining_a_descriptor_is_a_located_error_naming_both_places(tmp_path):
    o = _overlay_copy(tmp_path)
    f = o / "mip" / "sensor_gq9.yaml"
    f.write_text(f.read_text().replace("id: 0x50", "id: 0x04"))
    with pytest.raises(SpecErrors) as e:
        load_spec(overlays=[o])
    (msg,) = [str(x) for x in e.value.errors]
    assert msg.startswith("overlay/mip/sensor_gq9.yaml:9:")
    assert "descriptor 0x04 is used by both 'scaled_accel' and 'board_temperature'" in msg
    assert "the first at spec/mip/sensor.yaml:" in msg


def test_overlay_extension_errors_are_located_in_the_overlay(tmp_path):
    o = _overlay_copy(tmp_path)
    f = o / "mip" / "devices.yaml"
    text = f.read_text()
    f.write_text(text.replace("name: AckCode", "name: AckCod").replace("gq9-test.txt", "3dm-gx5-45-dcp.txt"))
    with pytest.raises(SpecErrors) as e:
        load_spec(overlays=[o])
    msgs = [str(x) for x in e.value.errors]
    assert any(
        m.startswith("overlay/mip/devices.yaml:5:") and "manual '3dm-gx5-45-dcp.txt' is already defined" in m
        for m in msgs
    ), msgs
    assert any("no enum named 'AckCod' to extend; did you mean 'AckCode'?" in m for m in msgs), msgs
    # A value that clashes with the spec's is reported by the IR passes, located in the overlay.
    f.write_text(text.replace("value: 0x07", "value: 0x01"))
    (o / "mip" / "sensor_gq9.yaml").unlink()
    with pytest.raises(SpecErrors) as e:
        load_spec(overlays=[o])
    assert any(str(x).startswith("overlay/mip/devices.yaml:9:") for x in e.value.errors), e.value.errors


def test_mipgen_generate_with_an_overlay_renders_the_new_descriptors(tmp_path):
    out = tmp_path / "out"
    rc = mipgen(["generate", "--spec", str(ROOT / "spec"), str(OVERLAY), "--out", str(out), "--langs", "python"])
    assert rc == 0
    sensor = (out / "python" / "mipcodec" / "mipcodec" / "sensor.py").read_text()
    assert "class BoardTemperature" in sensor and "class Vibration" in sensor
    assert not (out / "c").exists()
    assert not (ROOT / "docs" / "errata.md").read_text().count("gq9")


def test_mipgen_generate_usage_errors_exit_2(tmp_path, capsys):
    for argv in (
        ["generate", "--spec", str(ROOT / "spec"), str(OVERLAY)],  # no --out for a user's spec
        ["generate", "--langs", "cobol", "--out", str(tmp_path)],
        ["generate", "--spec", str(tmp_path / "missing"), "--out", str(tmp_path)],
    ):
        with pytest.raises(SystemExit) as e:
            mipgen(argv)
        assert e.value.code == 2
    err = capsys.readouterr().err
    assert "--out DIR is needed" in err and "unknown cobol" in err and "no such directory" in err


# ------------------------------------------------------------------------------ diff
def _mip(ir):
    return next(p for p in ir["protocols"] if p["name"] == "mip")


def _field(ir, set_id, fid):
    s = next(s for s in _mip(ir)["sets"] if s["id"] == set_id)
    return next(f for f in s["fields"] if f["id"] == fid)


def _kinds(changes):
    return sorted({(c.kind, c.where, c.what) for c in changes})


def test_diff_of_a_spec_with_itself_is_empty(project_ir):
    assert wirediff.diff(project_ir, copy.deepcopy(project_ir)) == []


def test_diff_layout_change_names_parameter_types_and_offsets(project_ir):
    new = copy.deepcopy(project_ir)
    q = _field(new, 0x80, 0x04)["variants"][0]["params"][0]
    q["type"] = {**q["type"], "name": "double"}
    (c,) = wirediff.diff(project_ir, new)
    assert c.kind == wirediff.BREAKING and c.where == "0x80,0x04 sensor.scaled_accel"
    assert c.detail == {
        "parameter": "scaled_accel",
        "old_type": "float[3]",
        "new_type": "double[3]",
        "old_offset": 0,
        "new_offset": 0,
    }


def test_diff_classifies_every_kind_of_change(project_ir):
    old = project_ir
    new = copy.deepcopy(old)
    mip = _mip(new)
    sensor = next(s for s in mip["sets"] if s["id"] == 0x80)
    added = copy.deepcopy(sensor["fields"][0])
    added.update(id=0x60, name="new_field")
    sensor["fields"].append(added)  # descriptor added
    sensor["fields"] = [f for f in sensor["fields"] if f["id"] != 0x05]  # descriptor removed
    _field(new, 0x80, 0x06)["name"] = "scaled_magnetometer"  # renamed
    ack = next(t for t in mip["types"] if t["name"] == "AckCode")
    ack["values"].append({**ack["values"][0], "name": "busy", "value": 0x07})  # value added
    ack["values"][1]["name"] = "unknown_cmd"  # value renamed
    flags = next(t for t in mip["types"] if t["name"] == "OverrangeStatusFlags")
    flags["members"] = [m for m in flags["members"] if m["name"] != "press"]  # bit removed
    cmd = next(f for s in mip["sets"] for f in s["fields"] if f["variants"][0]["functions"])
    cmd["variants"][0]["functions"] = cmd["variants"][0]["functions"][:-1]  # function removed
    mip["devices"].append({"id": "gq9", "title": "GQ9", "manual": "gq9.txt"})  # device added
    _field(new, 0x80, 0x40)["devices"] = ["cv7_ins", "gx5_45"]  # device support widened
    changes = wirediff.diff(old, new)
    got = {(c.kind, c.where, c.what.split(" (")[0]) for c in changes}
    assert (wirediff.COMPATIBLE, "0x80,0x60 sensor.new_field", "data descriptor added") in got
    assert (wirediff.BREAKING, "0x80,0x05 sensor.scaled_gyro", "data descriptor removed") in got
    assert (wirediff.COMPATIBLE, "enum AckCode", "value 7") in got
    assert (wirediff.BREAKING, "bitfield OverrangeStatusFlags", "bit 12") in got
    assert (wirediff.COMPATIBLE, "device gq9", "device gq9 added") in got
    assert (wirediff.COMPATIBLE, "0x80,0x40 sensor.odometer_data", "now also on gx5_45") in got
    assert any(c.kind == wirediff.BREAKING and c.what.startswith("function ") and "removed" in c.what for c in changes)
    rename = next(c for c in changes if c.what.startswith("descriptor renamed"))
    assert rename.kind == wirediff.API
    assert rename.names["c"] == ["mipc_sensor_scaled_mag_t -> mipc_sensor_scaled_magnetometer_t"]
    assert rename.names["python"] == ["mipcodec.sensor.ScaledMag -> mipcodec.sensor.ScaledMagnetometer"]
    value = next(c for c in changes if c.what.startswith("value 1 renamed"))
    assert value.kind == wirediff.API and value.names["rust"] == [
        "mipcodec::AckCode::UNKNOWN_COMMAND -> mipcodec::AckCode::UNKNOWN_CMD"
    ]
    assert wirediff.verdict(changes) == wirediff.BREAKING
    assert wirediff.bump(changes, "0.1.0") == "minor" and wirediff.bump(changes, "1.2.0") == "major"
    only_added = [c for c in changes if c.kind == wirediff.COMPATIBLE]
    assert wirediff.bump(only_added, "1.2.0") == "minor" and wirediff.bump(only_added, "0.1.0") == "patch"
    log = wirediff.changelog(changes, "0.2.0")
    assert log.startswith("## 0.2.0") and "### Breaking (wire)" in log and "### Added" in log


def test_diff_optional_trailing_command_parameter_is_compatible_but_data_parameter_breaks(project_ir):
    new = copy.deepcopy(project_ir)
    data = _field(new, 0x80, 0x04)["variants"][0]["params"]
    data.append({**data[0], "name": "extra", "offset": 12})
    (c,) = wirediff.diff(project_ir, new)
    assert c.kind == wirediff.BREAKING and "old decoders reject" in c.what


def test_diff_cli_on_directories_and_revisions(tmp_path, capsys, monkeypatch):
    new = tmp_path / "new"
    shutil.copytree(ROOT / "spec", new)
    sensor = new / "mip" / "sensor.yaml"
    sensor.write_text(
        sensor.read_text().replace("{name: valid_flags, type: OdometerDataValidFlags", "{name: valid_flags, type: u32")
    )
    assert mipgen(["diff", str(ROOT / "spec"), str(new), "--json"]) == 1
    doc = json.loads(capsys.readouterr().out)
    assert doc["verdict"] == "wire-breaking" and doc["counts"]["wire-breaking"] == 1
    assert doc["changes"][0]["detail"] == {
        "parameter": "valid_flags",
        "old_type": "OdometerDataValidFlags",
        "new_type": "u32",
        "old_offset": 8,
        "new_offset": 8,
    }
    # Two git revisions of a repository of our own (no history of this one needed: CI's clones
    # may be shallow): the project's spec without, then with, issue 23's optional_for (read/save/
    # load/default commands may leave their trailing parameters out): compatible on the wire.
    repo = tmp_path / "repo"
    shutil.copytree(ROOT / "spec", repo / "spec")
    streaming = repo / "spec" / "mip" / "3dm_streaming.yaml"
    current = streaming.read_text()
    # (the `ignored:` facts of issue 51 came later and need optional_for: gone with it)
    before = re.sub(r", optional_for: \[[^\]]*\]", "", current)
    streaming.write_text(re.sub(r", ignored: \{functions: \[[^\]]*\], source: \{[^}]*\}\}", "", before))
    git = [
        "git",
        "-C",
        str(repo),
        "-c",
        "user.name=t",
        "-c",
        "user.email=t@example.invalid",
        "-c",
        "commit.gpgsign=false",
    ]
    subprocess.run([*git, "init", "-q"], check=True)
    subprocess.run([*git, "add", "spec"], check=True)
    subprocess.run([*git, "commit", "-q", "-m", "before optional_for"], check=True)
    streaming.write_text(current)
    subprocess.run([*git, "commit", "-q", "-am", "optional_for"], check=True)
    monkeypatch.chdir(repo)
    assert mipgen(["diff", "HEAD~1", "HEAD", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    # 14: GNSS constellation settings' `settings` is written in block style since issue 51 gave it
    # its factory records, so the flow-style substitution above leaves its optional_for in place
    assert doc["verdict"] == "wire-compatible" and doc["counts"]["wire-compatible"] == 14
    assert all(c["what"].endswith("is now optional") for c in doc["changes"] if c["kind"] == "wire-compatible")
    assert {c["where"].split()[0] for c in doc["changes"]} == {
        "0x0C,0x08",
        "0x0C,0x09",
        "0x0C,0x0A",
        "0x0C,0x11",
        "0x0C,0x21",
        "0x0C,0x23",
        "0x0C,0x24",
    }
    assert mipgen(["diff", "no-such-revision-xyz", str(ROOT / "spec")]) == 2
    assert "neither a spec directory nor a git revision" in capsys.readouterr().err


# ------------------------------------------------------------------------------ lint
def test_lint_finds_unquoted_booleans(tmp_path):
    f = tmp_path / "x.yaml"
    f.write_text('a: on\nb: "off"\nc: [yes, No]\nd: true\n')
    got = yaml_traps(f, "x.yaml")
    assert got == [
        "x.yaml:1:4: warning: unquoted 'on' is read as the boolean true; write \"on\" if you mean the word",
        "x.yaml:3:5: warning: unquoted 'yes' is read as the boolean true; write \"yes\" if you mean the word",
        "x.yaml:3:10: warning: unquoted 'No' is read as the boolean false; write \"No\" if you mean the word",
    ]


def test_lint_lists_descriptors_without_vectors(capsys):
    assert mipgen(["lint"]) == 0
    out = capsys.readouterr().out
    assert "descriptors without a golden vector (" in out
    missing = [line for line in out.splitlines() if line.startswith("  mip 0x") or line.startswith("  mscip 0x")]
    assert missing and all("(" in m for m in missing)
    assert (
        out.rstrip().splitlines()[-1] == f"lint: 0 YAML trap(s), {len(missing)} descriptor(s) without a golden vector"
    )


# ------------------------------------------------------------------------------ quiet regeneration
def _render_all(spec: Path) -> dict[str, str]:
    """Every back end's files for a spec, unformatted (the formatters cost more than the
    rendering and do not change which lines a template prints)."""
    ir = load_spec(spec, root=spec.parent)
    release = load_release(spec)
    files = {"ir.json": ir_to_json(ir)}
    for mod in TARGETS.values():
        files.update(mod.render(ir, [], release))
    return files


def test_adding_one_descriptor_changes_only_its_files_and_indexes(tmp_path):
    spec = tmp_path / "spec"
    shutil.copytree(ROOT / "spec", spec)
    before = _render_all(spec)
    sensor = spec / "mip" / "sensor.yaml"
    sensor.write_text(
        sensor.read_text()
        + """
  - id: 0x41
    name: wheel_temperature
    role: data
    title: Wheel temperature
    description: A descriptor added by the quiet-regeneration test.
    sources:
      - {manual: 3dm-cv7-ins-docs.txt, line: 6560, title: "Wheel temperature (0x80,0x41)"}
    params:
      - {name: temperature, type: float, units: degC, description: "Temperature."}
"""
    )
    after = _render_all(spec)
    assert set(before) <= set(after)
    changed = sorted(rel for rel in after if before.get(rel) != after[rel])
    for side, files in (("a", before), ("b", after)):
        for rel in changed:
            path = tmp_path / side / rel
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(files.get(rel, ""))
    # git counts the lines faster than difflib does on ir.json.
    numstat = subprocess.run(
        ["git", "diff", "--no-index", "--numstat", str(tmp_path / "a"), str(tmp_path / "b")],
        capture_output=True,
        text=True,
    ).stdout
    removed = sum(int(line.split("\t")[1]) for line in numstat.splitlines())
    assert len(numstat.splitlines()) == len(changed)
    # Only the sensor set's own files and the indexes (dispatch, registries, lookup tables, the
    # IR, the version stamps that carry the spec hash, the typed test cases, the simulator's tables,
    # the per-device capabilities tables)
    # change.
    index_words = (
        "sensor",
        "dispatch",
        "lookup",
        "registry",
        "_columns",
        "_mcap_schemas",  # the JSON Schemas of the data fields (the MCAP export's JSON topics)
        "ir.json",
        "version",
        "README",
        "__init__",
        "lib.rs",
        "layouts_internal",
        "typed_cases",
        "spec.rs",
        "_sim",
        "_settings",  # the device command line's tables: the data fields' sizes (Python)
        "device_facts",  # the same tables of the C device tool
        "capabilities",  # the per-device tables of what each model supports (Python)
        "devices.hpp",  # the same tables in C++ (C and Rust hold them in dispatch)
    )
    assert all(any(w in rel for w in index_words) for rel in changed), [
        r for r in changed if not any(w in r for w in index_words)
    ]
    # 26 before the capabilities tables (Python, C++ devices.hpp) and the C device tool's tables;
    # 31 since the C++ package compiles like a library (the set's src/fields/sensor.cpp and
    # sensor_json.cpp beside its headers); 32 with the C++ straight-line packet decoders of issue 38
    # (the set's packets/sensor.hpp); 33 with the Python package's JSON Schemas (_mcap_schemas.py,
    # issue 54)
    assert len(changed) <= 33, changed
    # Before issue 24 the C layout ids (`= 236`) and the k_fields index comments renumbered:
    # 455 lines removed after formatting. Now the index tables alone shift.
    # 201 with issue 38's packet decoders and layout caches (173 of them C's dispatch.c index
    # tables, the rest one or two lines per index file)
    assert removed <= 210, removed


def test_python_m_generator_subcommands_are_mipgen():
    proc = subprocess.run(
        [sys.executable, "-m", "generator", "diff", "--help"], cwd=ROOT, capture_output=True, text=True
    )
    assert proc.returncode == 0 and "OLD" in proc.stdout.upper()


# ------------------------------------------------------------------------------ issue 39: tool gaps
def test_diff_of_the_spec_with_the_spec_plus_an_overlay(capsys):
    """A user's overlay compared with the spec it extends, without merging a copy by hand."""
    spec = str(ROOT / "spec")
    assert mipgen(["diff", spec, spec, "--new-overlay", str(OVERLAY), "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    got = {(c["kind"], c["where"]) for c in doc["changes"]}
    assert ("wire-compatible", "device gq9_test") in got
    assert ("wire-compatible", "0x80,0x50 sensor.board_temperature") in got
    assert ("wire-compatible", "0x80,0x51 sensor.vibration") in got
    assert doc["verdict"] == "wire-compatible"
    # The other way round, the overlay's additions are removals: wire-breaking.
    assert mipgen(["diff", spec, spec, "--old-overlay", str(OVERLAY)]) == 1
    out = capsys.readouterr().out
    assert f"+ {OVERLAY}" in out and "data descriptor removed" in out
    assert mipgen(["diff", spec, spec, "--new-overlay", str(ROOT / "no-such-overlay")]) == 2
    assert "overlay " in capsys.readouterr().err


def test_lint_of_a_users_spec_without_vectors_says_they_were_not_checked(capsys):
    """An installed mipgen with a user's spec has no vectors: one line, not every descriptor."""
    fixture = ROOT / "tests" / "generator" / "fixtures" / "everything"
    assert mipgen(["lint", "--spec", str(fixture)]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[-2].startswith("golden vectors: not checked (") and "--vectors DIR" in out[-2]
    assert out[-1] == "lint: 0 YAML trap(s), golden vectors not checked"
    assert not any(line.startswith("  ") for line in out)
    # With its vectors, the descriptors they do not cover are listed (fewer than all of them).
    assert mipgen(["lint", "--spec", str(fixture), "--vectors", str(ROOT / "tests" / "golden" / "vectors")]) == 0
    out = capsys.readouterr().out.splitlines()
    header = next(line for line in out if line.startswith("descriptors without a golden vector ("))
    listed, total = re.match(r"descriptors without a golden vector \((\d+) of (\d+);", header).groups()
    assert int(listed) < int(total)
    assert out[-1] == f"lint: 0 YAML trap(s), {listed} descriptor(s) without a golden vector"


def test_generate_prints_what_changed(tmp_path, capsys):
    out = tmp_path / "out"
    argv = ["generate", "--spec", str(ROOT / "spec"), str(OVERLAY), "--out", str(out), "--langs", "python"]
    assert mipgen(argv) == 0
    first = capsys.readouterr().err.splitlines()
    assert re.fullmatch(r".*out: 0 changed, (\d+) added, 0 removed \(\1 files\)", first[0]), first[0]
    assert any(line.startswith("  A python/") for line in first[1:])
    assert mipgen(argv) == 0
    assert re.fullmatch(r".*out: up to date \(\d+ files\)", capsys.readouterr().err.strip())
    sensor = out / "python" / "mipcodec" / "mipcodec" / "sensor.py"
    sensor.write_text("stale\n")
    (out / "python" / "left-over.py").write_text("x = 1\n")
    assert mipgen(argv) == 0
    lines = capsys.readouterr().err.splitlines()
    assert re.fullmatch(r".*out: 1 changed, 0 added, 1 removed \(\d+ files\)", lines[0]), lines[0]
    assert lines[1:] == ["  D python/left-over.py", "  M python/mipcodec/mipcodec/sensor.py"]


# ------------------------------------------------------------------------------ a spec with no protocol
@pytest.mark.parametrize(
    "argv",
    [
        ["generate", "--spec", "{spec}", "--out", "{out}"],
        ["generate", "--spec", "{spec}", "--out", "{out}", "--validate-only"],
        ["lint", "--spec", "{spec}"],
    ],
)
@pytest.mark.parametrize("given", ["protocol_dir", "empty_dir"])
def test_a_spec_with_no_protocol_is_one_error_line_and_writes_nothing(tmp_path, capsys, argv, given):
    """`--spec spec/mip` (a protocol's directory given for the spec root) once wrote an ir.json with
    no protocol and exited 0 (issue 49): now one error line, exit 1, and no output directory."""
    if given == "protocol_dir":
        spec = ROOT / "spec" / "mip"
    else:
        spec = tmp_path / "empty"
        spec.mkdir()
    out = tmp_path / "out"
    assert mipgen([a.format(spec=spec, out=out) for a in argv]) == 1
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1 and err[0].startswith("error: spec directory ") and "has no protocol directory" in err[0]
    if given == "protocol_dir":
        assert "give its parent (" in err[0] and "looks like one protocol's directory" in err[0]
    assert not out.exists()


def test_diff_of_a_spec_with_no_protocol_is_a_tool_error(tmp_path, capsys):
    assert mipgen(["diff", str(ROOT / "spec" / "mip"), str(ROOT / "spec")]) == 2
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1 and "does not load" in err[0] and "has no protocol directory" in err[0]


def test_the_old_entry_point_refuses_a_spec_with_no_protocol(tmp_path, capsys):
    from generator.__main__ import main as old_main

    out = tmp_path / "out"
    assert old_main(["--spec", str(ROOT / "spec" / "mip"), "--out", str(out)]) == 1
    assert len(capsys.readouterr().err.splitlines()) == 1 and not out.exists()
