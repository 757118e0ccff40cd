/* democodec: version of this package and hash of the spec it was generated from
 * (docs/versioning.md of the generator). Generated: do not edit. */
#ifndef DEMOCODEC_VERSION_H
#define DEMOCODEC_VERSION_H

/* The package's version (semantic versioning: MAJOR.MINOR.PATCH; every package of a release has it). */
#define DEMOCODEC_VERSION_MAJOR 2
#define DEMOCODEC_VERSION_MINOR 10
#define DEMOCODEC_VERSION_PATCH 3
#define DEMOCODEC_VERSION "2.10.3"
/* First 16 hex digits of the SHA-256 of the demo protocol's canonical IR: two packages
 * with the same hash were generated from the same spec. */
#define DEMOCODEC_SPEC_HASH "1d3f1495a97aed54"

#endif
