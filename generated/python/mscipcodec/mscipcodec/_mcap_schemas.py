"""JSON Schemas of the Memsense MS-CIP's data fields as JSON messages (the MCAP export's
`/mscip/<set>/<field>` topics, `mscipcodec.logs.mcap`), generated from the IR
(generator/mcap_schemas.py; the same columns as `_columns`): `SCHEMAS[(set, descriptor, device)]`
is the schema's JSON text, as an MCAP file stores it.
"""

from __future__ import annotations

from typing import Dict, Optional, Tuple

# the protocol's name: the first part of the JSON topics
PROTOCOL = "mscip"

SCHEMAS: Dict[Tuple[int, int, Optional[str]], str] = {
    (
        0xA2,
        0x81,
        None,
    ): '{"$schema":"http://json-schema.org/draft-07/schema#","additionalProperties":false,"description":"X, Y and Z acceleration in g.","properties":{"accel":{"items":{"description":"Acceleration [x, y, z]. [g]","type":["number","null"],"units":"g"},"maxItems":3,"minItems":3,"type":"array"},"log_offset":{"description":"the packet\'s offset in the log [bytes]","type":"integer"},"t_ns":{"description":"UTC time of the packet in ns since the Unix epoch (the time model); null when unknown","type":["integer","null"],"units":"ns"}},"required":["t_ns","log_offset","accel"],"title":"mscip.imu_data.scaled_accel: Scaled acceleration vector","type":"object"}',
    (
        0xA2,
        0x82,
        None,
    ): '{"$schema":"http://json-schema.org/draft-07/schema#","additionalProperties":false,"description":"X, Y and Z angular rate in degrees per second.","properties":{"gyro":{"items":{"description":"Angular rate [x, y, z]. [deg/s]","type":["number","null"],"units":"deg/s"},"maxItems":3,"minItems":3,"type":"array"},"log_offset":{"description":"the packet\'s offset in the log [bytes]","type":"integer"},"t_ns":{"description":"UTC time of the packet in ns since the Unix epoch (the time model); null when unknown","type":["integer","null"],"units":"ns"}},"required":["t_ns","log_offset","gyro"],"title":"mscip.imu_data.scaled_gyro: Scaled angular rate vector","type":"object"}',
    (
        0xA2,
        0x83,
        None,
    ): '{"$schema":"http://json-schema.org/draft-07/schema#","additionalProperties":false,"description":"X, Y and Z magnetic field in gauss.","properties":{"log_offset":{"description":"the packet\'s offset in the log [bytes]","type":"integer"},"mag":{"items":{"description":"Magnetic field [x, y, z]. [gauss]","type":["number","null"],"units":"gauss"},"maxItems":3,"minItems":3,"type":"array"},"t_ns":{"description":"UTC time of the packet in ns since the Unix epoch (the time model); null when unknown","type":["integer","null"],"units":"ns"}},"required":["t_ns","log_offset","mag"],"title":"mscip.imu_data.scaled_mag: Scaled magnetic field vector","type":"object"}',
    (
        0xA2,
        0x84,
        None,
    ): '{"$schema":"http://json-schema.org/draft-07/schema#","additionalProperties":false,"description":"X, Y and Z change in angle in radians.","properties":{"delta_theta":{"items":{"description":"Change in angle [x, y, z]. [rad]","type":["number","null"],"units":"rad"},"maxItems":3,"minItems":3,"type":"array"},"log_offset":{"description":"the packet\'s offset in the log [bytes]","type":"integer"},"t_ns":{"description":"UTC time of the packet in ns since the Unix epoch (the time model); null when unknown","type":["integer","null"],"units":"ns"}},"required":["t_ns","log_offset","delta_theta"],"title":"mscip.imu_data.delta_theta: Scaled delta theta vector","type":"object"}',
    (
        0xA2,
        0x85,
        None,
    ): '{"$schema":"http://json-schema.org/draft-07/schema#","additionalProperties":false,"description":"X, Y and Z change in velocity in metres per second.","properties":{"delta_velocity":{"items":{"description":"Change in velocity [x, y, z]. [m/s]","type":["number","null"],"units":"m/s"},"maxItems":3,"minItems":3,"type":"array"},"log_offset":{"description":"the packet\'s offset in the log [bytes]","type":"integer"},"t_ns":{"description":"UTC time of the packet in ns since the Unix epoch (the time model); null when unknown","type":["integer","null"],"units":"ns"}},"required":["t_ns","log_offset","delta_velocity"],"title":"mscip.imu_data.delta_velocity: Scaled delta velocity vector","type":"object"}',
    (
        0xA2,
        0x86,
        None,
    ): '{"$schema":"http://json-schema.org/draft-07/schema#","additionalProperties":false,"description":"Atmospheric pressure in millibar.","properties":{"log_offset":{"description":"the packet\'s offset in the log [bytes]","type":"integer"},"pressure":{"description":"Pressure. [mbar]","type":["number","null"],"units":"mbar"},"t_ns":{"description":"UTC time of the packet in ns since the Unix epoch (the time model); null when unknown","type":["integer","null"],"units":"ns"}},"required":["t_ns","log_offset","pressure"],"title":"mscip.imu_data.scaled_pressure: Scaled pressure","type":"object"}',
    (
        0xA2,
        0x87,
        None,
    ): '{"$schema":"http://json-schema.org/draft-07/schema#","additionalProperties":false,"description":"IMU temperature in degrees Celsius.","properties":{"log_offset":{"description":"the packet\'s offset in the log [bytes]","type":"integer"},"t_ns":{"description":"UTC time of the packet in ns since the Unix epoch (the time model); null when unknown","type":["integer","null"],"units":"ns"},"temperature":{"description":"Temperature. [degC]","type":["number","null"],"units":"degC"}},"required":["t_ns","log_offset","temperature"],"title":"mscip.imu_data.scaled_temperature: Scaled temperature","type":"object"}',
    (
        0xA2,
        0x88,
        None,
    ): '{"$schema":"http://json-schema.org/draft-07/schema#","additionalProperties":false,"description":"GPS time of the sample: seconds of the week (precision follows the output rate, 5 ms at 200 Hz), week number, and the correlation flags.","properties":{"flags":{"description":"GPS correlated time flags.","type":["integer","null"]},"log_offset":{"description":"the packet\'s offset in the log [bytes]","type":"integer"},"seconds":{"description":"GPS seconds of the week. [s]","type":["number","null"],"units":"s"},"t_ns":{"description":"UTC time of the packet in ns since the Unix epoch (the time model); null when unknown","type":["integer","null"],"units":"ns"},"week":{"description":"GPS week number. [weeks]","type":["integer","null"],"units":"weeks"}},"required":["t_ns","log_offset","seconds","week","flags"],"title":"mscip.imu_data.gps_correlated_time: GPS correlated time","type":"object"}',
    (
        0xA2,
        0x89,
        None,
    ): '{"$schema":"http://json-schema.org/draft-07/schema#","additionalProperties":false,"description":"X, Y and Z acceleration of the auxiliary accelerometer in g.","properties":{"accel":{"items":{"description":"Auxiliary acceleration [x, y, z]. [g]","type":["number","null"],"units":"g"},"maxItems":3,"minItems":3,"type":"array"},"log_offset":{"description":"the packet\'s offset in the log [bytes]","type":"integer"},"t_ns":{"description":"UTC time of the packet in ns since the Unix epoch (the time model); null when unknown","type":["integer","null"],"units":"ns"}},"required":["t_ns","log_offset","accel"],"title":"mscip.imu_data.scaled_aux_accel: Scaled aux accel vector","type":"object"}',
}
