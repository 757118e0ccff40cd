/* Canonical JSON lines of docs/conformance.md section 4: packet and skip lines, number
 * formatting, and the reverse (JSON line -> bytes) used by the encode tool. */
/*
 * Pointer arguments (every function of this header): a pointer must be valid for what the function
 * reads or writes, and not NULL, unless its documentation says "may be NULL". A buffer pointer
 * paired with a size (bytes/len, buf/cap, out/cap) may be NULL when that size is 0. Debug builds
 * (without NDEBUG) check these preconditions with assert(); docs/conformance.md section 7.
 */
#ifndef CODEC_JSON_H
#define CODEC_JSON_H

#include "codec/dispatch.h"
#include "codec/session.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Room for any number codec_json_format_double/float print (with quotes for inf/nan). */
#define CODEC_JSON_NUMBER_MAX 40

/**
 * A double as canonical JSON: the shortest decimal that round-trips, laid out like Python's
 * repr(float); "inf", "-inf", "nan" or "nan:0x<16 hex digits>" (in quotes) otherwise.
 * Returns the length (like snprintf; buf is NUL-terminated when cap > 0).
 */
size_t codec_json_format_double(double v, char *buf, size_t cap);
/** A float: widened to double exactly, NaN bits printed with 8 hex digits. */
size_t codec_json_format_float(float v, char *buf, size_t cap);

/** Bytes as a canonical JSON string (byte b -> U+00bb, escaped per section 4), like snprintf. */
size_t codec_json_format_string(const char *bytes, size_t n, char *buf, size_t cap);

/**
 * The JSON line (without newline) of a packet the parser reported: every field decoded, or
 * raw with its error, trailing bytes last. Returns the full length, like snprintf.
 */
size_t codec_json_packet_line(const uint8_t *packet, size_t len, uint64_t offset, codec_device_t device,
                              char *out, size_t cap);
/**
 * The JSON line of codec_json_packet_line, from a packet that codec_decode_packet or
 * codec_decode_packet_cached decoded (issue 38; the decode tool's --decoder): the fields of index
 * (may be NULL: none) are written from their typed members, and the entries the decoder passed to
 * other, copied in order into others[0..other_count), through the general path. The same bytes as
 * codec_json_packet_line for a correct decoder. Returns the full length, like snprintf, or 0 when
 * the decoded fields and the entries passed on do not make up the packet's entries in order.
 */
size_t codec_json_decoded_packet_line(const uint8_t *packet, size_t len, uint64_t offset,
                                      codec_device_t device, const codec_packet_index_t *index,
                                      const codec_field_entry_t *others, size_t other_count, char *out,
                                      size_t cap);
/** The JSON line (without newline) of a skip run. Returns the full length, like snprintf. */
size_t codec_json_skip_line(uint64_t offset, const uint8_t *bytes, size_t n, char *out, size_t cap);
/** The JSON line (without newline) of a foreign frame (a CODEC_EVENT_NMEA or CODEC_EVENT_RTCM
 * event; docs/conformance.md section 5). Returns the full length, like snprintf. */
size_t codec_json_foreign_line(const codec_event_t *ev, char *out, size_t cap);

/**
 * Turns one JSON line (a packet or a skip run, as printed by the decoder) back into bytes:
 * packets are rebuilt from their fields with lengths and checksum recomputed.
 * Returns CODEC_OK, CODEC_ERR_BUFFER (out too small) or CODEC_ERR_JSON with a message in msg.
 * out_len may be NULL; *out_len receives the number of bytes written.
 */
codec_status_t codec_json_encode_line(const char *line, size_t len, uint8_t *out, size_t cap, size_t *out_len,
                                      char *msg, size_t msg_cap);

/**
 * The session tool's result line of docs/conformance.md section 8 (without newline):
 * {"line":N,"result":..,"code":C|null,"reply":[...]} and "error" for invalid and refused.
 * The reply fields are decoded for `device`. Returns the full length, like snprintf.
 */
size_t codec_json_result_line(const codec_result_t *result, uint64_t line, codec_device_t device, char *out,
                              size_t cap);

/**
 * The command of one session tool input line: a packet line as codec_json_encode_line accepts
 * it with exactly one decoded field (its "device" picks the layout of a per-device field).
 * Returns CODEC_OK, or CODEC_ERR_JSON with the reason in msg (a field that is not a command is
 * refused by codec_command_facts, not here).
 */
codec_status_t codec_json_command_line(const char *line, size_t len, codec_field_value_t *out, char *msg,
                                       size_t msg_cap);

#ifdef __cplusplus
}
#endif

#endif
