"""`make audit`: headings and quoted packets that the spec and vectors do not cover are reported."""

from generator import audit


def _manuals(tmp_path, gx5: str, cv7: str = "", mscip: str = ""):
    (tmp_path / "3dm-gx5-45-dcp.txt").write_text(gx5)
    (tmp_path / "3dm-cv7-ins-docs.txt").write_text(cv7)
    (tmp_path / "ms-cip-doc00419-revM.txt").write_text(mscip)
    return tmp_path


def test_covered_manual_reports_nothing(tmp_path, capsys):
    # The copy-paste string sits on line 311, the line the project's ping vector cites.
    text = (
        "### 4.1.1 Ping (0x01, 0x01)\n"
        + "\n" * 309
        + '<i>Copy-Paste version of the command: "7565 0102 0201 E0C6"</i>\n'
        "## Scaled Accel (0x80,0x04)\n"
        + "\n" * 456
        + '<i>Set To Idle copy-paste, the Ping bytes again (a negative vector cites it): "7565 0102 0201 E0C6"</i>\n'
    )
    assert text.splitlines()[310].endswith('E0C6"</i>') and text.splitlines()[768].endswith('E0C6"</i>')
    assert audit.main(["--manuals", str(_manuals(tmp_path, text))]) == 0
    assert "0 not covered" in capsys.readouterr().err


def test_missing_heading_and_packet_are_listed(tmp_path, capsys):
    text = (
        "### 4.3.1 Not A Command (0x0D, 0x7D)\n"
        "prose mentioning (0x0D, 0x02) is not a heading\n"
        'Copy-paste: "7565 0D02 027D 5DBB"\n'
    )
    assert audit.main(["--manuals", str(_manuals(tmp_path, text))]) == 1
    out = capsys.readouterr()
    assert "3dm-gx5-45-dcp.txt:1: heading (0x0D,0x7D) not in the spec" in out.out
    assert "(0x0D,0x02)" not in out.out
    assert "3dm-gx5-45-dcp.txt:3: quoted packet not in tests/vectors: 7565 0D02 027D 5DBB" in out.out
    assert "2 not covered" in out.err


def test_missing_manuals_directory_is_a_usage_error(tmp_path):
    assert audit.main(["--manuals", str(tmp_path / "nope")]) == 2


def test_example_table_rows_are_packets(tmp_path, capsys):
    text = (
        "<i>Command: Ping</i>\t0x75\t0x65\t0x01\t0x02\t0x02\t0x01\tN/A\t0xE0\t0xC6\n"
        "<i>Command: Reset</i>\t0x75\t0x65\t0x0D\t0x02\t0x02\t0x7D\t\t0x5D\t0xBB\n"
    )
    assert audit.main(["--manuals", str(_manuals(tmp_path, text))]) == 1
    out = capsys.readouterr()
    assert ":1: example table row" not in out.out  # the Ping packet is a vector
    assert "3dm-gx5-45-dcp.txt:2: example table row not in tests/vectors: 75650d02027d5dbb" in out.out


def test_table_row_bytes_and_continuation_rows():
    text = (
        "<b>Header</b>\tSync1\n"
        "<i>Reply Field 1: ACK/NACK</i>\t0x75\t0x65\t0x01\t0x0A\t0x04\t0xF1\tEcho cmd: 0x05 Error code: 0x00\t\t\n"
        "<i>Reply Field 2: BIT</i>\t\t\t\t\t0x06\t0x83\tFlags: 0x00000000\t0x68\t0x7D\n"
        "Row\t0x75\t0x65\t0x80\t0x0E\t0x0E\t0x04\t0x3E 7A 63 A0 0xBB 8E\t0x92\t0xC0\n"
    )
    rows = list(audit.table_rows(text, bytes([0x75, 0x65])))
    assert [(r[0], r[1], r[2]) for r in rows] == [
        (2, [2, 3], "7565010a04f10500068300000000687d"),
        (4, [4], "7565800e0e043e7a63a0bb8e92c0"),
    ]


def test_vector_citing_the_wrong_line_is_reported(tmp_path, capsys):
    # The project's ping vector cites 3dm-gx5-45-dcp.txt at its real line; here the packet sits elsewhere.
    text = "\n" * 2000 + 'Copy-Paste version of the command: "7565 0102 0201 E0C6"\n'
    audit.main(["--manuals", str(_manuals(tmp_path, text))])
    assert "but its packet is printed at line 2001" in capsys.readouterr().out


def test_kinds_limits_the_audit(tmp_path, capsys):
    text = "### 4.3.1 Not A Command (0x0D, 0x7D)\n### 5.9 Some Data (0x82, 0x7E)\n"
    manuals = str(_manuals(tmp_path, text))
    assert audit.main(["--manuals", manuals, "--kinds", "data"]) == 1
    out = capsys.readouterr().out
    assert "(0x82,0x7E)" in out and "(0x0D,0x7D)" not in out
    assert audit.main(["--manuals", manuals, "--kinds", "command"]) == 1
    out = capsys.readouterr().out
    assert "(0x0D,0x7D)" in out and "(0x82,0x7E)" not in out
    assert audit.main(["--manuals", manuals, "--kinds", "bogus"]) == 2


def test_mscip_code_headings_and_byte_tables(tmp_path, capsys):
    """MS-CIP titles carry type and code as one number; its example tables have one row per
    byte. A covered table (the Ping command, which the vectors hold) is silent; an unknown code
    and a table whose bytes no vector has are listed, prose with a code is not a heading."""
    rows = ["0xA5", "0xA5", "0x01", "0x02", "0x02", "0x00", "0x4F", "0x25"]
    ping = "".join(f"{i}\tByte {i}\t{v}\tdescription\n" for i, v in enumerate(rows))
    bad = [*rows[:4], "0x7E", "0x00", "0x00", "0x00"]
    other = "".join(f"{i}\tByte {i}\t{v}\tdescription\n" for i, v in enumerate(bad))
    text = (
        "PING COMMAND 0x0102\nMYSTERY COMMAND 0x017E\nthe message 0x017D is mentioned in prose.\n" + ping + "\n" + other
    )
    assert audit.main(["--manuals", str(_manuals(tmp_path, "", mscip=text))]) == 1
    out = capsys.readouterr()
    assert "ms-cip-doc00419-revM.txt:1:" not in out.out
    assert "ms-cip-doc00419-revM.txt:2: heading (0x01,0x7E) not in the spec" in out.out
    assert "0x017D" not in out.out and "(0x01,0x7D)" not in out.out
    assert ":4: example table row" not in out.out  # the Ping bytes are a vector
    assert "ms-cip-doc00419-revM.txt:13: example table row not in tests/vectors: a5a501027e000000" in out.out
    # The project's ping vector cites the manual's real table line, not this file's line 4.
    assert "but its packet is printed at line 4, 5, 6, 7, 8, 9, 10, 11" in out.out
    assert "3 not covered" in out.err


def test_byte_table_rows_without_a_byte_number():
    text = "0\tSync1\t0xA5\tx\n1\tSync2\t0xA5\tx\n2\tT\t0x02\tx\n\tno number\t0x12\tx\nResulting\n"
    ((first, rows, hx, _),) = list(audit.byte_tables(text, b"\xa5\xa5"))
    assert (first, rows, hx) == (1, [1, 2, 3, 4], "a5a50212")
