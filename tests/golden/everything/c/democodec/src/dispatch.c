/* Dispatch tables. Generated from the spec: do not edit. */
#include "democodec/dispatch.h"
#include "layouts_internal.h"

#include <assert.h>
#include <string.h>

const char *demo_device_id(demo_device_t device) {
    switch (device) {
    case DEMO_DEVICE_DEV_A:
        return "dev_a";
    case DEMO_DEVICE_DEV_B:
        return "dev_b";
    case DEMO_DEVICE_ANY:
    default:
        return NULL;
    }
}

bool demo_device_from_id(const char *id, demo_device_t *out) {
    assert(id != NULL);
    assert(out != NULL);
    if (strcmp(id, "dev_a") == 0) {
        *out = DEMO_DEVICE_DEV_A;
        return true;
    }
    if (strcmp(id, "dev_b") == 0) {
        *out = DEMO_DEVICE_DEV_B;
        return true;
    }
    (void)id;
    (void)out;
    return false;
}

demo_set_kind_t demo_set_kind(uint8_t set) {
    if (set >= 0x01 && set <= 0x7F) {
        return DEMO_SET_KIND_COMMAND;
    }
    if (set >= 0x80 && 1) {
        return DEMO_SET_KIND_DATA;
    }
    (void)set;
    return DEMO_SET_KIND_NONE;
}

static const demo_layout_info_t k_layouts[DEMO_FIELD_COUNT] = {
    {DEMO_FIELD_NONE, NULL, NULL, DEMO_DEVICE_ANY, 0},
    {DEMO_FIELD_ACK, "ack", NULL, DEMO_DEVICE_ANY, 0x80},
    {DEMO_FIELD_COMMANDS_PING, "ping", NULL, DEMO_DEVICE_ANY, 0x01},
    {DEMO_FIELD_COMMANDS_CONFIGURE, "configure", NULL, DEMO_DEVICE_ANY, 0x02},
    {DEMO_FIELD_COMMANDS_CONFIGURATION, "configuration", NULL, DEMO_DEVICE_ANY, 0x82},
    {DEMO_FIELD_COMMANDS_PER_DEVICE_DEV_A, "per_device", "dev_a", DEMO_DEVICE_DEV_A, 0x03},
    {DEMO_FIELD_COMMANDS_PER_DEVICE_DEV_B, "per_device", "dev_b", DEMO_DEVICE_DEV_B, 0x03},
    {DEMO_FIELD_DATA_SAMPLE, "sample", NULL, DEMO_DEVICE_ANY, 0x01},
    {DEMO_FIELD_RECEIVER_1_LLH_POSITION, "llh_position", NULL, DEMO_DEVICE_ANY, 0x03},
    {DEMO_FIELD_RECEIVER_2_LLH_POSITION, "llh_position", NULL, DEMO_DEVICE_ANY, 0x03},
    {DEMO_FIELD_SHARED_TIMESTAMP, "timestamp", NULL, DEMO_DEVICE_ANY, 0xD3},
};

static const demo_field_info_t k_fields[9] = {
    {"ack", 0x80, DEMO_FIELD_ACK, 1},                              /* 0 */
    {"ping", 0x01, DEMO_FIELD_COMMANDS_PING, 1},                   /* 1 */
    {"configure", 0x02, DEMO_FIELD_COMMANDS_CONFIGURE, 1},         /* 2 */
    {"configuration", 0x82, DEMO_FIELD_COMMANDS_CONFIGURATION, 1}, /* 3 */
    {"per_device", 0x03, DEMO_FIELD_COMMANDS_PER_DEVICE_DEV_A, 2}, /* 4 */
    {"sample", 0x01, DEMO_FIELD_DATA_SAMPLE, 1},                   /* 5 */
    {"llh_position", 0x03, DEMO_FIELD_RECEIVER_1_LLH_POSITION, 1}, /* 6 */
    {"llh_position", 0x03, DEMO_FIELD_RECEIVER_2_LLH_POSITION, 1}, /* 7 */
    {"timestamp", 0xD3, DEMO_FIELD_SHARED_TIMESTAMP, 1},           /* 8 */
};

const demo_layout_info_t *demo_layout_info(demo_field_id_t id) {
    if ((size_t)id >= DEMO_FIELD_COUNT) {
        return NULL;
    }
    return &k_layouts[id];
}

/* Fields of each set: descriptor -> 1 + index into k_fields (0: not defined). Dispatch by
 * (set, descriptor) is two table lookups. A set's table also holds the reserved fields of its
 * kind and, in a data set, the shared data fields that it does not define itself: the answer
 * find_field's search would reach (the generator resolves the search once). */
static const uint16_t k_set_commands[256] = {
    [0x01] = 2, /* ping */
    [0x02] = 3, /* configure */
    [0x03] = 5, /* per_device */
    [0x80] = 1, /* reserved ack */
    [0x82] = 4, /* configuration */
};
static const uint16_t k_set_data[256] = {
    [0x01] = 6, /* sample */
    [0xD3] = 9, /* shared timestamp */
};
static const uint16_t k_set_receiver_1[256] = {
    [0x03] = 7, /* llh_position */
    [0xD3] = 9, /* shared timestamp */
};
static const uint16_t k_set_receiver_2[256] = {
    [0x03] = 8, /* llh_position */
    [0xD3] = 9, /* shared timestamp */
};
static const uint16_t k_set_shared[256] = {
    [0xD3] = 9, /* timestamp */
};

static const uint16_t *const k_sets[256] = {
    [0x01] = k_set_commands,   [0x90] = k_set_data,   [0x91] = k_set_receiver_1,
    [0x92] = k_set_receiver_2, [0xFF] = k_set_shared,
};

/* Fields of a set (reserved and shared data fields included, see k_set_*); *set_known tells
 * whether the set is defined at all. */
static const demo_field_info_t *defined(uint8_t set, uint8_t descriptor, bool *set_known) {
    const uint16_t *table = k_sets[set];
    *set_known = table != NULL;
    if (!table || table[descriptor] == 0) {
        return NULL;
    }
    return &k_fields[table[descriptor] - 1];
}

/* The body of demo_find_field, static so that demo_decode_field inlines it. */
static const demo_field_info_t *find_field(uint8_t set, uint8_t descriptor, demo_status_t *why) {
    bool known = false;
    demo_set_kind_t kind;
    const demo_field_info_t *f = defined(set, descriptor, &known);
    if (f) {
        return f;
    }
    kind = demo_set_kind(set);
    /* reserved fields of the set's kind */
    switch (kind) {
    case DEMO_SET_KIND_COMMAND:
        if (descriptor == 0x80) {
            return &k_fields[0]; /* ack */
        }
        break;
    case DEMO_SET_KIND_DATA:
        break;
    case DEMO_SET_KIND_NONE:
    default:
        break;
    }
    /* shared data fields, valid in every data set */
    if (kind == DEMO_SET_KIND_DATA) {
        bool shared_known;
        f = defined(0xFF, descriptor, &shared_known);
        if (f) {
            return f;
        }
    }
    if (why) {
        *why = known ? DEMO_ERR_UNKNOWN_DESCRIPTOR : DEMO_ERR_UNKNOWN_SET;
    }
    return NULL;
}

const demo_field_info_t *demo_find_field(uint8_t set, uint8_t descriptor, demo_status_t *why) {
    return find_field(set, descriptor, why);
}

static demo_status_t decode_layout(demo_field_id_t id, const uint8_t *data, size_t len,
                                   demo_field_value_t *out, demo_decode_error_t *err) {
    out->id = id;
    switch (id) {
    case DEMO_FIELD_ACK:
        return demo_ack_decode(data, len, &out->u.ack, err);
    case DEMO_FIELD_COMMANDS_PING:
        return demo_commands_ping_decode(data, len, &out->u.commands_ping, err);
    case DEMO_FIELD_COMMANDS_CONFIGURE:
        return demo_commands_configure_decode(data, len, &out->u.commands_configure, err);
    case DEMO_FIELD_COMMANDS_CONFIGURATION:
        return demo_commands_configuration_decode(data, len, &out->u.commands_configuration, err);
    case DEMO_FIELD_COMMANDS_PER_DEVICE_DEV_A:
        return demo_commands_per_device_dev_a_decode(data, len, &out->u.commands_per_device_dev_a, err);
    case DEMO_FIELD_COMMANDS_PER_DEVICE_DEV_B:
        return demo_commands_per_device_dev_b_decode(data, len, &out->u.commands_per_device_dev_b, err);
    case DEMO_FIELD_DATA_SAMPLE:
        return demo_data_sample_decode(data, len, &out->u.data_sample, err);
    case DEMO_FIELD_RECEIVER_1_LLH_POSITION:
        return demo_receiver_1_llh_position_decode(data, len, &out->u.receiver_1_llh_position, err);
    case DEMO_FIELD_RECEIVER_2_LLH_POSITION:
        return demo_receiver_2_llh_position_decode(data, len, &out->u.receiver_2_llh_position, err);
    case DEMO_FIELD_SHARED_TIMESTAMP:
        return demo_shared_timestamp_decode(data, len, &out->u.shared_timestamp, err);
    case DEMO_FIELD_NONE:
    case DEMO_FIELD_COUNT:
    default:
        return DEMO_ERR_INVALID;
    }
}

/* Every case of demo_decode_field: several layouts per field, a device to choose among them, error
 * details. Out of line (DEMO_NOINLINE) so that the common case below stays a short function. */
static DEMO_NOINLINE demo_status_t decode_field_general(uint8_t set, uint8_t descriptor, const uint8_t *data,
                                                        size_t len, demo_device_t device,
                                                        demo_field_value_t *out, demo_decode_error_t *err) {
    demo_status_t why = DEMO_ERR_UNKNOWN_SET;
    const demo_field_info_t *f = find_field(set, descriptor, &why);
    size_t first;
    size_t count;
    size_t i;
    out->id = DEMO_FIELD_NONE;
    if (!f) {
        return why;
    }
    first = (size_t)f->first_layout;
    count = f->layout_count;
    if (device != DEMO_DEVICE_ANY) {
        for (i = 0; i < count; i++) {
            if (k_layouts[first + i].device_id == device) {
                first += i;
                count = 1;
                break;
            }
        }
    }
    /* No error details on the way (the common case is a field that decodes); when no layout
     * decodes, the first one runs again to report its error. */
    for (i = 0; i < count; i++) {
        if (decode_layout((demo_field_id_t)(first + i), data, len, out, NULL) == DEMO_OK) {
            return DEMO_OK;
        }
    }
    if (err) {
        memset(err, 0, sizeof *err);
        (void)decode_layout((demo_field_id_t)first, data, len, out, err);
    }
    out->id = DEMO_FIELD_NONE;
    return DEMO_ERR_DECODE;
}

/* The common case first: a field its set defines, with one layout (the device does not choose
 * among one). Its decoder fills *err itself when it fails (as decode_field_general's second run
 * does). Anything else goes to decode_field_general, which starts over. */
demo_status_t demo_decode_field(uint8_t set, uint8_t descriptor, const uint8_t *data, size_t len,
                                demo_device_t device, demo_field_value_t *out, demo_decode_error_t *err) {
    const uint16_t *table = k_sets[set];
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (table && table[descriptor] != 0) {
        const demo_field_info_t *f = &k_fields[table[descriptor] - 1];
        if (f->layout_count == 1) {
            if (decode_layout(f->first_layout, data, len, out, err) == DEMO_OK) {
                return DEMO_OK;
            }
            out->id = DEMO_FIELD_NONE;
            return DEMO_ERR_DECODE;
        }
    }
    return decode_field_general(set, descriptor, data, len, device, out, err);
}

demo_status_t demo_encode_field(const demo_field_value_t *value, uint8_t *buf, size_t cap, size_t *len_out) {
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    switch (value->id) {
    case DEMO_FIELD_ACK:
        return demo_ack_encode(&value->u.ack, buf, cap, len_out);
    case DEMO_FIELD_COMMANDS_PING:
        return demo_commands_ping_encode(&value->u.commands_ping, buf, cap, len_out);
    case DEMO_FIELD_COMMANDS_CONFIGURE:
        return demo_commands_configure_encode(&value->u.commands_configure, buf, cap, len_out);
    case DEMO_FIELD_COMMANDS_CONFIGURATION:
        return demo_commands_configuration_encode(&value->u.commands_configuration, buf, cap, len_out);
    case DEMO_FIELD_COMMANDS_PER_DEVICE_DEV_A:
        return demo_commands_per_device_dev_a_encode(&value->u.commands_per_device_dev_a, buf, cap, len_out);
    case DEMO_FIELD_COMMANDS_PER_DEVICE_DEV_B:
        return demo_commands_per_device_dev_b_encode(&value->u.commands_per_device_dev_b, buf, cap, len_out);
    case DEMO_FIELD_DATA_SAMPLE:
        return demo_data_sample_encode(&value->u.data_sample, buf, cap, len_out);
    case DEMO_FIELD_RECEIVER_1_LLH_POSITION:
        return demo_receiver_1_llh_position_encode(&value->u.receiver_1_llh_position, buf, cap, len_out);
    case DEMO_FIELD_RECEIVER_2_LLH_POSITION:
        return demo_receiver_2_llh_position_encode(&value->u.receiver_2_llh_position, buf, cap, len_out);
    case DEMO_FIELD_SHARED_TIMESTAMP:
        return demo_shared_timestamp_encode(&value->u.shared_timestamp, buf, cap, len_out);
    case DEMO_FIELD_NONE:
    case DEMO_FIELD_COUNT:
    default:
        return DEMO_ERR_INVALID;
    }
}

void demo_value_to_json(demo_jw_t *w, const demo_field_value_t *value) {
    switch (value->id) {
    case DEMO_FIELD_ACK:
        demo_ack_to_json(w, &value->u.ack);
        return;
    case DEMO_FIELD_COMMANDS_PING:
        demo_commands_ping_to_json(w, &value->u.commands_ping);
        return;
    case DEMO_FIELD_COMMANDS_CONFIGURE:
        demo_commands_configure_to_json(w, &value->u.commands_configure);
        return;
    case DEMO_FIELD_COMMANDS_CONFIGURATION:
        demo_commands_configuration_to_json(w, &value->u.commands_configuration);
        return;
    case DEMO_FIELD_COMMANDS_PER_DEVICE_DEV_A:
        demo_commands_per_device_dev_a_to_json(w, &value->u.commands_per_device_dev_a);
        return;
    case DEMO_FIELD_COMMANDS_PER_DEVICE_DEV_B:
        demo_commands_per_device_dev_b_to_json(w, &value->u.commands_per_device_dev_b);
        return;
    case DEMO_FIELD_DATA_SAMPLE:
        demo_data_sample_to_json(w, &value->u.data_sample);
        return;
    case DEMO_FIELD_RECEIVER_1_LLH_POSITION:
        demo_receiver_1_llh_position_to_json(w, &value->u.receiver_1_llh_position);
        return;
    case DEMO_FIELD_RECEIVER_2_LLH_POSITION:
        demo_receiver_2_llh_position_to_json(w, &value->u.receiver_2_llh_position);
        return;
    case DEMO_FIELD_SHARED_TIMESTAMP:
        demo_shared_timestamp_to_json(w, &value->u.shared_timestamp);
        return;
    case DEMO_FIELD_NONE:
    case DEMO_FIELD_COUNT:
    default:
        demo_jw_lit(w, "null");
        return;
    }
}

int demo_value_from_json(demo_jr_t *jr, size_t pos, demo_field_id_t id, demo_field_value_t *value) {
    value->id = id;
    switch (id) {
    case DEMO_FIELD_ACK:
        return demo_ack_from_json(jr, pos, &value->u.ack);
    case DEMO_FIELD_COMMANDS_PING:
        return demo_commands_ping_from_json(jr, pos, &value->u.commands_ping);
    case DEMO_FIELD_COMMANDS_CONFIGURE:
        return demo_commands_configure_from_json(jr, pos, &value->u.commands_configure);
    case DEMO_FIELD_COMMANDS_CONFIGURATION:
        return demo_commands_configuration_from_json(jr, pos, &value->u.commands_configuration);
    case DEMO_FIELD_COMMANDS_PER_DEVICE_DEV_A:
        return demo_commands_per_device_dev_a_from_json(jr, pos, &value->u.commands_per_device_dev_a);
    case DEMO_FIELD_COMMANDS_PER_DEVICE_DEV_B:
        return demo_commands_per_device_dev_b_from_json(jr, pos, &value->u.commands_per_device_dev_b);
    case DEMO_FIELD_DATA_SAMPLE:
        return demo_data_sample_from_json(jr, pos, &value->u.data_sample);
    case DEMO_FIELD_RECEIVER_1_LLH_POSITION:
        return demo_receiver_1_llh_position_from_json(jr, pos, &value->u.receiver_1_llh_position);
    case DEMO_FIELD_RECEIVER_2_LLH_POSITION:
        return demo_receiver_2_llh_position_from_json(jr, pos, &value->u.receiver_2_llh_position);
    case DEMO_FIELD_SHARED_TIMESTAMP:
        return demo_shared_timestamp_from_json(jr, pos, &value->u.shared_timestamp);
    case DEMO_FIELD_NONE:
    case DEMO_FIELD_COUNT:
    default:
        (void)pos;
        return demo_jr_fail(jr, "no such field layout");
    }
}
