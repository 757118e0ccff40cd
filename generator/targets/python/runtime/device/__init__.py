"""The device room of <package>: configuring a device.

`settings` (a settings file validated, normalized, diffed against a device and applied),
`budget` (the link budget of a streaming configuration), `record` (the recorder: the device's
stream to a log file, docs/record.md) and `cli` (the device command line,
`<package>-device` and `python -m <package> device`). Imports the codec and session rooms.
"""
