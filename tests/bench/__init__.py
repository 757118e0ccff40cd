"""Benchmarks of the four languages (`make bench`) and the tests of their streams."""
