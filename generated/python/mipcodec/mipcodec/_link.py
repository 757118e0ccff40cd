"""What a MicroStrain MIP session needs to get through to a device (the IR's `link`,
docs/conformance.md section 8 "Getting through"): the idle, ping and resume commands as
(set, descriptor), how many times to send the idle command, the time a baud-rate change takes, the
baud rates of each model's main port and the manuals' UART bandwidth calculation. Each fact gives
the manual lines it comes from. Generated from the spec: do not edit.
"""

from __future__ import annotations

from typing import Dict, Optional, Tuple

# The IR's protocol name (the session tool's --baud message names it)
PROTOCOL = "mip"

# set_to_idle: 3dm-gx5-45-dcp.txt:363, 3dm-gx5-45-dcp.txt:759, 3dm-cv7-ins-docs.txt:8043
IDLE: Optional[Tuple[int, int]] = (0x01, 0x02)

# ping: 3dm-gx5-45-dcp.txt:748, 3dm-cv7-ins-docs.txt:8032
PING: Optional[Tuple[int, int]] = (0x01, 0x01)

# resume: 3dm-gx5-45-dcp.txt:832, 3dm-cv7-ins-docs.txt:8099
RESUME: Optional[Tuple[int, int]] = (0x01, 0x06)

# Times the idle command is sent (each with the command's reply timeout) before giving up (a decision in the spec: link.idle_attempts)
IDLE_ATTEMPTS = 3
# Milliseconds after a baud-rate change before the device answers at the new rate: 3dm-gx5-45-dcp.txt:1297, 3dm-cv7-ins-docs.txt:7417, 3dm-cv7-ins-docs.txt:8144
BAUD_SETTLE_MS: Optional[int] = 250
# The baud rates of each model's main port, ascending (empty: the manual lists none)
BAUD_RATES: Dict[str, Tuple[int, ...]] = {
    "gx5_45": (
        9600,
        19200,
        115200,
        230400,
        460800,
        921600,
    ),  # main (UART1): 3dm-gx5-45-dcp.txt:1296
    "cv7_ins": (
        115200,
        230400,
        460800,
        921600,
        3000000,
    ),  # main (UART1, port 0x11): 3dm-cv7-ins-docs.txt:2718
}
# The default baud rate of each model's main port (None: the manual states none)
DEFAULT_BAUD: Dict[str, Optional[int]] = {
    "gx5_45": 115200,
    "cv7_ins": None,
}
# The UART bandwidth calculation, 3dm-gx5-45-dcp.txt:536, 3dm-cv7-ins-docs.txt:4099: bits per second needed =
# UART_WORD_BITS * (PACKET_OVERHEAD * packets per second + sum over fields of
# (data size + FIELD_OVERHEAD) * field rate)
UART_WORD_BITS: Optional[int] = 10
PACKET_OVERHEAD: Optional[int] = 6
FIELD_OVERHEAD: Optional[int] = 2
