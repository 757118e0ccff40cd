/* mscipcodec: version of this package and hash of the spec it was generated from
 * (docs/versioning.md of the generator). Generated: do not edit. */
#ifndef MSCIPC_VERSION_H
#define MSCIPC_VERSION_H

/* The macros carry the package's C prefix (MSCIPC_, docs/packaging.md).
 * The package's version (semantic versioning: MAJOR.MINOR.PATCH; every package of a release has it). */
#define MSCIPC_VERSION_MAJOR 0
#define MSCIPC_VERSION_MINOR 1
#define MSCIPC_VERSION_PATCH 0
#define MSCIPC_VERSION "0.1.0"
/* First 16 hex digits of the SHA-256 of the mscip protocol's canonical IR: two packages
 * with the same hash were generated from the same spec. */
#define MSCIPC_SPEC_HASH "3314b414c7a35ed5"

#endif
