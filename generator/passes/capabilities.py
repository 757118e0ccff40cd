"""Pass: what each device supports, as data (exported as the protocol's `capabilities`).

Per device, in the protocol file's order: `commands`, every (set, descriptor) of a command field
whose manual documents it for that device (the field's `devices`), and `data`, every data field's
(set, descriptor) in a data set other than the shared placeholder set, both ascending. Every
package prints these as a per-device table its sessions consult; the simulator answers its
descriptor-list commands with them (the `simulation` section's `descriptor_lists`, whose
`contents` say which of the two lists a reply holds).

Checked: each device's listed entries fit the replies (the first reply's `capacity`, then the
extended one's), and a device whose list runs past the first reply supports the extended command.
"""

from __future__ import annotations

from .context import Context


def run(ctx: Context) -> None:
    devices = []
    for device in ctx.device_ids:
        commands, data = [], []
        for s in ctx.sets:
            for f in s["fields"]:
                if device not in (f.get("devices") or []):
                    continue
                if f["role"] == "command":
                    commands.append([s["id"], f["id"]])
                elif f["role"] == "data" and s["kind"] == "data" and not s.get("shared"):
                    data.append([s["id"], f["id"]])
        devices.append({"device": device, "commands": sorted(commands), "data": sorted(data)})
    ctx.capabilities = {"devices": devices}
    lists = (ctx.simulation or {}).get("descriptor_lists")
    if lists:
        _check_fit(ctx, lists, devices)


def _check_fit(ctx: Context, lists: dict, devices: list[dict]) -> None:
    path = ("simulation", "descriptor_lists", "lists")
    for d in devices:
        listed = [e for kind in lists["contents"] for e in d["commands" if kind == "command" else "data"]]
        room = 0
        for i, entry in enumerate(lists["lists"]):
            if room >= len(listed):
                break
            key = [entry.get("set"), entry.get("command_descriptor")]
            if i > 0 and key not in d["commands"]:
                ctx.err(
                    ctx.pf, path + (i, "command"),
                    f"simulation descriptor_lists: {d['device']} lists {len(listed)} entries, more than its first reply holds ({room}), but does not support {entry['command']}",
                    f"a device that supports {entry['command']}, or a shorter list",
                )  # fmt: skip
                return
            room += entry["capacity"]
        if room < len(listed):
            ctx.err(
                ctx.pf, path,
                f"simulation descriptor_lists: {d['device']} lists {len(listed)} entries, more than the replies hold ({room})",
                "lists whose replies hold every entry",
            )  # fmt: skip
