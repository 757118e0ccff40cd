"""getting_started FILE: builds a ping command with mscipcodec, then decodes the packets
in FILE (read in blocks, as from a serial port) and prints the name of every field.

Run it with the package importable (installed, or PYTHONPATH=generated/python/mscipcodec).
The documentation quotes the parts between the [...] and [end] comments. Generated: do not edit.
"""

import sys
from typing import List, Union

from mscipcodec import DecodedField, Nmea, PacketBuilder, Parser, RawPacket, Rtcm, Skip, decode_packet
from mscipcodec.base import Ping


# [build-command]
def print_command() -> None:
    """Builds the command with its typed value and prints the packet bytes."""
    command = PacketBuilder(Ping.SET).add(Ping()).build()
    print("command", command.hex())


# [end]


# [parse-stream]
def on_event(event: Union[RawPacket, Skip, Nmea, Rtcm]) -> None:
    """Prints one parser event: a packet with the names of its fields, a run of skipped bytes, or
    an NMEA sentence or RTCM3 frame between packets (protocols whose framing has them)."""
    if isinstance(event, Skip):
        print("skipped", event.count)
        return
    if not isinstance(event, RawPacket):
        print(type(event).__name__.lower(), len(event.data))
        return
    packet = decode_packet(event.data)
    # A field that does not decode, or trailing bytes that are not a whole field, print "?".
    names = [entry.name if isinstance(entry, DecodedField) else "?" for entry in packet.fields]
    print(f"packet set=0x{packet.set:02x} fields={','.join(names)}")


# [end]


# [read-file]
def decode_file(path: str) -> int:
    """Feeds the file to the parser block by block, then flushes it at the end of the input."""
    parser = Parser()
    try:
        with open(path, "rb") as file:
            while block := file.read(4096):
                for event in parser.feed(block):
                    on_event(event)
    except OSError as error:
        print(f"getting_started: cannot read {path}: {error.strerror}", file=sys.stderr)
        return 1
    for event in parser.flush():
        on_event(event)
    return 0


# [end]


def main(argv: List[str]) -> int:
    if len(argv) != 2:
        print("usage: getting_started FILE", file=sys.stderr)
        return 2
    print_command()
    return decode_file(argv[1])


if __name__ == "__main__":
    sys.exit(main(sys.argv))
