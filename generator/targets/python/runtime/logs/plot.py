"""`<package> plot`: chosen fields of a log against time (matplotlib)."""

from __future__ import annotations

import argparse
import io
import os
from typing import Any, Dict, List, Optional, Tuple

from ..codec.packets import DecodedField, Packet
from .pipeline import LogDevice, PacketClock, plot_times
from .writers import (
    COLUMN_SETS,
    Events,
    Layout,
    Outputs,
    Source,
    ToolError,
    field_list,
    need,
    select,
    stream_events,
)


# --------------------------------------------------------------------------------------- plot
def figure(log: str, fields: Optional[List[str]], device: Optional[str] = None) -> Any:
    """The matplotlib figure of `plot`: the selected columns against time, one panel per unit."""
    need("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    # x: (UTC t_ns or None, offset); plotted against UTC when the log has it (pipeline.plot_times)
    series: Dict[str, Tuple[List[Any], List[float], str]] = {}
    dev = LogDevice.of(log, device)
    clock = PacketClock(log)
    source = Source(log)
    stream = Events(dev.device)
    have_time = False
    for e in stream_events(source, stream):
        if not isinstance(e, Packet):
            continue
        dev.packet(e, stream.decoder)
        t = clock.t_ns(e)
        if e.set not in COLUMN_SETS:
            continue
        x = (t, e.offset)
        have_time = have_time or t is not None
        for f in e.fields:
            if not isinstance(f, DecodedField):
                continue
            lay = Layout(type(f.value), True)
            keep = select(lay.headers, fields)
            if not keep:
                continue
            cells = lay.cells(f.value)
            for i in keep:
                if lay.specs[i][3] == "json" or cells[i] is None:
                    continue
                s = series.setdefault(lay.headers[i], ([], [], lay.specs[i][2] or ""))
                s[0].append(x)
                s[1].append(float(cells[i]))
    if not series:
        raise ToolError("no values of the selected fields in the log", 1)
    series = plot_times(series, have_time)
    by_units: Dict[str, List[str]] = {}
    for name, (_x, _y, units) in series.items():
        by_units.setdefault(units, []).append(name)
    fig, axes = plt.subplots(len(by_units), 1, sharex=True, figsize=(10, 2.8 * len(by_units)), squeeze=False)
    for ax, (units, names) in zip(axes[:, 0], by_units.items()):
        for name in names:
            xs, ys, _u = series[name]
            ax.plot(xs, ys, label=name.split(" [")[0], linewidth=0.8)
        ax.set_ylabel(units or "value")
        ax.legend(loc="upper right", fontsize="small")
        ax.grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel("time (UTC)" if have_time else "packet offset [bytes]")
    fig.suptitle(os.path.basename(log))
    fig.tight_layout()
    return fig


def plot(args: argparse.Namespace) -> int:
    fields = field_list(args.fields)
    ext = os.path.splitext(args.out)[1].lower()
    if ext not in (".png", ".svg", ".html"):
        raise ToolError(f"--out must end in .png, .svg or .html (got {args.out!r})")
    need("matplotlib")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    outputs = Outputs(args.force)
    outputs.refuse_existing(args.out)  # before reading the log
    fig = figure(args.log, fields, args.device)
    with outputs.writing(args.out):
        tmp = outputs.claim(args.out)
        if ext == ".html":
            buf = io.StringIO()
            fig.savefig(buf, format="svg")
            title = os.path.basename(args.log)
            with open(tmp, "w", encoding="utf-8") as fh:
                fh.write(f"<!DOCTYPE html>\n<html><head><meta charset='utf-8'><title>{title}</title></head><body>\n")
                fh.write(buf.getvalue()[buf.getvalue().find("<svg") :])
                fh.write("</body></html>\n")
        else:
            with open(tmp, "wb") as fh:
                fig.savefig(fh, dpi=110, format=ext[1:])
    plt.close(fig)
    print(f"{args.out}: {sum(len(ax.lines) for ax in fig.axes)} series")
    return 0
