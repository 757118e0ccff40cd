"""settings.py and budget.py on the test protocol: the settings files' text, their located
validation, the differences against a device, and a spec without the bandwidth calculation."""

from __future__ import annotations

from typing import Any, Dict, List

import pytest
from testproto import control
from testproto.device import budget
from testproto.device import settings as st


class _Result:
    def __init__(self, response: Any) -> None:
        self.response = response


class FakeDevice:
    """Answers a gain read with the stored value; records every command it is given."""

    def __init__(self, gain: int) -> None:
        self.gain = gain
        self.sent: List[Any] = []

    def call(self, command: Any) -> _Result:
        self.sent.append(command)
        if int(command.function) == st.WRITE:
            self.gain = command.gain
            return _Result(None)
        return _Result(control.GainValue(gain=self.gain))


def test_the_models_settings_come_from_the_spec() -> None:
    (gain,) = st.settings_for("alpha")
    assert (gain.name, gain.key_attrs, gain.keyed) == ("gain", (), False)
    assert [a for a, _, _ in gain.attrs] == ["gain"]
    assert st.known_names() == {"gain": ["alpha", "beta"]}


def test_dump_text() -> None:
    device = FakeDevice(7)
    values = st.read_all(device, "alpha")
    assert values == {"gain": {"gain": 7}}
    text = st.dump_text(values, "alpha", ["header line"])
    assert text == "# header line\ndevice: alpha\ngain:\n  gain: 7\n"
    assert [int(c.function) for c in device.sent] == [2]  # only reads


def _validate(text: str) -> List[st.Planned]:
    return st.validate(st.load_text(text, "f.yaml"), "alpha", "f.yaml")


def test_a_good_file_and_its_differences() -> None:
    planned = _validate("device: alpha\ngain:\n  gain: 9\n")
    device = FakeDevice(7)
    (change,) = st.differences(device, planned)
    assert (change.device, change.file) == ({"gain": 7}, {"gain": 9})
    assert st.changed_params(change.device, change.file) == ["gain: 7 -> 9"]
    device.gain = 9
    assert st.differences(device, planned) == []


@pytest.mark.parametrize(
    "text,expected",
    [
        ("gain:\n  gain: 70000\n", ["f.yaml:2: gain: gain: 70000 is out of range for u16 (0..65535)"]),
        ("gain:\n  gain: x\n", ["f.yaml:2: gain.gain: 'x' is not an integer"]),
        ("gain:\n  gain: 1\n  other: 2\n", ["f.yaml:3: gain: unknown parameter 'other' (expected: gain)"]),
        ("gain: {}\n", ["f.yaml:1: gain: missing gain"]),
        ("nope: 1\ngain:\n  gain: 1\n", ["f.yaml:1: unknown setting 'nope' (not a setting of the spec's commands)"]),
        ("device: beta\n", ["f.yaml:1: the file is for 'beta', the connected model is alpha"]),
        ("gain: 1\ngain: 2\n", ["f.yaml:2: 'gain' given twice (first on line 1)"]),
        ("gain: [\n", ["f.yaml:2: not valid YAML"]),
        ("[1, 2]\n", ["f.yaml:1: expected a mapping of setting names to values"]),
    ],
)
def test_bad_files_are_located(text: str, expected: List[str]) -> None:
    with pytest.raises(st.FileError) as e:
        _validate(text)
    assert len(e.value.lines) == len(expected), e.value.lines
    for line, start in zip(e.value.lines, expected):
        assert line.startswith(start), (line, start)


def test_every_problem_at_once() -> None:
    with pytest.raises(st.FileError) as e:
        _validate("nope: 1\ngain:\n  gain: x\n")
    assert [x.split(":")[1] for x in e.value.lines] == ["1", "3"]


def test_no_bandwidth_calculation_in_the_spec() -> None:
    assert not budget.available()
    with pytest.raises(budget.BudgetError, match="no UART bandwidth calculation"):
        budget.stream("alpha", 0x80, [(0x01, 1)], 100.0)
    values: Dict[str, Any] = {}
    assert st.dump_text(values, "alpha", []) == "device: alpha\n"
