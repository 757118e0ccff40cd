"""What the C and C++ back ends print alike: the syntax the two languages share."""

from __future__ import annotations


def c_string(text: str, *, cpp: bool = False) -> str:
    """A C (or with `cpp`, C++) string literal for ASCII-ish text: octal escapes for anything
    outside printable ASCII. The C++ back end escapes `?` too (no trigraphs) and writes a newline
    as an octal escape, the C back end as `\\n`; both kept so that generated code does not change.
    A character beyond Latin-1 has no one-byte escape: ValueError."""
    out = ['"']
    for ch in text:
        o = ord(ch)
        if ch in '\\"':
            out.append("\\" + ch)
        elif ch == "?" and cpp:
            out.append("\\?")
        elif ch == "\n" and not cpp:
            out.append("\\n")
        elif 0x20 <= o < 0x7F:
            out.append(ch)
        elif o < 0x100:
            out.append("\\%03o" % o)
        else:
            raise ValueError(f"non-Latin-1 character in {text!r}")
    out.append('"')
    return "".join(out)


def session_steps(case: dict, literal) -> list[dict]:
    """The steps of a session-corpus case (generator/sessions.py) as C or C++ string literals
    (`literal`: `c_string` for the dialect), `nullptr` where a step has none."""
    out = []
    for s in case["steps"]:
        send = s.get("send")
        out.append(
            {
                "at": s["at"],
                "send": literal(send) if send is not None else "nullptr",
                "bytes": literal(s["bytes"]) if send is not None and s.get("bytes") else "nullptr",
                "receive": literal(s["receive"]) if "receive" in s else "nullptr",
            }
        )
    return out
