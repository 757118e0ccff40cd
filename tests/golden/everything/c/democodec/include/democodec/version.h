/* democodec: version of this package and hash of the spec it was generated from
 * (docs/versioning.md of the generator). Generated: do not edit. */
#ifndef DEMOC_VERSION_H
#define DEMOC_VERSION_H

/* The macros carry the package's C prefix (DEMOC_, docs/packaging.md).
 * The package's version (semantic versioning: MAJOR.MINOR.PATCH; every package of a release has it). */
#define DEMOC_VERSION_MAJOR 2
#define DEMOC_VERSION_MINOR 10
#define DEMOC_VERSION_PATCH 3
#define DEMOC_VERSION "2.10.3"
/* First 16 hex digits of the SHA-256 of the demo protocol's canonical IR: two packages
 * with the same hash were generated from the same spec. */
#define DEMOC_SPEC_HASH "f5fc3f0d91525c4c"

#endif
