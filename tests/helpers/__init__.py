"""Facts every Python test needs once: the Fletcher-16 and the packet builder (packets.py), and
the import of a generated Python package from generated/python/ (generated.py)."""
