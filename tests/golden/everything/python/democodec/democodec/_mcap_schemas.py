"""JSON Schemas of the Demo protocol with every spec feature's data fields as JSON messages (the MCAP export's
`/demo/<set>/<field>` topics, `democodec.logs.mcap`), generated from the IR
(generator/mcap_schemas.py; the same columns as `_columns`): `SCHEMAS[(set, descriptor, device)]`
is the schema's JSON text, as an MCAP file stores it.
"""

from __future__ import annotations

from typing import Dict, Optional, Tuple

# the protocol's name: the first part of the JSON topics
PROTOCOL = "demo"

SCHEMAS: Dict[Tuple[int, int, Optional[str]], str] = {
    (
        0x90,
        0x01,
        None,
    ): '{"$schema":"http://json-schema.org/draft-07/schema#","additionalProperties":false,"description":"Sample","properties":{"big":{"type":["integer","null"]},"f":{"type":["number","null"]},"log_offset":{"description":"the packet\'s offset in the log [bytes]","type":"integer"},"quat":{"items":{"type":["number","null"]},"maxItems":4,"minItems":4,"type":"array"},"small":{"type":["integer","null"]},"t_ns":{"description":"UTC time of the packet in ns since the Unix epoch (the time model); null when unknown","type":["integer","null"],"units":"ns"}},"required":["t_ns","log_offset","quat","big","small","f"],"title":"demo.data.sample: Sample","type":"object"}',
    (
        0x91,
        0x03,
        None,
    ): '{"$schema":"http://json-schema.org/draft-07/schema#","additionalProperties":false,"description":"LLH position","properties":{"latitude":{"description":" [deg]","type":["number","null"],"units":"deg"},"log_offset":{"description":"the packet\'s offset in the log [bytes]","type":"integer"},"longitude":{"description":" [deg]","type":["number","null"],"units":"deg"},"t_ns":{"description":"UTC time of the packet in ns since the Unix epoch (the time model); null when unknown","type":["integer","null"],"units":"ns"},"valid_flags":{"type":["integer","null"]}},"required":["t_ns","log_offset","latitude","longitude","valid_flags"],"title":"demo.receiver_1.llh_position: LLH position","type":"object"}',
    (
        0x92,
        0x03,
        None,
    ): '{"$schema":"http://json-schema.org/draft-07/schema#","additionalProperties":false,"description":"LLH position","properties":{"latitude":{"description":" [deg]","type":["number","null"],"units":"deg"},"log_offset":{"description":"the packet\'s offset in the log [bytes]","type":"integer"},"longitude":{"description":" [deg]","type":["number","null"],"units":"deg"},"t_ns":{"description":"UTC time of the packet in ns since the Unix epoch (the time model); null when unknown","type":["integer","null"],"units":"ns"},"valid_flags":{"type":["integer","null"]}},"required":["t_ns","log_offset","latitude","longitude","valid_flags"],"title":"demo.receiver_2.llh_position: LLH position","type":"object"}',
    (
        0xFF,
        0xD3,
        None,
    ): '{"$schema":"http://json-schema.org/draft-07/schema#","additionalProperties":false,"description":"Timestamp","properties":{"log_offset":{"description":"the packet\'s offset in the log [bytes]","type":"integer"},"nanoseconds":{"type":["integer","null"]},"t_ns":{"description":"UTC time of the packet in ns since the Unix epoch (the time model); null when unknown","type":["integer","null"],"units":"ns"}},"required":["t_ns","log_offset","nanoseconds"],"title":"demo.shared.timestamp: Timestamp","type":"object"}',
}
