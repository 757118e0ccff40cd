"""The cross-language suite (docs/conformance.md) and its tools: the `decode` / `encode` wrappers, the reference decoder, the differential rounds."""
