"""The defaults inventory (generator/defaults_audit.py, part of `make audit`) on a tiny made-up
manual: which lines state a default, and each one transcribed, decided or reported uncovered."""

from __future__ import annotations

from generator import defaults_audit
from generator.defaults_audit import audit, stated_lines

MANUAL = "\n".join(
    [
        "1 Stream Control (0x0C, 0x11)",  # 1
        "Function Selector u8 This command supports: Write Read Save Load Default [WRSLD]",  # 2: selector name
        "0x05 - Reset to factory default settings",  # 3: selector name
        "The default for the device is all streams enabled.",  # 4: transcribed
        "0x01 - Portable (default)",  # 5: decided
        "Baud rates: 9600, 115200 (<i>default</i>)",  # 6: uncovered
        "Desc Set: when function is SAVE, LOAD, or DEFAULT, 0 applies to all.",  # 7: selector prose
        "Factory default setting is GPS enabled.",  # 8: transcribed through `also`
        "No word of it here.",  # 9
    ]
)


def _ir(notes_lines: list[int], default: dict | None, kind: str = "decision", manual: str = "a.txt") -> dict:
    """A one-command protocol: a parameter with `default` (IR shape) and a decision note listing
    `notes_lines` of manual a.txt."""
    param = {"name": "enable", "type": {"kind": "primitive", "name": "bool"}, "notes": [], "default": default}
    note = {
        "kind": kind,
        "text": "Not a parameter's value.",
        "lines": [{"manual": manual, "line": n} for n in notes_lines],
    }
    field = {
        "id": 0x11,
        "name": "stream",
        "notes": [note],
        "sources": [],
        "variants": [{"device": None, "notes": [], "sources": [], "params": [param]}],
    }
    proto = {
        "name": "p",
        "types": [],
        "reserved_fields": [],
        "field_layouts": [],
        "sets": [{"id": 0x0C, "name": "cmd", "notes": [], "sources": [], "fields": [field]}],
    }
    return {"protocols": [proto]}


def _default(line: int, also: tuple[int, ...] = ()) -> dict:
    return {
        "value": True,
        "source": {"manual": "a.txt", "line": line},
        "also": [{"manual": "a.txt", "line": n} for n in also],
        "devices": ["dev"],
    }


def test_stated_lines_leave_out_the_function_selector_names():
    stated, selector = stated_lines(MANUAL)
    assert [n for n, _ in stated] == [4, 5, 6, 8]
    assert selector == 3  # lines 2, 3 and 7 name the default function, not a value


def test_transcribed_decided_and_uncovered_lines():
    rows, problems, counts = audit(_ir([5], _default(4, also=(8,))), {"a.txt": MANUAL})
    assert [(r["line"], r["status"]) for r in rows] == [
        (4, "transcribed"),
        (5, "decided"),
        (6, "uncovered"),
        (8, "transcribed"),
    ]
    assert rows[0]["where"] == "p: cmd.stream enable = True"
    assert rows[1]["where"].startswith("p: cmd.stream (0x0C,0x11): Not a parameter's value.")
    assert problems == [
        "a.txt:6: states a default that no parameter's default or decision note cites: "
        "Baud rates: 9600, 115200 ( default )"
    ]
    assert counts == {"a.txt": {"stated": 4, "transcribed": 2, "decided": 1, "uncovered": 1, "selector": 3}}


def test_everything_covered_is_no_problem():
    _, problems, counts = audit(_ir([5, 6], _default(4, also=(8,))), {"a.txt": MANUAL})
    assert problems == []
    assert counts["a.txt"]["uncovered"] == 0


def test_citing_a_line_that_states_no_default_is_reported():
    _, problems, _ = audit(_ir([5, 6, 9], _default(8, also=(4, 40))), {"a.txt": MANUAL})
    assert problems == [
        "a.txt:9: p: cmd.stream (0x0C,0x11): Not a parameter's value. (decided) cites a line stating no default",
        "a.txt:40: p: cmd.stream enable = True (transcribed) cites beyond the end of the manual",
    ]


def test_a_missing_manuals_directory_is_exit_status_2(tmp_path, capsys):
    assert defaults_audit.main(["--manuals", str(tmp_path / "nowhere")]) == 2
    assert "no manuals directory" in capsys.readouterr().err


def test_lines_on_a_note_other_than_a_decision_or_of_another_manual_are_reported():
    _, problems, counts = audit(_ir([5, 6], _default(4, also=(8,)), kind="gap"), {"a.txt": MANUAL})
    assert counts["a.txt"]["uncovered"] == 2
    assert (
        "a.txt:5: p: cmd.stream (0x0C,0x11): Not a parameter's value.: only a decision note may list lines it decides"
        in problems
    )
    _, problems, _ = audit(_ir([5], _default(4, also=(8,)), manual="z.txt"), {"a.txt": MANUAL})
    assert (
        "z.txt:5: p: cmd.stream (0x0C,0x11): Not a parameter's value. (decided) cites a manual that is not audited"
        in problems
    )
