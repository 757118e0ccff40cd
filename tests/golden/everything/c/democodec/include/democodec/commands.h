/* The typed command API of Demo protocol with every spec feature (docs/conformance.md section 8): one
 * function per command and function it supports, typed parameters in, the typed reply out, over a link
 * (democodec/link.h). Each returns the result's kind: DEMOC_RESULT_ACK or DEMOC_RESULT_SENT on
 * success; DEMOC_RESULT_REFUSED when the link's device does not support the command or function
 * (nothing is sent; the check is the session's check_device), NACK, TIMEOUT, INVALID or TRANSPORT.
 * The link's last result (link->result) holds the code and the error text. *reply (may be NULL)
 * is written on ACK only. Generated: do not edit. */
#ifndef DEMOC_COMMANDS_H
#define DEMOC_COMMANDS_H

#include "democodec/link.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Ping. */
democ_result_kind_t democ_commands_ping(democ_link_t *link);
/** Configure: function write. */
democ_result_kind_t democ_commands_configure_write(democ_link_t *link, uint8_t instance, democ_mode_t mode,
                                                   const democ_trigger_params_t *params, bool suppress_ack);
/** Configure: function read. */
democ_result_kind_t democ_commands_configure_read(democ_link_t *link, uint8_t instance,
                                                  democ_commands_configuration_t *reply);
/** Configure: function save. */
democ_result_kind_t democ_commands_configure_save(democ_link_t *link, uint8_t instance);
/** Per-device command. */
democ_result_kind_t democ_commands_per_device_dev_a(democ_link_t *link, uint32_t a);
/** Per-device command. */
democ_result_kind_t democ_commands_per_device_dev_b(democ_link_t *link, uint64_t b, uint8_t extra);

#ifdef __cplusplus
}
#endif

#endif
