"""The project's spec (spec/) against facts its manuals state outside the per-field tables: sizes
given in prose, worked examples."""
