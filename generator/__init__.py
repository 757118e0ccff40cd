"""Protocol code generator: spec/ (YAML) -> validated IR -> generated/ (C, C++, Python, Rust, docs)."""
