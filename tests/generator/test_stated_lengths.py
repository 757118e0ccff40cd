"""generator.stated_lengths: a manual's stated field length against the computed one (MIP: the
field length counts the 2-byte header)."""

from generator.stated_lengths import lint_stated_lengths


def _q(size: int, fixed: bool = True, optional: bool = False) -> dict:
    return {"size": {"min": size if fixed else 0, "max": size, "fixed": fixed}, "optional": optional}


def _ir(params: list[dict], stated) -> dict:
    mn = sum(q["size"]["min"] for q in params if not q["optional"])
    mx = sum(q["size"]["max"] for q in params)
    fixed = all(q["size"]["fixed"] and not q["optional"] for q in params)
    variant = {
        "size": {"min": mn, "max": mx, "fixed": fixed},
        "params": params,
        "sources": [{"manual": "m.txt", "line": 7, "stated_length": stated}],
    }
    field = {"id": 0x02, "name": "cmd", "variants": [variant]}
    proto = {"name": "p", "framing": {"field_length_adjust": 2}, "sets": [{"id": 1, "name": "s", "fields": [field]}]}
    return {"protocols": [proto]}


def test_agreeing_lengths_are_not_listed():
    assert lint_stated_lengths(_ir([_q(4), _q(1)], 7)) == []
    # Optional parameters: a manual may state the full length.
    assert lint_stated_lengths(_ir([_q(4), _q(1, optional=True)], 7)) == []


def test_a_disagreement_is_listed_with_both_lengths():
    (item,) = lint_stated_lengths(_ir([_q(4), _q(1)], 9))
    assert item == {
        "protocol": "p",
        "set": 1,
        "descriptor": 0x02,
        "name": "s.cmd",
        "manual": "m.txt",
        "line": 7,
        "stated": 9,
        "computed": 7,
    }


def test_textual_lengths_are_always_listed():
    (item,) = lint_stated_lengths(_ir([_q(4), _q(8, fixed=False)], "variable"))
    assert (item["textual"], item["computed"]) == (True, "6..14")
