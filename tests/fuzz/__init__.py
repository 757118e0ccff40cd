"""Fuzzing: the driver, the seed corpora and the harnesses of every language."""
