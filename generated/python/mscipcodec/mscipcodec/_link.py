"""What a Memsense MS-CIP session needs to get through to a device (the IR's `link`,
docs/conformance.md section 8 "Getting through"): the idle, ping and resume commands as
(set, descriptor), how many times to send the idle command, the time a baud-rate change takes, the
baud rates of each model's main port and the manuals' UART bandwidth calculation. Each fact gives
the manual lines it comes from. Generated from the spec: do not edit.
"""

from __future__ import annotations

from typing import Dict, Optional, Tuple

# The IR's protocol name (the session tool's --baud message names it)
PROTOCOL = "mscip"

# the manual names no such command
IDLE: Optional[Tuple[int, int]] = None

# ping: ms-cip-doc00419-revM.txt:166
PING: Optional[Tuple[int, int]] = (0x01, 0x02)

# the manual names no such command
RESUME: Optional[Tuple[int, int]] = None

# Times the idle command is sent (each with the command's reply timeout) before giving up (a decision in the spec: link.idle_attempts)
IDLE_ATTEMPTS = 3
# Milliseconds after a baud-rate change before the device answers at the new rate: ms-cip-doc00419-revM.txt:528
BAUD_SETTLE_MS: Optional[int] = 0
# The baud rates of each model's main port, ascending (empty: the manual lists none)
BAUD_RATES: Dict[str, Tuple[int, ...]] = {
    "ms_imu3020": (
        9600,
        19200,
        115200,
        230400,
        460800,
        921600,
    ),  # UART: ms-cip-doc00419-revM.txt:539
}
# The default baud rate of each model's main port (None: the manual states none)
DEFAULT_BAUD: Dict[str, Optional[int]] = {
    "ms_imu3020": None,
}
# The manual gives no UART bandwidth calculation
UART_WORD_BITS: Optional[int] = None
PACKET_OVERHEAD: Optional[int] = None
FIELD_OVERHEAD: Optional[int] = None
