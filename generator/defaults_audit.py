"""`make audit` (defaults): is every factory default the manuals state in the spec?

A manual line states a default when it says "default" in any case ("(default)", "factory default",
"by default", "Default Offset" in a table, a table's "Default Setting" column), once the function
selector's own name is taken out of it: "Reset to factory default settings", "Write Read Save Load
Default [WRSLD]", "when function is SAVE, LOAD, or DEFAULT" name the function, not a value
(SELECTOR below; such lines are counted apart). Each stated line must be covered:

- transcribed: a parameter's `default` cites it (`source` or `also`, docs/spec-format.md), or
- decided: a `kind: decision` note lists it in its `lines` (why it is no parameter's value).

A default stated in a sentence (PROSE below: "The default time constant is 10 seconds", "Factory
default setting is GPS and GLONASS enabled with ...", "In its default state, the labeled axes ...
are aligned", "Triggers are disabled by default": a default for a structure, for several
parameters at once, or as a property of the device's initial state) must be transcribed; a
decision covers such a line only when it says the sentence names no parameter's value
(`no_value: true`).

A transcription or decision citing a line that states no default is reported too (the manual
changed, or the line is wrong). Prints one row per stated line and the counts per manual; exit
status 1 when a stated default is not covered, 2 when the manuals are missing. Not part of
`make test`: users do not have the manuals.
"""

from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

from .errata import spec_notes
from .spec import ROOT, load_spec

WORD = re.compile(r"default", re.I)
# The function selector's names and the prose naming that function: not a stated value.
SELECTOR = re.compile(
    "|".join(
        [
            r"(?:Write\s+)?(?:Read\s+)?Save\s+Load\s+Default\s*\[\w+\]",
            r"(?:0x05\s*-?\s*)?(?:Reset\s+to|Load|Restore)(?:\s+the)?(?:\s+factory)?\s+defaults?(?:\s+settings?)?",
            r"Reset\s+to\s+Default\s+the",
            r"SAVE,\s+LOAD,?\s+(?:or|and)\s+DEFAULT",
            r"save,\s+load,?\s+(?:or|and)\s+default\s+function\s+selectors?",
            r"restoring\s+the\s+default\s+behavior",
        ]
    ),
    re.I,
)

# A default stated in a sentence rather than marked in a table ("(default)").
PROSE = re.compile(
    "|".join(
        [
            r"\bdefault(?:\s+[\w/-]+){0,3}\s+(?:is|are|was|of)\s+",
            r"\bin\s+its\s+default\s+state\b",
            r"\bis\s+the\s+default\b",
            r"\bdefaults?\s+to\b",
            r"\bby\s+default\b",
        ]
    ),
    re.I,
)


def in_a_sentence(line: str) -> bool:
    """Whether a line states a default in a sentence (PROSE), the function selector's names left out."""
    return bool(PROSE.search(SELECTOR.sub(" ", re.sub(r"<[^>]+>", " ", line))))


def stated_lines(text: str) -> tuple[list[tuple[int, str]], int]:
    """The lines of a manual that state a default ((line number, text)), and how many lines say
    "default" only as the function selector's name."""
    stated = []
    selector = 0
    for lineno, line in enumerate(text.splitlines(), 1):
        if not WORD.search(line):
            continue
        if WORD.search(SELECTOR.sub(" ", line)):
            stated.append((lineno, line))
        else:
            selector += 1
    return stated, selector


def _params(p: dict):
    """(label, parameter) of every parameter of the protocol that can have a default."""
    for s in p["sets"]:
        for f in s["fields"]:
            for v in f["variants"]:
                dev = f" [{v['device']}]" if v["device"] else ""
                for q in v["params"]:
                    yield f"{p['name']}: {s['name']}.{f['name']}{dev} {q['name']}", q
    for fl in p.get("field_layouts", []):
        for q in fl["params"]:
            yield f"{p['name']}: layout {fl['name']} {q['name']}", q


def _value_text(q: dict, types: dict) -> str:
    value = q["default"]["value"]
    t = types.get(q["type"].get("name", ""))
    if t and t["kind"] == "enum":
        names = {v["value"]: v["name"] for v in t["values"]}
        return str([names.get(x, x) for x in value] if isinstance(value, list) else names.get(value, value))
    return str(value)


def coverage(ir: dict) -> dict[tuple[str, int], list[tuple[str, str]]]:
    """(manual, line) -> [(how, where)]: how is "transcribed", "decided", or "not a decision" (a
    note of another kind listing lines, which decides nothing)."""
    cover: dict[tuple[str, int], list[tuple[str, str]]] = {}
    for p in ir["protocols"]:
        types = {t["name"]: t for t in p["types"]}
        for label, q in _params(p):
            d = q.get("default")
            if not d:
                continue
            for ref in [d["source"], *d.get("also", [])]:
                where = f"{label} = {_value_text(q, types)}"
                cover.setdefault((ref["manual"], ref["line"]), []).append(("transcribed", where))
    for proto, label, _sources, note in spec_notes(ir):
        how = "decided" if note["kind"] == "decision" else "not a decision"
        if how == "decided" and note.get("no_value"):
            how = "decided: names no value"
        for ref in note.get("lines", []):
            text = " ".join(note["text"].split())
            cover.setdefault((ref["manual"], ref["line"]), []).append(
                (how, f"{proto}: {label}: {text[:70]}{'…' if len(text) > 70 else ''}")
            )
    return cover


def audit(ir: dict, texts: dict[str, str]) -> tuple[list[dict], list[str], dict[str, dict]]:
    """The stated defaults of the manuals in `texts` (name -> text) against the spec: the rows
    (manual, line, status, where, text), the problems (uncovered lines, citations of lines
    stating no default) and the counts per manual."""
    cover = coverage(ir)
    rows: list[dict] = []
    problems: list[str] = []
    counts: dict[str, dict] = {}
    for manual, text in texts.items():
        stated, selector = stated_lines(text)
        c = counts[manual] = {"stated": len(stated), "transcribed": 0, "decided": 0, "uncovered": 0, "sentences": 0}
        c["selector"] = selector
        at = {n for n, _ in stated}
        for lineno, line in stated:
            how = [h for h in cover.get((manual, lineno), []) if h[0] != "not a decision"]
            kinds = {h for h, _ in how}
            status = "transcribed" if "transcribed" in kinds else "decided" if kinds else "uncovered"
            c[status] += 1
            sentence = in_a_sentence(line)
            c["sentences"] += sentence
            excerpt = " ".join(re.sub(r"<[^>]+>", " ", line).split())
            rows.append(
                {
                    "manual": manual,
                    "line": lineno,
                    "status": status,
                    "sentence": sentence,
                    "where": "; ".join(w for _, w in how),
                    "text": excerpt,
                }
            )
            if sentence and status == "decided" and "decided: names no value" not in kinds:
                problems.append(
                    f"{manual}:{lineno}: states a default in a sentence that only a decision covers: transcribe "
                    f"it (or mark the decision no_value when the sentence names no value): {excerpt[:100]}"
                )
            if status == "uncovered":
                problems.append(
                    f"{manual}:{lineno}: states a default that no parameter's default or decision note cites: "
                    f"{excerpt[:100]}"
                )
        lines = len(text.splitlines())
        for (m, n), how in sorted(cover.items()):
            if m == manual and n not in at:
                what = "beyond the end of the manual" if n > lines else "a line stating no default"
                for h, w in how:
                    problems.append(f"{manual}:{n}: {w} ({h}) cites {what}")
    for (m, n), how in sorted(cover.items()):
        for h, w in how:
            if m not in texts:
                problems.append(f"{m}:{n}: {w} ({h}) cites a manual that is not audited")
            elif h == "not a decision":
                problems.append(f"{m}:{n}: {w}: only a decision note may list lines it decides")
    return rows, problems, counts


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="make audit", description=__doc__.splitlines()[0])
    ap.add_argument("--manuals", default=str(ROOT.parent / "shared" / "manuals"))
    ap.add_argument("--quiet", action="store_true", help="print the problems and counts only, not every row")
    args = ap.parse_args(argv)
    manuals = Path(args.manuals)
    if not manuals.is_dir():
        print(f"defaults audit: no manuals directory at {manuals}", file=sys.stderr)
        return 2
    ir = load_spec()
    texts = {}
    for p in ir["protocols"]:
        for dev in p["devices"]:
            path = manuals / dev["manual"]
            if not path.exists():
                print(f"defaults audit: {dev['manual']} not found in {manuals}", file=sys.stderr)
                return 2
            texts[dev["manual"]] = path.read_text(encoding="utf-8", errors="replace")
    rows, problems, counts = audit(ir, texts)
    if not args.quiet:
        for r in rows:
            print(f"{r['manual']}:{r['line']}\t{r['status']}\t{r['where'] or '-'}\t{r['text'][:80]}")
    for msg in problems:
        print(msg)
    print(
        "manual\tstated\ttranscribed\tdecided\tuncovered\tin sentences\t(function selector mentions)",
        file=sys.stderr,
    )
    for manual, c in counts.items():
        print(
            f"{manual}\t{c['stated']}\t{c['transcribed']}\t{c['decided']}\t{c['uncovered']}\t{c['sentences']}"
            f"\t({c['selector']})",
            file=sys.stderr,
        )
    print(
        f"defaults audit: {sum(c['stated'] for c in counts.values())} stated defaults, {len(problems)} problems",
        file=sys.stderr,
    )
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
