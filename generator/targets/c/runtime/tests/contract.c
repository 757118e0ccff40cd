/* The C runtime contract (docs/runtime-contract.md, "C"): everything the runtime takes from the
 * generated files, stated with the types the runtime uses. Built into the runtime's test binary
 * against the package rendered from tests/runtime_specs/ (CMakeLists.txt): a template that drops a
 * macro fails the #if below, one that changes a prototype is a conflicting-types error, and one
 * that stops defining a function fails the link (codec_contract holds every address). */
#include "codec/dispatch.h"
#include "codec/protocol.h"
#include "codec/session.h"
#include "layouts_internal.h"

/* include/codec/protocol.h */
#if !defined(CODEC_LITTLE_ENDIAN) || !defined(CODEC_SYNC_SIZE) || !defined(CODEC_SYNC_BYTES) ||              \
    !defined(CODEC_HEADER_SIZE) || !defined(CODEC_SET_OFFSET) || !defined(CODEC_LENGTH_OFFSET) ||            \
    !defined(CODEC_MAX_PAYLOAD) || !defined(CODEC_CHECKSUM_SIZE) || !defined(CODEC_CHECKSUM_SUM1_FIRST) ||   \
    !defined(CODEC_MAX_PACKET) || !defined(CODEC_FIELD_HEADER_SIZE) ||                                       \
    !defined(CODEC_FIELD_LENGTH_OFFSET) || !defined(CODEC_FIELD_DESCRIPTOR_OFFSET) ||                        \
    !defined(CODEC_MAX_FIELD_DATA) || !defined(CODEC_NMEA_MAX)
#error "codec/protocol.h lacks a framing constant of the runtime contract"
#endif
#if !defined(CODEC_SAMPLE_DATA_SET_COUNT) || !defined(CODEC_SAMPLE_SETS) ||                                  \
    !defined(CODEC_SAMPLE_DATA_SETS) || !defined(CODEC_SAMPLE_FIRST_SHARED) ||                               \
    !defined(CODEC_SAMPLE_TIMESTAMPS) || !defined(CODEC_SAMPLE_STAMP_DESCRIPTORS) ||                         \
    !defined(CODEC_SAMPLE_STAMP_SIZES) || !defined(CODEC_SAMPLE_KEY_MAX)
#error "codec/protocol.h lacks a samples constant of the runtime contract"
#endif
#if !defined(CODEC_SESSION_ACK_DESCRIPTOR) || !defined(CODEC_SESSION_ACK_OK) ||                              \
    !defined(CODEC_SESSION_MAX_EXPECT) || !defined(CODEC_PATH_MAX_DEPTH) ||                                  \
    !defined(CODEC_ERROR_MESSAGE_MAX) || !defined(CODEC_NAME_MAX) || !defined(CODEC_PROTOCOL_NAME)
#error "codec/protocol.h lacks a session or limit constant of the runtime contract"
#endif
#if !defined(CODEC_LINK_HAS_IDLE) || !defined(CODEC_LINK_IDLE_SET) ||                                        \
    !defined(CODEC_LINK_IDLE_DESCRIPTOR) || !defined(CODEC_LINK_HAS_PING) ||                                 \
    !defined(CODEC_LINK_PING_SET) || !defined(CODEC_LINK_PING_DESCRIPTOR) ||                                 \
    !defined(CODEC_LINK_HAS_RESUME) || !defined(CODEC_LINK_RESUME_SET) ||                                    \
    !defined(CODEC_LINK_RESUME_DESCRIPTOR) || !defined(CODEC_LINK_IDLE_ATTEMPTS) ||                          \
    !defined(CODEC_LINK_BAUD_SETTLE_MS) || !defined(CODEC_LINK_HAS_BANDWIDTH) ||                             \
    !defined(CODEC_LINK_UART_WORD_BITS) || !defined(CODEC_LINK_PACKET_OVERHEAD) ||                           \
    !defined(CODEC_LINK_FIELD_OVERHEAD)
#error "codec/protocol.h lacks a link constant of the runtime contract"
#endif
#if !defined(CODEC_CLOCK_BUCKET_NS) || !defined(CODEC_CLOCK_BUCKETS) || !defined(CODEC_CLOCK_MIN_BUCKETS) || \
    !defined(CODEC_CLOCK_RESTART_NS)
#error "codec/protocol.h lacks a clock model constant of the runtime contract"
#endif
#if !defined(CODEC_IDENTITY_HAS) || !defined(CODEC_IDENTITY_SET) || !defined(CODEC_IDENTITY_COMMAND) ||      \
    !defined(CODEC_IDENTITY_REPLY) || !defined(CODEC_IDENTITY_MODEL_OFFSET) ||                               \
    !defined(CODEC_IDENTITY_MODEL_LENGTH) || !defined(CODEC_IDENTITY_UNKNOWN_CODES) ||                       \
    !defined(CODEC_IDENTITY_UNKNOWN_COUNT)
#error "codec/protocol.h lacks an identity constant of the runtime contract"
#endif
#if CODEC_MAX_PACKET != CODEC_HEADER_SIZE + CODEC_MAX_PAYLOAD + CODEC_CHECKSUM_SIZE
#error "CODEC_MAX_PACKET is not header + maximum payload + checksum"
#endif
static inline int codec_field_length_adjust(uint8_t set, uint8_t descriptor);

/* include/codec/dispatch.h (defined in dispatch.c, dispatch_json.c) */
const char *codec_device_id(codec_device_t device);
bool codec_device_from_id(const char *id, codec_device_t *out);
const char *codec_device_title(codec_device_t device);
const char *codec_device_manual(codec_device_t device);
bool codec_device_supports(codec_device_t device, uint8_t set, uint8_t descriptor);
const uint32_t *codec_device_baud_rates(codec_device_t device, size_t *count);
uint32_t codec_device_default_baud(codec_device_t device);
codec_set_kind_t codec_set_kind(uint8_t set);
const codec_layout_info_t *codec_layout_info(codec_field_id_t id);
const codec_field_info_t *codec_find_field(uint8_t set, uint8_t descriptor, codec_status_t *why);
codec_status_t codec_decode_field(uint8_t set, uint8_t descriptor, const uint8_t *data, size_t len,
                                  codec_device_t device, codec_field_value_t *out, codec_decode_error_t *err);
codec_status_t codec_encode_field(const codec_field_value_t *value, uint8_t *buf, size_t cap,
                                  size_t *len_out);

/* src/layouts_internal.h */
void codec_value_to_json(codec_jw_t *w, const codec_field_value_t *value);
void codec_layout_to_json(codec_jw_t *w, codec_field_id_t id, const void *in);
int codec_value_from_json(codec_jr_t *jr, size_t pos, codec_field_id_t id, codec_field_value_t *value);

/* src/session_facts.c (declared by the runtime's codec/session.h) */
bool codec_command_facts(const codec_field_value_t *command, codec_command_facts_t *out);
const char *codec_function_name(int value);
int codec_session_ack_decode(uint8_t set, const uint8_t *data, size_t len, codec_device_t device,
                             uint8_t *echo, uint32_t *code);
const char *const *codec_device_model_names(codec_device_t device);
extern const codec_reference_time_t codec_reference_times[];
extern const size_t codec_reference_time_count;

/* The generated side defines every function: each address, so that the link fails without one. */
struct codec_contract {
    const char *(*device_id)(codec_device_t);
    bool (*device_from_id)(const char *, codec_device_t *);
    const char *(*device_title)(codec_device_t);
    const char *(*device_manual)(codec_device_t);
    bool (*device_supports)(codec_device_t, uint8_t, uint8_t);
    const codec_layout_info_t *(*layout_info)(codec_field_id_t);
    const codec_field_info_t *(*find_field)(uint8_t, uint8_t, codec_status_t *);
    codec_status_t (*decode_field)(uint8_t, uint8_t, const uint8_t *, size_t, codec_device_t,
                                   codec_field_value_t *, codec_decode_error_t *);
    codec_status_t (*encode_field)(const codec_field_value_t *, uint8_t *, size_t, size_t *);
    void (*value_to_json)(codec_jw_t *, const codec_field_value_t *);
    int (*value_from_json)(codec_jr_t *, size_t, codec_field_id_t, codec_field_value_t *);
    bool (*command_facts)(const codec_field_value_t *, codec_command_facts_t *);
    const char *(*function_name)(int);
    int (*session_ack_decode)(uint8_t, const uint8_t *, size_t, codec_device_t, uint8_t *, uint32_t *);
    const char *const *(*device_model_names)(codec_device_t);
    int (*field_length_adjust)(uint8_t, uint8_t);
    const uint32_t *(*device_baud_rates)(codec_device_t, size_t *);
    uint32_t (*device_default_baud)(codec_device_t);
    codec_device_t any;
    codec_set_kind_t (*set_kind)(uint8_t);
    codec_set_kind_t kinds[2];
    void (*layout_to_json)(codec_jw_t *, codec_field_id_t, const void *);
    size_t packet_size; /* codec_packet_t (dispatch.h): a data packet as its set's decoder fills it */
    const codec_reference_time_t *reference_times;
    const size_t *reference_time_count;
};

extern const struct codec_contract codec_contract;
const struct codec_contract codec_contract = {
    codec_device_id,
    codec_device_from_id,
    codec_device_title,
    codec_device_manual,
    codec_device_supports,
    codec_layout_info,
    codec_find_field,
    codec_decode_field,
    codec_encode_field,
    codec_value_to_json,
    codec_value_from_json,
    codec_command_facts,
    codec_function_name,
    codec_session_ack_decode,
    codec_device_model_names,
    codec_field_length_adjust,
    codec_device_baud_rates,
    codec_device_default_baud,
    CODEC_DEVICE_ANY,
    codec_set_kind,
    {CODEC_SET_KIND_COMMAND, CODEC_SET_KIND_DATA},
    codec_layout_to_json,
    sizeof(codec_packet_t),
    codec_reference_times,
    &codec_reference_time_count,
};
