/* mscipcodec: version of this package and hash of the spec it was generated from
 * (docs/versioning.md of the generator). Generated: do not edit. */
#ifndef MSCIPCODEC_VERSION_H
#define MSCIPCODEC_VERSION_H

/* The package's version (semantic versioning: MAJOR.MINOR.PATCH; every package of a release has it). */
#define MSCIPCODEC_VERSION_MAJOR 0
#define MSCIPCODEC_VERSION_MINOR 1
#define MSCIPCODEC_VERSION_PATCH 0
#define MSCIPCODEC_VERSION "0.1.0"
/* First 16 hex digits of the SHA-256 of the mscip protocol's canonical IR: two packages
 * with the same hash were generated from the same spec. */
#define MSCIPCODEC_SPEC_HASH "d0b17e43b10441a7"

#endif
