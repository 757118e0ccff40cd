/* Dispatch tables. Generated from the spec: do not edit. */
#include "democodec/dispatch.h"
#include "layouts_internal.h"

#include <assert.h>
#include <string.h>

const char *democ_device_id(democ_device_t device) {
    switch (device) {
    case DEMOC_DEVICE_DEV_A:
        return "dev_a";
    case DEMOC_DEVICE_DEV_B:
        return "dev_b";
    case DEMOC_DEVICE_ANY:
    default:
        return NULL;
    }
}

bool democ_device_from_id(const char *id, democ_device_t *out) {
    assert(id != NULL);
    assert(out != NULL);
    if (strcmp(id, "dev_a") == 0) {
        *out = DEMOC_DEVICE_DEV_A;
        return true;
    }
    if (strcmp(id, "dev_b") == 0) {
        *out = DEMOC_DEVICE_DEV_B;
        return true;
    }
    (void)id;
    (void)out;
    return false;
}

const char *democ_device_title(democ_device_t device) {
    switch (device) {
    case DEMOC_DEVICE_DEV_A:
        return "Device A";
    case DEMOC_DEVICE_DEV_B:
        return "Device B";
    case DEMOC_DEVICE_ANY:
    default:
        return NULL;
    }
}

const char *democ_device_manual(democ_device_t device) {
    switch (device) {
    case DEMOC_DEVICE_DEV_A:
        return "demo.txt";
    case DEMOC_DEVICE_DEV_B:
        return "demo-b.txt";
    case DEMOC_DEVICE_ANY:
    default:
        return NULL;
    }
}

/* The capabilities tables: (set << 8) | descriptor, ascending (a leading 0 keeps an empty one legal). */
static const uint16_t k_dev_a_commands[] = {0, 0x0101, 0x0102, 0x0103};
static const uint16_t k_dev_a_data[] = {0, 0x9001, 0x9103, 0x9203};
static const uint16_t k_dev_b_commands[] = {0, 0x0103};
static const uint16_t k_dev_b_data[] = {0};

static const uint16_t *device_table(democ_device_t device, bool data, size_t *count) {
    switch (device) {
    case DEMOC_DEVICE_DEV_A:
        *count = data ? 3u : 3u;
        return (data ? k_dev_a_data : k_dev_a_commands) + 1;
    case DEMOC_DEVICE_DEV_B:
        *count = data ? 0u : 1u;
        return (data ? k_dev_b_data : k_dev_b_commands) + 1;
    case DEMOC_DEVICE_ANY:
    default:
        *count = 0;
        return NULL;
    }
}

const uint16_t *democ_device_commands(democ_device_t device, size_t *count) {
    assert(count != NULL);
    return device_table(device, false, count);
}

const uint16_t *democ_device_data(democ_device_t device, size_t *count) {
    assert(count != NULL);
    return device_table(device, true, count);
}

/* The baud rates of each device's main port (the IR's `link`), ascending. */

const uint32_t *democ_device_baud_rates(democ_device_t device, size_t *count) {
    assert(count != NULL);
    switch (device) {
    case DEMOC_DEVICE_DEV_A:
        *count = 0u;
        return NULL;
    case DEMOC_DEVICE_DEV_B:
        *count = 0u;
        return NULL;
    case DEMOC_DEVICE_ANY:
    default:
        *count = 0;
        return NULL;
    }
}

uint32_t democ_device_default_baud(democ_device_t device) {
    switch (device) {
    case DEMOC_DEVICE_DEV_A:
        return 0u;
    case DEMOC_DEVICE_DEV_B:
        return 0u;
    case DEMOC_DEVICE_ANY:
    default:
        return 0u;
    }
}

static bool table_has(const uint16_t *table, size_t n, uint16_t key) {
    size_t lo = 0;
    while (lo < n) {
        size_t mid = lo + (n - lo) / 2u;
        if (table[mid] == key) {
            return true;
        }
        if (table[mid] < key) {
            lo = mid + 1u;
        } else {
            n = mid;
        }
    }
    return false;
}

bool democ_device_supports(democ_device_t device, uint8_t set, uint8_t descriptor) {
    size_t n;
    uint16_t key = (uint16_t)(((unsigned)set << 8) | descriptor);
    const uint16_t *t = device_table(device, false, &n);
    if (t != NULL && table_has(t, n, key)) {
        return true;
    }
    t = device_table(device, true, &n);
    return t != NULL && table_has(t, n, key);
}

democ_set_kind_t democ_set_kind(uint8_t set) {
    if (set >= 0x01 && set <= 0x7F) {
        return DEMOC_SET_KIND_COMMAND;
    }
    if (set >= 0x80 && 1) {
        return DEMOC_SET_KIND_DATA;
    }
    (void)set;
    return DEMOC_SET_KIND_NONE;
}

static const democ_layout_info_t k_layouts[DEMOC_FIELD_COUNT] = {
    {DEMOC_FIELD_NONE, NULL, NULL, DEMOC_DEVICE_ANY, 0},
    {DEMOC_FIELD_ACK, "ack", NULL, DEMOC_DEVICE_ANY, 0x80},
    {DEMOC_FIELD_COMMANDS_PING, "ping", NULL, DEMOC_DEVICE_ANY, 0x01},
    {DEMOC_FIELD_COMMANDS_CONFIGURE, "configure", NULL, DEMOC_DEVICE_ANY, 0x02},
    {DEMOC_FIELD_COMMANDS_CONFIGURATION, "configuration", NULL, DEMOC_DEVICE_ANY, 0x82},
    {DEMOC_FIELD_COMMANDS_PER_DEVICE_DEV_A, "per_device", "dev_a", DEMOC_DEVICE_DEV_A, 0x03},
    {DEMOC_FIELD_COMMANDS_PER_DEVICE_DEV_B, "per_device", "dev_b", DEMOC_DEVICE_DEV_B, 0x03},
    {DEMOC_FIELD_DATA_SAMPLE, "sample", NULL, DEMOC_DEVICE_ANY, 0x01},
    {DEMOC_FIELD_RECEIVER_1_LLH_POSITION, "llh_position", NULL, DEMOC_DEVICE_ANY, 0x03},
    {DEMOC_FIELD_RECEIVER_2_LLH_POSITION, "llh_position", NULL, DEMOC_DEVICE_ANY, 0x03},
    {DEMOC_FIELD_SHARED_TIMESTAMP, "timestamp", NULL, DEMOC_DEVICE_ANY, 0xD3},
};

static const democ_field_info_t k_fields[] = {
    {"ack", 0x80, DEMOC_FIELD_ACK, 1},
    {"ping", 0x01, DEMOC_FIELD_COMMANDS_PING, 1},
    {"configure", 0x02, DEMOC_FIELD_COMMANDS_CONFIGURE, 1},
    {"configuration", 0x82, DEMOC_FIELD_COMMANDS_CONFIGURATION, 1},
    {"per_device", 0x03, DEMOC_FIELD_COMMANDS_PER_DEVICE_DEV_A, 2},
    {"sample", 0x01, DEMOC_FIELD_DATA_SAMPLE, 1},
    {"llh_position", 0x03, DEMOC_FIELD_RECEIVER_1_LLH_POSITION, 1},
    {"llh_position", 0x03, DEMOC_FIELD_RECEIVER_2_LLH_POSITION, 1},
    {"timestamp", 0xD3, DEMOC_FIELD_SHARED_TIMESTAMP, 1},
};

const democ_layout_info_t *democ_layout_info(democ_field_id_t id) {
    if ((size_t)id >= DEMOC_FIELD_COUNT) {
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
static const democ_field_info_t *defined(uint8_t set, uint8_t descriptor, bool *set_known) {
    const uint16_t *table = k_sets[set];
    *set_known = table != NULL;
    if (!table || table[descriptor] == 0) {
        return NULL;
    }
    return &k_fields[table[descriptor] - 1];
}

/* The body of democ_find_field, static so that democ_decode_field inlines it. */
static const democ_field_info_t *find_field(uint8_t set, uint8_t descriptor, democ_status_t *why) {
    bool known = false;
    democ_set_kind_t kind;
    const democ_field_info_t *f = defined(set, descriptor, &known);
    if (f) {
        return f;
    }
    kind = democ_set_kind(set);
    /* reserved fields of the set's kind */
    switch (kind) {
    case DEMOC_SET_KIND_COMMAND:
        if (descriptor == 0x80) {
            return &k_fields[0]; /* ack */
        }
        break;
    case DEMOC_SET_KIND_DATA:
        break;
    case DEMOC_SET_KIND_NONE:
    default:
        break;
    }
    /* shared data fields, valid in every data set */
    if (kind == DEMOC_SET_KIND_DATA) {
        bool shared_known;
        f = defined(0xFF, descriptor, &shared_known);
        if (f) {
            return f;
        }
    }
    if (why) {
        *why = known ? DEMOC_ERR_UNKNOWN_DESCRIPTOR : DEMOC_ERR_UNKNOWN_SET;
    }
    return NULL;
}

const democ_field_info_t *democ_find_field(uint8_t set, uint8_t descriptor, democ_status_t *why) {
    return find_field(set, descriptor, why);
}

static democ_status_t decode_layout(democ_field_id_t id, const uint8_t *data, size_t len,
                                    democ_field_value_t *out, democ_decode_error_t *err) {
    out->id = id;
    switch (id) {
    case DEMOC_FIELD_ACK:
        return democ_ack_decode(data, len, &out->u.ack, err);
    case DEMOC_FIELD_COMMANDS_PING:
        return democ_commands_ping_decode(data, len, &out->u.commands_ping, err);
    case DEMOC_FIELD_COMMANDS_CONFIGURE:
        return democ_commands_configure_decode(data, len, &out->u.commands_configure, err);
    case DEMOC_FIELD_COMMANDS_CONFIGURATION:
        return democ_commands_configuration_decode(data, len, &out->u.commands_configuration, err);
    case DEMOC_FIELD_COMMANDS_PER_DEVICE_DEV_A:
        return democ_commands_per_device_dev_a_decode(data, len, &out->u.commands_per_device_dev_a, err);
    case DEMOC_FIELD_COMMANDS_PER_DEVICE_DEV_B:
        return democ_commands_per_device_dev_b_decode(data, len, &out->u.commands_per_device_dev_b, err);
    case DEMOC_FIELD_DATA_SAMPLE:
        return democ_data_sample_decode(data, len, &out->u.data_sample, err);
    case DEMOC_FIELD_RECEIVER_1_LLH_POSITION:
        return democ_receiver_1_llh_position_decode(data, len, &out->u.receiver_1_llh_position, err);
    case DEMOC_FIELD_RECEIVER_2_LLH_POSITION:
        return democ_receiver_2_llh_position_decode(data, len, &out->u.receiver_2_llh_position, err);
    case DEMOC_FIELD_SHARED_TIMESTAMP:
        return democ_shared_timestamp_decode(data, len, &out->u.shared_timestamp, err);
    case DEMOC_FIELD_NONE:
    case DEMOC_FIELD_COUNT:
    default:
        return DEMOC_ERR_INVALID;
    }
}

/* Every case of democ_decode_field: several layouts per field, a device to choose among them, error
 * details. Out of line (DEMOC_NOINLINE) so that the common case below stays a short function. */
static DEMOC_NOINLINE democ_status_t decode_field_general(uint8_t set, uint8_t descriptor,
                                                          const uint8_t *data, size_t len,
                                                          democ_device_t device, democ_field_value_t *out,
                                                          democ_decode_error_t *err) {
    democ_status_t why = DEMOC_ERR_UNKNOWN_SET;
    const democ_field_info_t *f = find_field(set, descriptor, &why);
    size_t first;
    size_t count;
    size_t i;
    out->id = DEMOC_FIELD_NONE;
    if (!f) {
        return why;
    }
    first = (size_t)f->first_layout;
    count = f->layout_count;
    if (device != DEMOC_DEVICE_ANY) {
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
        if (decode_layout((democ_field_id_t)(first + i), data, len, out, NULL) == DEMOC_OK) {
            return DEMOC_OK;
        }
    }
    if (err) {
        memset(err, 0, sizeof *err);
        (void)decode_layout((democ_field_id_t)first, data, len, out, err);
    }
    out->id = DEMOC_FIELD_NONE;
    return DEMOC_ERR_DECODE;
}

/* The common case first: a field its set defines, with one layout (the device does not choose
 * among one). Its decoder fills *err itself when it fails (as decode_field_general's second run
 * does). Anything else goes to decode_field_general, which starts over. */
democ_status_t democ_decode_field(uint8_t set, uint8_t descriptor, const uint8_t *data, size_t len,
                                  democ_device_t device, democ_field_value_t *out,
                                  democ_decode_error_t *err) {
    const uint16_t *table = k_sets[set];
    assert(data != NULL || len == 0);
    assert(out != NULL);
    if (table && table[descriptor] != 0) {
        const democ_field_info_t *f = &k_fields[table[descriptor] - 1];
        if (f->layout_count == 1) {
            if (decode_layout(f->first_layout, data, len, out, err) == DEMOC_OK) {
                return DEMOC_OK;
            }
            out->id = DEMOC_FIELD_NONE;
            return DEMOC_ERR_DECODE;
        }
    }
    return decode_field_general(set, descriptor, data, len, device, out, err);
}

/* Every entry of a payload to fn (out of line: democ_decode_packet stays a switch). */
static DEMOC_NOINLINE void visit_all(uint8_t set, const uint8_t *payload, size_t len, democ_field_entry_fn fn,
                                     void *ctx) {
    democ_field_iter_t it;
    democ_field_entry_t e;
    democ_field_iter_init(&it, set, payload, len);
    while (democ_field_iter_next(&it, &e)) {
        fn(ctx, &e);
    }
}

const democ_packet_index_t *democ_decode_packet(const uint8_t *packet, democ_packet_t *out,
                                                democ_field_entry_fn other, void *ctx) {
    const uint8_t set = democ_packet_set(packet);
    const uint8_t *payload = democ_packet_payload(packet);
    const size_t len = democ_packet_payload_length(packet);
    assert(packet != NULL);
    assert(out != NULL);
    out->set = set;
    switch (set) {
    case 0x90:
        (void)democ_data_decode_packet(payload, len, &out->u.data, other, ctx);
        return &out->u.data.index;
    case 0x91:
        (void)democ_receiver_1_decode_packet(payload, len, &out->u.receiver_1, other, ctx);
        return &out->u.receiver_1.index;
    case 0x92:
        (void)democ_receiver_2_decode_packet(payload, len, &out->u.receiver_2, other, ctx);
        return &out->u.receiver_2.index;
    case 0xFF:
        (void)democ_shared_decode_packet(payload, len, &out->u.shared, other, ctx);
        return &out->u.shared.index;
    default:
        break;
    }
    if (other) {
        visit_all(set, payload, len, other, ctx);
    }
    return NULL;
}

/* The other of a cached decode's fallback: passes each entry on and notes the payload offsets of
 * the fields (a trailing entry, or more fields than a shape holds, and the packet is not recorded). */
typedef struct {
    democ_field_entry_fn other;
    void *ctx;
    size_t count;
    int whole; /* every entry a field, at most DEMOC_LAYOUT_SHAPE_FIELDS */
    size_t pos[DEMOC_LAYOUT_SHAPE_FIELDS];
} noted_other_t;

static void note_other(void *ctx, const democ_field_entry_t *entry) {
    noted_other_t *c = ctx;
    if (entry->kind != DEMOC_ENTRY_FIELD || c->count == DEMOC_LAYOUT_SHAPE_FIELDS) {
        c->whole = 0;
    } else {
        c->pos[c->count++] = entry->offset;
    }
    if (c->other) {
        c->other(c->ctx, entry);
    }
}

/* The members of a set's packet struct (democ_layout_cache_record_); count 0: none. */
static const democ_layout_member_t *shape_members(uint8_t set, size_t *count) {
    switch (set) {
    case 0x90:
        *count = 2;
        return democ_data_layout_members_;
    case 0x91:
        *count = 2;
        return democ_receiver_1_layout_members_;
    case 0x92:
        *count = 2;
        return democ_receiver_2_layout_members_;
    case 0xFF:
        *count = 1;
        return democ_shared_layout_members_;
    default:
        *count = 0;
        return NULL;
    }
}

/* A packet whose shape is not the last one hit: the other cached shapes, else the straight-line
 * decoder (and its shape recorded). */
static DEMOC_NOINLINE const democ_packet_index_t *decode_uncached(democ_layout_cache_t *cache,
                                                                  const uint8_t *packet, democ_packet_t *out,
                                                                  democ_field_entry_fn other, void *ctx) {
    const uint8_t set = democ_packet_set(packet);
    const uint8_t *payload = democ_packet_payload(packet);
    const size_t len = democ_packet_payload_length(packet);
    const democ_layout_shape_t *shape = democ_layout_cache_find_(cache, set, payload, len);
    const democ_packet_index_t *index;
    noted_other_t noted;
    if (shape != NULL &&
        democ_layout_shape_decode_(shape, payload, (democ_packet_index_t *)(void *)&out->u)) {
        out->set = set;
        if (shape->others != 0 && other != NULL) {
            democ_layout_shape_others_(shape, payload, other, ctx);
        }
        return (const democ_packet_index_t *)(const void *)&out->u;
    }
    noted.other = other;
    noted.ctx = ctx;
    noted.count = 0;
    noted.whole = 1;
    index = democ_decode_packet(packet, out, note_other, &noted);
    if (index != NULL && noted.whole && shape == NULL) {
        size_t count;
        const democ_layout_member_t *members = shape_members(set, &count);
        if (count != 0) {
            democ_layout_cache_record_(cache, set, payload, len, index, noted.pos, noted.count, members,
                                       count);
        }
    }
    return index;
}

/* Every packet struct of out->u starts with its index: a pointer to the union converts to one to
 * each member, and that to one to its first member (C99 6.7.2.1). */
const democ_packet_index_t *democ_decode_packet_cached(democ_layout_cache_t *cache, const uint8_t *packet,
                                                       democ_packet_t *out, democ_field_entry_fn other,
                                                       void *ctx) {
    const uint8_t set = democ_packet_set(packet);
    const uint8_t *payload = democ_packet_payload(packet);
    const democ_layout_shape_t *shape;
    assert(cache != NULL);
    assert(out != NULL);
    shape = &cache->shapes[cache->last % DEMOC_LAYOUT_CACHE_SHAPES];
    if (democ_layout_shape_matches_(shape, set, payload, democ_packet_payload_length(packet)) &&
        democ_layout_shape_decode_(shape, payload, (democ_packet_index_t *)(void *)&out->u)) {
        out->set = set;
        if (shape->others != 0 && other != NULL) {
            democ_layout_shape_others_(shape, payload, other, ctx);
        }
        return (const democ_packet_index_t *)(const void *)&out->u;
    }
    return decode_uncached(cache, packet, out, other, ctx);
}

democ_status_t democ_encode_field(const democ_field_value_t *value, uint8_t *buf, size_t cap,
                                  size_t *len_out) {
    assert(value != NULL);
    assert(buf != NULL || cap == 0);
    switch (value->id) {
    case DEMOC_FIELD_ACK:
        return democ_ack_encode(&value->u.ack, buf, cap, len_out);
    case DEMOC_FIELD_COMMANDS_PING:
        return democ_commands_ping_encode(&value->u.commands_ping, buf, cap, len_out);
    case DEMOC_FIELD_COMMANDS_CONFIGURE:
        return democ_commands_configure_encode(&value->u.commands_configure, buf, cap, len_out);
    case DEMOC_FIELD_COMMANDS_CONFIGURATION:
        return democ_commands_configuration_encode(&value->u.commands_configuration, buf, cap, len_out);
    case DEMOC_FIELD_COMMANDS_PER_DEVICE_DEV_A:
        return democ_commands_per_device_dev_a_encode(&value->u.commands_per_device_dev_a, buf, cap, len_out);
    case DEMOC_FIELD_COMMANDS_PER_DEVICE_DEV_B:
        return democ_commands_per_device_dev_b_encode(&value->u.commands_per_device_dev_b, buf, cap, len_out);
    case DEMOC_FIELD_DATA_SAMPLE:
        return democ_data_sample_encode(&value->u.data_sample, buf, cap, len_out);
    case DEMOC_FIELD_RECEIVER_1_LLH_POSITION:
        return democ_receiver_1_llh_position_encode(&value->u.receiver_1_llh_position, buf, cap, len_out);
    case DEMOC_FIELD_RECEIVER_2_LLH_POSITION:
        return democ_receiver_2_llh_position_encode(&value->u.receiver_2_llh_position, buf, cap, len_out);
    case DEMOC_FIELD_SHARED_TIMESTAMP:
        return democ_shared_timestamp_encode(&value->u.shared_timestamp, buf, cap, len_out);
    case DEMOC_FIELD_NONE:
    case DEMOC_FIELD_COUNT:
    default:
        return DEMOC_ERR_INVALID;
    }
}
