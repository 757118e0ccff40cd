"""The project's tests as one package: run pytest and the test scripts from the project root
(`python -m pytest tests/...`, `python -m tests.conformance.differential`), so that `tests.*` and
`generator` import without touching sys.path."""
