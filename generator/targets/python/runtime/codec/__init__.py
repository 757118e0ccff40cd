"""The codec room of <package>: the wire format, and the one rule every command line shares.

`layout` (the field layouts the generated modules declare: Field, Struct, Enum, the operations),
`canonical` (canonical JSON: numbers, hex bytes, the line reader), `framing` (checksum, packet
builder, stream parser, field splitter), `packets` (dispatch, decoded packets, JSON lines,
columns), `samples` (packets grouped by shared timestamp) and the optional C accelerator
`_speedups` (built by setup.py from the `_speedups*.c` files); `stdio`: a standard output closed by
its reader ends a command line quietly, by SIGPIPE. The other rooms import it; it imports none of
them.
"""
