"""Tests of the reference documentation (Markdown and the HTML site)."""
