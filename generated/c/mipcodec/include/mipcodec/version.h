/* mipcodec: version of this package and hash of the spec it was generated from
 * (docs/versioning.md of the generator). Generated: do not edit. */
#ifndef MIPC_VERSION_H
#define MIPC_VERSION_H

/* The macros carry the package's C prefix (MIPC_, docs/packaging.md).
 * The package's version (semantic versioning: MAJOR.MINOR.PATCH; every package of a release has it). */
#define MIPC_VERSION_MAJOR 0
#define MIPC_VERSION_MINOR 1
#define MIPC_VERSION_PATCH 0
#define MIPC_VERSION "0.1.0"
/* First 16 hex digits of the SHA-256 of the mip protocol's canonical IR: two packages
 * with the same hash were generated from the same spec. */
#define MIPC_SPEC_HASH "fc07cd5fc98d115a"

#endif
