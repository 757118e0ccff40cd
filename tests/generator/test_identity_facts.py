"""The facts of the wrong-model check (issue 39; generator/linkfacts.py identity_facts), which the
C, C++ and Rust packages print as constants, against the manuals:

- MIP: Get Device Information is (0x01, 0x03), its reply field 0x81 holds the firmware version
  (U16, offset 0) then the model name (String(16), offset 2): 3dm-gx5-45-dcp.txt lines 772-782.
  The NACK code of an unknown command is 1 (spec simulation.nack unknown_descriptor:
  unknown_command).
- MS-CIP: Get Device Model is (0x01, 0x05), answered by 0x85 whose data is the 16-character model
  (ms-cip-doc00419-revM.txt lines 276-294).
- The names a model answers to are its title and identity model name, upper case without spaces
  and punctuation (3DM-GX5-45 -> 3DMGX545; MS-IMU3020 and MS_IMU3020 -> MSIMU3020).
"""

from __future__ import annotations

from generator.linkfacts import identity_facts, plain_name
from generator.spec import load_spec


def _protocols() -> dict:
    return {p["name"]: p for p in load_spec()["protocols"]}


def test_identity_facts_are_the_manuals() -> None:
    protos = _protocols()
    mip = identity_facts(protos["mip"])
    assert mip is not None
    assert (mip["command"]["set"], mip["command"]["descriptor"], mip["reply"]["descriptor"]) == (0x01, 0x03, 0x81)
    assert (mip["model_offset"], mip["model_length"]) == (2, 16)
    assert 1 in mip["unknown_codes"]
    assert {d["id"]: d["plain"] for d in mip["devices"]} == {"gx5_45": ["3DMGX545"], "cv7_ins": ["3DMCV7GNSSINS"]}
    mscip = identity_facts(protos["mscip"])
    assert mscip is not None
    assert (mscip["command"]["descriptor"], mscip["reply"]["descriptor"]) == (0x05, 0x85)
    assert (mscip["model_offset"], mscip["model_length"]) == (0, 16)
    assert mscip["devices"] == [{"id": "ms_imu3020", "names": ["MS-IMU3020", "MS_IMU3020"], "plain": ["MSIMU3020"]}]


def test_plain_name_keeps_what_is_not_ascii() -> None:
    assert plain_name(" 3dm-gx5/45 ") == "3DMGX545"
    assert plain_name("GX5\xe9") == "GX5\xc9"  # kept: it matches no name of the spec (all ASCII)
    assert plain_name("--- ") == ""
