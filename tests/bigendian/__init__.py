"""The C library on a big-endian host (s390x under qemu-user)."""
