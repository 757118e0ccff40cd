"""Tests of the generator itself: spec loading, errors, IR, lookups, the audit."""
