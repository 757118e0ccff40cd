"""The golden tree holds a generated Python package with its own tests: they run inside their
package (tests/golden/test_builds.py), never collected as tests of this directory."""

collect_ignore = ["everything"]
