"""The Python fuzz harnesses (atheris) and their regression replay."""
