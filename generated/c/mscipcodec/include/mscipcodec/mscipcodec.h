/* mscipcodec: C99 codec of the Memsense MS-CIP protocol. Generated from the spec: do not edit.
 * Everything is bounded by caller buffers; nothing allocates. */
#ifndef MSCIPC_MSCIPCODEC_H
#define MSCIPC_MSCIPCODEC_H

#include "mscipcodec/version.h"
#include "mscipcodec/status.h"
#include "mscipcodec/framing.h"
#include "mscipcodec/parser.h"
#include "mscipcodec/field_iter.h"
#include "mscipcodec/samples.h"
#include "mscipcodec/clock.h"
#include "mscipcodec/types.h"
#include "mscipcodec/reserved.h"
#include "mscipcodec/sets/base.h"
#include "mscipcodec/sets/imu_config.h"
#include "mscipcodec/sets/imu_data.h"
#include "mscipcodec/dispatch.h"
#include "mscipcodec/session.h"
#include "mscipcodec/link.h"
#include "mscipcodec/commands.h"
#include "mscipcodec/json.h"

#endif
