/* democodec: C99 codec of the Demo protocol with every spec feature protocol. Generated from the spec: do not
 * edit. Everything is bounded by caller buffers; nothing allocates. */
#ifndef DEMOC_DEMOCODEC_H
#define DEMOC_DEMOCODEC_H

#include "democodec/version.h"
#include "democodec/status.h"
#include "democodec/framing.h"
#include "democodec/parser.h"
#include "democodec/field_iter.h"
#include "democodec/samples.h"
#include "democodec/clock.h"
#include "democodec/types.h"
#include "democodec/reserved.h"
#include "democodec/sets/commands.h"
#include "democodec/sets/data.h"
#include "democodec/sets/receiver_1.h"
#include "democodec/sets/receiver_2.h"
#include "democodec/sets/shared.h"
#include "democodec/dispatch.h"
#include "democodec/session.h"
#include "democodec/link.h"
#include "democodec/commands.h"
#include "democodec/json.h"

#endif
