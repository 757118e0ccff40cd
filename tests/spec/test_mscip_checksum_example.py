"""MS-CIP manual Table 1 (ms-cip-doc00419-revM.txt lines 129-139): the Ping message's Fletcher-16
worked example, row by row. The running sums F1/F2 are transcribed from the manual; they are
checked against the algorithm of section 2.4 written out here (not the generated code), and
the generated Python checksum must give the published bytes 4F 25.

The manual's byte-4 row prints F1 333 and F2 1493; adding byte 4 (0x02) to F1 333 gives 335, and
F2 1159 + 335 = 1494. Row 5 (335, 1829) continues from the right values, and 1829 mod 256 = 37 =
0x25, so only row 4 is misprinted (docs/errata.md).
"""

from tests.helpers.generated import python_package
from tests.helpers.packets import fletcher16

# (byte, published F1, published F2) for rows 0-5 of Table 1.
TABLE_1 = [
    (0xA5, 165, 165),
    (0xA5, 330, 495),
    (0x01, 331, 826),
    (0x02, 333, 1159),
    (0x02, 333, 1493),
    (0x00, 335, 1829),
]
PUBLISHED_CHECKSUM = (0x4F, 0x25)  # rows 6 and 7


def running_sums(data):
    """The manual's unreduced running sums (F1, F2) after each byte."""
    f1 = f2 = 0
    out = []
    for b in data:
        f1 += b
        f2 += f1
        out.append((f1, f2))
    return out


def test_only_row_4_of_table_1_is_misprinted():
    computed = running_sums([b for b, _, _ in TABLE_1])
    wrong = [i for i, ((_, f1, f2), (c1, c2)) in enumerate(zip(TABLE_1, computed)) if (f1, f2) != (c1, c2)]
    assert wrong == [4]
    assert computed[4] == (335, 1494)
    f1, f2 = computed[-1]
    assert (f1 % 256, f2 % 256) == PUBLISHED_CHECKSUM
    assert fletcher16(bytes(b for b, _, _ in TABLE_1)) == bytes(PUBLISHED_CHECKSUM)


def test_generated_checksum_gives_the_published_bytes():
    framing = python_package("mscipcodec").codec.framing
    packet = bytes(b for b, _, _ in TABLE_1)
    assert framing.checksum_bytes(packet) == bytes(PUBLISHED_CHECKSUM)
