"""The GPS time scale (spec/common/gps_time.yaml, generator/gps_scale.py): the facts every package
reads for the GPS epoch and GPS - UTC, checked against what is known independently of the file:

- the GPS epoch is 1980-01-06T00:00:00Z (the manuals' "GPS Week Number since 1980", the GPS
  interface specification's week 0), computed here with `datetime`;
- leap seconds are inserted only at the end of June or December (IERS), so every row starts at a
  UTC midnight of 1 January or 1 July; GPS - UTC grows by one second a row, from 1 (1981-07-01) to
  18 (2017-01-01, IERS Bulletin C: none since);
- a bad file gets located errors (file:line), never a traceback; a spec root without common/ of
  its own reads the project's.
"""

from __future__ import annotations

import datetime
import shutil
from pathlib import Path

import pytest

from generator.columns import time_facts
from generator.diagnostics import SpecErrors
from generator.gps_scale import load_gps_scale
from generator.resources import ROOT
from generator.spec import load_spec

UTC = datetime.timezone.utc


def _unix(*ymd: int) -> int:
    return int(datetime.datetime(*ymd, tzinfo=UTC).timestamp())


def test_the_project_file_is_the_known_scale() -> None:
    scale = load_gps_scale(ROOT / "spec")
    assert scale["epoch_unix_s"] == _unix(1980, 1, 6)
    rows = scale["leap_seconds"]
    assert [v for _t, v in rows] == list(range(1, 19))
    assert rows[0][0] == _unix(1981, 7, 1) and rows[-1][0] == _unix(2017, 1, 1)
    for t, _v in rows:
        day = datetime.datetime.fromtimestamp(t, UTC)
        assert (day.month, day.day, day.hour, day.minute, day.second) in ((1, 1, 0, 0, 0), (7, 1, 0, 0, 0)), day


def test_every_protocol_and_its_python_table_carry_it() -> None:
    scale = load_gps_scale(ROOT / "spec")
    for proto in load_spec()["protocols"]:
        assert proto["time"]["gps_scale"] == scale, proto["name"]
        assert time_facts(proto)["gps_scale"] == scale


def _spec_with_common(tmp_path: Path, text: str) -> Path:
    spec = tmp_path / "spec"
    shutil.copytree(ROOT / "spec" / "mscip", spec / "mscip")
    (spec / "common").mkdir()
    (spec / "common" / "gps_time.yaml").write_text(text, encoding="utf-8")
    return spec


@pytest.mark.parametrize(
    ("body", "words"),
    [
        ("  epoch_unix_s: -1\n  leap_seconds: [[362793600, 1]]\n", ["gps_time.yaml:2:", "epoch_unix_s -1"]),
        (
            "  epoch_unix_s: 315964800\n  leap_seconds: [[394329600, 2], [362793600, 1]]\n",
            ["gps_time.yaml:3:", "does not follow"],
        ),
        ("  epoch_unix_s: 315964800\n  leap_seconds: [[362793600, one]]\n", ["gps_time.yaml:3:", "two integers"]),
        ("  epoch_unix_s: 315964800\n  leap_seconds: []\n", ["gps_time.yaml:3:", "not a list of rows"]),
        ("  epoch_unix_s: 315964800\n  leap_seconds: [[1, 1]]\n", ["gps_time.yaml:3:", "not after the GPS epoch"]),
        (
            "  epoch: 315964800\n  epoch_unix_s: 315964800\n  leap_seconds: [[362793600, 1]]\n",
            ["gps_time.yaml:2:", "unknown key 'epoch'"],
        ),
    ],
)
def test_a_bad_file_is_a_located_error(tmp_path: Path, body: str, words: list) -> None:
    spec = _spec_with_common(tmp_path, "gps_time_scale:\n" + body)
    with pytest.raises(SpecErrors) as e:
        load_spec(spec, root=tmp_path)
    assert all(w in str(e.value) for w in words), str(e.value)


def test_a_spec_root_with_its_own_common_reads_it(tmp_path: Path) -> None:
    spec = _spec_with_common(tmp_path, "gps_time_scale:\n  epoch_unix_s: 315964800\n  leap_seconds: [[362793600, 1]]\n")
    proto = load_spec(spec, root=tmp_path)["protocols"][0]
    assert proto["time"]["gps_scale"] == {"epoch_unix_s": 315964800, "leap_seconds": [[362793600, 1]]}
    shutil.rmtree(spec / "common")
    proto = load_spec(spec, root=tmp_path)["protocols"][0]
    assert proto["time"]["gps_scale"] == load_gps_scale(ROOT / "spec")
