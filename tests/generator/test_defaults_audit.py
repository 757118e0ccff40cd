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


def _ir(
    notes_lines: list[int], default: dict | None, kind: str = "decision", manual: str = "a.txt", no_value: bool = False
) -> dict:
    """A one-command protocol: a parameter with `default` (IR shape) and a decision note listing
    `notes_lines` of manual a.txt."""
    param = {"name": "enable", "type": {"kind": "primitive", "name": "bool"}, "notes": [], "default": default}
    note = {
        "kind": kind,
        "text": "Not a parameter's value.",
        "lines": [{"manual": manual, "line": n} for n in notes_lines],
    }
    if no_value:
        note["no_value"] = True
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
    assert counts == {
        "a.txt": {"stated": 4, "transcribed": 2, "decided": 1, "uncovered": 1, "sentences": 2, "selector": 3}
    }  # lines 4 and 8 state their default in a sentence


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


# Defaults stated in sentences (issue 51): for a structure, for several parameters at once, or as
# a property of the device's initial state. Excerpts in the manuals' words (3dm-gx5-45-dcp.txt:1106,
# 3dm-cv7-ins-docs.txt:7594, :154, :7021, :2161), one per line.
PROSE_MANUAL = "\n".join(
    [
        "Factory default setting is GPS and GLONASS enabled with min/max of GPS 8/16, GLONASS 8/14.",  # 1
        "Pitch/roll and heading corrections each have their own configurable time constants, with a "
        "valid range of 1-1000 seconds. The default time constant is 10 seconds.",  # 2
        "In its default state, the labeled axes of the 3DM-CV7 are assumed to be aligned with the vehicle frame.",  # 3
        "Triggers are disabled by default.",  # 4
        "When the device is connected to a computer via USB, the Main port will default to USB1.",  # 5
        "0x01 - Portable (default)",  # 6: a table's mark, not a sentence
        "0x05 - Reset to factory default settings",  # 7: the selector's name
    ]
)


def test_defaults_stated_in_sentences_are_found():
    stated, _ = stated_lines(PROSE_MANUAL)
    assert [n for n, _ in stated] == [1, 2, 3, 4, 5, 6]
    assert [n for n, line in stated if defaults_audit.in_a_sentence(line)] == [1, 2, 3, 4, 5]


def test_a_default_stated_in_a_sentence_is_not_waived_by_a_decision():
    rows, problems, counts = audit(_ir([1, 2, 3, 4, 5, 6], None), {"a.txt": PROSE_MANUAL})
    assert [(r["line"], r["status"], r["sentence"]) for r in rows] == [
        (1, "decided", True),
        (2, "decided", True),
        (3, "decided", True),
        (4, "decided", True),
        (5, "decided", True),
        (6, "decided", False),
    ]
    assert [p.split(":")[1] for p in problems] == ["1", "2", "3", "4", "5"]
    assert all("states a default in a sentence that only a decision covers" in p for p in problems)
    assert counts["a.txt"]["sentences"] == 5


def test_a_sentence_is_covered_by_its_transcription_or_a_decision_that_it_names_no_value():
    # lines 1-4 transcribed (one parameter's default citing them all), line 5 decided as naming no value
    _, problems, _ = audit(_ir([5, 6], _default(1, also=(2, 3, 4)), no_value=True), {"a.txt": PROSE_MANUAL})
    assert problems == []
