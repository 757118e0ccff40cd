"""The Python benchmark (run in its own process by tests/bench/run.py)."""
