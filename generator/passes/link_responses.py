"""Pass: link each command's responses to fields: a response descriptor must name a field with
role response in the same set (the response gets that field's name), and follow the protocol's
reply code rule when it has one (MS-CIP: response = command | command_or)."""

from __future__ import annotations

from .context import Context


def run(ctx: Context) -> None:
    rule = ctx.pf.data.get("response_descriptor")
    for s in ctx.sets:
        by_desc = {f["id"]: f for f in s["fields"]}
        for f in s["fields"]:
            sf = f["_sf"]
            for v in f["variants"]:
                for r in v["responses"]:
                    target = by_desc.get(r["id"])
                    if target is None:
                        ctx.err(
                            sf,
                            r["_loc"],
                            f"{s['name']}.{f['name']}: response 0x{r['id']:02X} does not exist in set 0x{s['id']:02X}",
                            "the descriptor of a field with role response in the same set",
                        )
                    elif target["role"] != "response":
                        ctx.err(
                            sf,
                            r["_loc"],
                            f"{s['name']}.{f['name']}: response 0x{r['id']:02X} is '{target['name']}', a {target['role']} field",
                            "a field with role response",
                        )
                    else:
                        r["name"] = target["name"]
                    if rule and r["id"] != f["id"] | rule["command_or"]:
                        ctx.err(
                            sf,
                            r["_loc"],
                            f"{s['name']}.{f['name']}: response 0x{r['id']:02X} breaks the reply code rule",
                            f"0x{f['id'] | rule['command_or']:02X} (command 0x{f['id']:02X} | 0x{rule['command_or']:02X}, protocol response_descriptor)",
                        )
