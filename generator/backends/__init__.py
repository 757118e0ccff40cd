"""One module per target language; see generator/pipeline.py for the interface."""
