"""The simulator's command line: `python -m mscipcodec.sim` (docs/conformance.md section 9)."""

from __future__ import annotations

import argparse
import math
import sys
from typing import List, Optional, Tuple

from .. import _link, registry
from ..codec.stdio import closed_stdout
from . import (
    FAULT_KINDS,
    IDENTITY_FLAGS,
    MAX_REPLAY_BYTES,
    MAX_SECONDS,
    SPEED_RANGE,
    Fault,
    Simulator,
    check_speed,
    parse_identity,
    replay_chunks,
)
from .hosts import BAUD_CODES, serve
from .world import gps_start_of_utc


# ---------------------------------------------------------------------------------------- command
def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog=f"python -m {__package__}",
        description="A simulated device answering commands and streaming data as the spec says "
        "(docs/conformance.md section 9). Prints the address it listens on, then serves until terminated.",
    )
    p.add_argument(
        "--listen",
        required=True,
        help="pty, pty:PATH (PATH: a symbolic link to the pty, replaced when it is reopened), "
        "or tcp:HOST:PORT (port 0: a free port; up to 8 hosts at once, each receiving all the device sends)",
    )
    p.add_argument("--device", help=f"device model: {', '.join(registry.DEVICES)} (default {registry.DEVICES[0]})")
    p.add_argument("--seed", type=int, default=0, help="seed of the simulated values (default 0)")
    p.add_argument(
        "--scenario",
        default="static",
        help="the simulated world: static (on a bench), circle (driving a 50 m circle), file:PATH (a trajectory)",
    )
    p.add_argument(
        "--baud",
        action="store_true",
        help="a baud rate change (written) is acknowledged at the old rate, then the pty serves at the new one only",
    )
    p.add_argument(
        "--start-baud",
        type=int,
        metavar="RATE",
        help="the pty serves at RATE only from the start, as a device whose port was set to it "
        "(a host at another rate reads garbage)",
    )
    p.add_argument(
        "--stream-full",
        action="store_true",
        help="stream at the highest data rates from the start: every data set with a base rate, every data "
        "quantity the model documents in it, at decimation 1 (until the host changes the format or stream)",
    )
    p.add_argument(
        "--replug",
        action="append",
        default=[],
        metavar="START:END",
        help="the port goes away at START and a fresh one comes back at END, seconds of real time since the first "
        "bytes a host sent (pty: closed and reopened, pty:PATH re-pointed; TCP: connections and listener closed, "
        "listening again on the same port); the device keeps its settings (repeatable)",
    )
    p.add_argument(
        "--gnss-outage",
        action="append",
        default=[],
        metavar="START:END",
        help="no GNSS fix from START to END seconds of simulated time (repeatable)",
    )
    p.add_argument(
        "--mag-disturbance",
        action="append",
        default=[],
        metavar="START:END",
        help="a magnetic disturbance near the device from START to END seconds of simulated time (repeatable): "
        "the magnetometer reads it, a filter using the magnetometer for heading rejects it and flags it",
    )
    p.add_argument(
        "--rtk-corrections",
        action="append",
        default=[],
        metavar="START:END",
        help="RTK corrections reach the receivers from START to END seconds of simulated time (repeatable): "
        "with a fix their solution goes to RTK float, then RTK fixed (devices whose spec describes RTK)",
    )
    p.add_argument(
        "--start-utc",
        metavar="TIME",
        help="the UTC time (YYYY-MM-DDTHH:MM:SS[Z]) of the device's start: its GPS time (default 2026-01-07T23:59:42Z)",
    )
    p.add_argument(
        "--speed",
        type=float,
        default=1.0,
        help=f"simulated seconds per real second, {SPEED_RANGE[0]:g} to {SPEED_RANGE[1]:g} (default 1)",
    )
    # the simulated clocks (clocks.py, docs/timesync.md)
    p.add_argument(
        "--clock-drift",
        type=float,
        default=0.0,
        metavar="PPM",
        help=f"the device's reference clock runs fast by PPM against true time (|PPM| <= {MAX_DRIFT_PPM:g}; default 0)",
    )
    p.add_argument(
        "--link-jitter",
        type=float,
        default=0.0,
        metavar="MS",
        help=f"each data packet waits a random 0 to MS ms of simulated time before it is sent, in order "
        f"(0 to {MAX_JITTER_MS:g}; default 0)",
    )
    p.add_argument(
        "--pps-input",
        action="store_true",
        help="a PPS is applied to the device's PPS pin (CV7: its GPIO, with PPS source gpio; GX5-45: pin 7)",
    )
    for flag, item in IDENTITY_FLAGS.items():
        p.add_argument(
            f"--{flag}", metavar="VALUE", help=f"the {item.replace('_', ' ')} the device reports (default: the spec's)"
        )
    p.add_argument("--replay", metavar="FILE", help="send the packets of a capture instead of simulating")
    p.add_argument("--fast", action="store_true", help="with --replay: as fast as possible, not at the recorded pace")
    for kind, what in (
        ("drop", "COMMAND[@N]: send no reply to COMMAND"),
        ("delay", "COMMAND:MS[@N]: send the reply MS milliseconds late"),
        ("corrupt", "COMMAND[@N]: send the reply with a wrong checksum"),
        ("split", "COMMAND[@N]: send the reply in two writes 20 ms apart"),
        ("garbage", "COMMAND[:BYTES][@N]: send random bytes (7 by default) before the reply"),
        ("nack", "COMMAND[:CODE][@N]: answer COMMAND with a NACK (default: the invalid-parameter code)"),
    ):
        p.add_argument(
            f"--{kind}",
            action="append",
            default=[],
            metavar="SPEC",
            help=what + "; COMMAND a name or 'all', @N the first N times only",
        )
    return p


def _outage(text: str, option: str = "--gnss-outage") -> Tuple[float, float]:
    start, _, end = text.partition(":")
    try:
        a, b = float(start), float(end)
    except ValueError:
        raise ValueError(f"{option} {text}: expected START:END in seconds") from None
    if not (math.isfinite(a) and math.isfinite(b) and 0 <= a < b <= MAX_SECONDS):
        raise ValueError(f"{option} {text}: expected 0 <= START < END <= {MAX_SECONDS:.0f} (seconds)")
    return a, b


MAX_DRIFT_PPM = 10000.0
MAX_JITTER_MS = 1000.0


def _clock_options(drift: float, jitter: float) -> None:
    """--clock-drift and --link-jitter: finite, in range (ValueError names it)."""
    if not (math.isfinite(drift) and abs(drift) <= MAX_DRIFT_PPM):
        raise ValueError(f"--clock-drift {drift:g}: expected ppm from -{MAX_DRIFT_PPM:g} to {MAX_DRIFT_PPM:g}")
    if not (math.isfinite(jitter) and 0 <= jitter <= MAX_JITTER_MS):
        raise ValueError(f"--link-jitter {jitter:g}: expected milliseconds from 0 to {MAX_JITTER_MS:g}")


def _replay_file(path: str, fast: bool) -> List[Tuple[float, bytes]]:
    """The packets of --replay FILE, read no further than MAX_REPLAY_BYTES (a larger file, or an
    endless one such as /dev/zero, is refused)."""
    try:
        with open(path, "rb") as f:
            data = f.read(MAX_REPLAY_BYTES + 1)
    except OSError as e:
        raise ValueError(f"--replay {path}: cannot read it: {e.strerror or e}") from None
    if len(data) > MAX_REPLAY_BYTES:
        raise ValueError(f"--replay {path}: larger than {MAX_REPLAY_BYTES >> 20} MiB (the most a replay reads)")
    return replay_chunks(data, fast=fast)


def _start_baud(rate: int, device: str, listen: str) -> int:
    """--start-baud: a rate of the model's port (_link.BAUD_RATES, from the manuals; a model whose
    manual lists none: any rate of this system's serial lines), over a pty."""
    if not listen.startswith("pty"):
        raise ValueError("--start-baud needs --listen pty (TCP has no baud rate)")
    rates = _link.BAUD_RATES.get(device, ())
    if rates and rate not in rates:
        raise ValueError(
            f"--start-baud {rate}: not a baud rate of {device} (expected one of {', '.join(map(str, rates))})"
        )
    if rate not in BAUD_CODES.values():
        raise ValueError(f"--start-baud {rate}: not a baud rate of this system's serial lines")
    return rate


def main(argv: Optional[List[str]] = None) -> int:
    parser = _parser()
    args = parser.parse_args(argv)
    try:
        check_speed(args.speed)
        _clock_options(args.clock_drift, args.link_jitter)
        faults = [Fault.parse(kind, text) for kind in FAULT_KINDS for text in getattr(args, kind)]
        outages = [_outage(text) for text in args.gnss_outage]
        disturbances = [_outage(text, "--mag-disturbance") for text in args.mag_disturbance]
        corrections = [_outage(text, "--rtk-corrections") for text in args.rtk_corrections]
        replug = [_outage(text, "--replug") for text in args.replug]
        device = args.device or registry.DEVICES[0]
        if device not in registry.DEVICES:
            raise ValueError(f"--device {device}: unknown (expected one of {', '.join(registry.DEVICES)})")
        if args.start_baud is not None:
            _start_baud(args.start_baud, device, args.listen)
        replay = None
        sim = None
        if args.replay:
            replay = _replay_file(args.replay, args.fast)
        else:
            identity = dict(
                parse_identity(device, flag, getattr(args, flag))
                for flag in IDENTITY_FLAGS
                if getattr(args, flag) is not None
            )
            sim = Simulator(
                device,
                args.seed,
                faults,
                scenario=args.scenario,
                speed=args.speed,
                baud=args.baud or args.start_baud is not None,
                identity=identity,
                stream_full=args.stream_full,
            )
            sim.world.gnss_outages.extend(outages)
            sim.clocks.drift_ppm, sim.clocks.jitter_ms = args.clock_drift, args.link_jitter
            sim.clocks.pps_input = args.pps_input
            sim.world.mag_disturbances.extend(disturbances)
            sim.world.rtk_corrections.extend(corrections)
            if args.start_utc is not None:
                sim.world.gps_start = gps_start_of_utc(args.start_utc)
        serve(args.listen, sim, replay, replug=replug, start_baud=args.start_baud)
    except ValueError as e:
        print(f"{parser.prog}: {e}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # stdout closed by its reader: quietly, by SIGPIPE (codec.stdio)
        return closed_stdout()
    except OSError as e:
        print(f"{parser.prog}: {e.strerror or e}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        return 0
    return 0
