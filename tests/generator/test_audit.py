"""`make audit`: headings and quoted packets that the spec and vectors do not cover are reported."""

from generator import audit


def _manuals(tmp_path, gx5: str, cv7: str = ""):
    (tmp_path / "3dm-gx5-45-dcp.txt").write_text(gx5)
    (tmp_path / "3dm-cv7-ins-docs.txt").write_text(cv7)
    return tmp_path


def test_covered_manual_reports_nothing(tmp_path, capsys):
    text = (
        "### 4.1.1 Ping (0x01, 0x01)\n"
        '<i>Copy-Paste version of the command: "7565 0102 0201 E0C6"</i>\n'
        "## Scaled Accel (0x80,0x04)\n"
    )
    assert audit.main(["--manuals", str(_manuals(tmp_path, text))]) == 0
    assert "0 not covered" in capsys.readouterr().err


def test_missing_heading_and_packet_are_listed(tmp_path, capsys):
    text = (
        "### 4.3.1 Reset Filter (0x0D, 0x01)\n"
        "prose mentioning (0x0D, 0x02) is not a heading\n"
        'Copy-paste: "7565 0D02 0201 E1C3"\n'
    )
    assert audit.main(["--manuals", str(_manuals(tmp_path, text))]) == 1
    out = capsys.readouterr()
    assert "3dm-gx5-45-dcp.txt:1: heading (0x0D,0x01) not in the spec" in out.out
    assert "(0x0D,0x02)" not in out.out
    assert "3dm-gx5-45-dcp.txt:3: quoted packet not in tests/vectors: 7565 0D02 0201 E1C3" in out.out
    assert "2 not covered" in out.err


def test_missing_manuals_directory_is_a_usage_error(tmp_path):
    assert audit.main(["--manuals", str(tmp_path / "nope")]) == 2
