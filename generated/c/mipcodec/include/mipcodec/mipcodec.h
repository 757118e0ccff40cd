/* mipcodec: C99 codec of the MicroStrain MIP protocol. Generated from the spec: do not edit.
 * Everything is bounded by caller buffers; nothing allocates. */
#ifndef MIPC_MIPCODEC_H
#define MIPC_MIPCODEC_H

#include "mipcodec/version.h"
#include "mipcodec/status.h"
#include "mipcodec/framing.h"
#include "mipcodec/parser.h"
#include "mipcodec/field_iter.h"
#include "mipcodec/samples.h"
#include "mipcodec/clock.h"
#include "mipcodec/types.h"
#include "mipcodec/reserved.h"
#include "mipcodec/sets/base.h"
#include "mipcodec/sets/threedm.h"
#include "mipcodec/sets/filter.h"
#include "mipcodec/sets/gnss.h"
#include "mipcodec/sets/aiding.h"
#include "mipcodec/sets/system.h"
#include "mipcodec/sets/sensor.h"
#include "mipcodec/sets/gnss_data.h"
#include "mipcodec/sets/filter_data.h"
#include "mipcodec/sets/gnss_receiver_1.h"
#include "mipcodec/sets/gnss_receiver_2.h"
#include "mipcodec/sets/gnss_corrections.h"
#include "mipcodec/sets/gnss_external.h"
#include "mipcodec/sets/system_data.h"
#include "mipcodec/sets/shared.h"
#include "mipcodec/dispatch.h"
#include "mipcodec/session.h"
#include "mipcodec/link.h"
#include "mipcodec/commands.h"
#include "mipcodec/json.h"

#endif
