/* cv7_external_aiding ADDRESS FEED [--period-ms N] [--samples N] [--deadline-s N]
 *
 * The CV7-INS flow with external aiding (tests/apps/README.md), written against the generated C
 * package mipcodec: its typed session API (mipc_<set>_<command>_<function>(&link, ...)), the link
 * of mipcodec/link.h and the POSIX transports of mipcodec/posix_transport.h.
 *
 * It configures the device (ping, idle, device information, default settings, gyro bias capture,
 * the filter data message, the aiding frames, the aiding sources, the filter initialization, a
 * filter reset, resume), then sends external heading, position, velocity and body-frame velocity
 * from the FEED file every --period-ms, until the filter reports full navigation and --samples
 * navigation samples were printed. stdout: "mode N" whenever the filter mode changes, then one
 * JSON object per full-navigation filter packet. Exit status 0; 1 with "error: ..." on stderr
 * (a command not acknowledged, the connection, the feed, the deadline); 2 with "usage: ..." for
 * wrong arguments. */
#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mipcodec/mipcodec.h"
#include "mipcodec/posix_transport.h"

#define BAUD 115200ul
#define BASE_RATE_HZ_OUT 10u         /* the filter data rate asked for: base rate / 10 */
#define GYRO_BIAS_AVERAGING_MS 2000u /* capture gyro bias: the reply comes after this */
#define FRAME_HEADING 1u             /* aiding frame of the external heading sensor */
#define FRAME_GNSS 2u                /* aiding frame of the GNSS antenna */
#define FRAME_BODY_VELOCITY 3u       /* aiding frame of the body-frame velocity sensor */
#define FEED_COLUMNS 12              /* tow ns lat lon height vn ve vd heading bx by bz */
#define MAX_MILLISECONDS 86400000ul  /* upper bound of --period-ms and --deadline-s (in ms) */

#define USAGE_LINE "usage: cv7_external_aiding ADDRESS FEED [--period-ms N] [--samples N] [--deadline-s N]\n"
static const char USAGE[] =
    USAGE_LINE "  ADDRESS  tcp:HOST:PORT or a serial device path (115200 baud)\n"
               "  FEED     aiding rows 'tow ns lat lon height vn ve vd heading bx by bz' ('#' comments)\n"
               "  --period-ms N   how often aiding is sent (default 500)\n"
               "  --samples N     full-navigation samples to print (default 30)\n"
               "  --deadline-s N  give up after N seconds of waiting (default 60)\n";

/* ------------------------------------------------------------------------------- arguments */
typedef struct {
    const char *address;
    const char *feed;
    unsigned long period_ms;
    unsigned long samples;
    unsigned long deadline_s;
} options_t;

/* A decimal number in [1, max]. */
static bool parse_number(const char *text, unsigned long max, unsigned long *out) {
    char *end;
    unsigned long n;
    if (text[0] < '0' || text[0] > '9') {
        return false;
    }
    errno = 0;
    n = strtoul(text, &end, 10);
    if (errno != 0 || *end != '\0' || n == 0 || n > max) {
        return false;
    }
    *out = n;
    return true;
}

/* Returns -1 when the arguments are fine, else the exit status (usage printed). */
static int parse_options(int argc, char **argv, options_t *options) {
    int i, positional = 0;
    options->period_ms = 500;
    options->samples = 30;
    options->deadline_s = 60;
    for (i = 1; i < argc; i++) {
        const char *arg = argv[i];
        unsigned long *value = NULL, max = 0;
        if (strcmp(arg, "-h") == 0 || strcmp(arg, "--help") == 0) {
            fputs(USAGE, stdout);
            return 0;
        }
        if (strcmp(arg, "--period-ms") == 0) {
            value = &options->period_ms;
            max = MAX_MILLISECONDS;
        } else if (strcmp(arg, "--samples") == 0) {
            value = &options->samples;
            max = 1000000ul;
        } else if (strcmp(arg, "--deadline-s") == 0) {
            value = &options->deadline_s;
            max = MAX_MILLISECONDS / 1000ul;
        }
        if (value != NULL) {
            if (i + 1 >= argc) {
                fprintf(stderr, "usage: %s needs a value\n" USAGE_LINE, arg);
                return 2;
            }
            if (!parse_number(argv[++i], max, value)) {
                fprintf(stderr, "usage: %s %s: not a number from 1 to %lu\n" USAGE_LINE, arg, argv[i], max);
                return 2;
            }
        } else if (arg[0] == '-' && arg[1] != '\0') {
            fprintf(stderr, "usage: unknown option %s\n" USAGE_LINE, arg);
            return 2;
        } else if (positional == 0) {
            options->address = arg;
            positional++;
        } else if (positional == 1) {
            options->feed = arg;
            positional++;
        } else {
            fprintf(stderr, "usage: unexpected argument %s\n" USAGE_LINE, arg);
            return 2;
        }
    }
    if (positional != 2) {
        fputs(USAGE, stderr);
        return 2;
    }
    return -1;
}

/* ------------------------------------------------------------------------------- the feed */
typedef struct {
    double tow;      /* GPS time of week [s] */
    uint64_t ns;     /* the same instant, in the device's internal reference timebase [ns] */
    double lat, lon; /* [deg] */
    double height;   /* [m] */
    float ned[3];    /* NED velocity [m/s] */
    float heading;   /* true heading [rad] */
    float body[3];   /* body-frame velocity [m/s] */
} feed_row_t;

typedef struct {
    feed_row_t *rows;
    size_t count;
} feed_t;

/* Parses one row; false (with *why) when it is not FEED_COLUMNS numbers. */
static bool parse_row(char *line, feed_row_t *row, const char **why) {
    double v[FEED_COLUMNS];
    char *p = line, *end;
    int i;
    for (i = 0; i < FEED_COLUMNS; i++) {
        errno = 0;
        if (i == 1) { /* ns: an integer */
            while (*p == ' ' || *p == '\t') {
                p++;
            }
            if (*p < '0' || *p > '9') {
                *why = "ns is not a non-negative integer";
                return false;
            }
            row->ns = (uint64_t)strtoull(p, &end, 10);
            v[i] = 0.0;
        } else {
            v[i] = strtod(p, &end);
        }
        if (end == p || errno == ERANGE ||
            (*end != '\0' && *end != ' ' && *end != '\t' && *end != '\n' && *end != '\r')) {
            *why = "expected 12 numbers: tow ns lat lon height vn ve vd heading bx by bz";
            return false;
        }
        if (i != 1 && !isfinite(v[i])) {
            *why = "a number is not finite";
            return false;
        }
        p = end;
    }
    while (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r') {
        p++;
    }
    if (*p != '\0') {
        *why = "expected 12 numbers: tow ns lat lon height vn ve vd heading bx by bz";
        return false;
    }
    row->tow = v[0];
    row->lat = v[2];
    row->lon = v[3];
    row->height = v[4];
    for (i = 0; i < 3; i++) {
        row->ned[i] = (float)v[5 + i];
        row->body[i] = (float)v[9 + i];
    }
    row->heading = (float)v[8];
    return true;
}

/* Reads FEED; false with a message on stderr. */
static bool load_feed(const char *path, feed_t *feed) {
    char line[1024];
    size_t cap = 0, number = 0;
    bool bad = false; /* a row was refused (reported) */
    FILE *f = fopen(path, "r");
    feed->rows = NULL;
    feed->count = 0;
    if (f == NULL) {
        fprintf(stderr, "error: cannot read the feed %s: %s\n", path, strerror(errno));
        return false;
    }
    errno = 0;
    while (fgets(line, sizeof line, f) != NULL) {
        const char *why = NULL;
        char *p = line;
        number++;
        if (strchr(line, '\n') == NULL && !feof(f)) {
            fprintf(stderr, "error: %s:%lu: line too long\n", path, (unsigned long)number);
            bad = true;
            break;
        }
        while (*p == ' ' || *p == '\t') {
            p++;
        }
        if (*p == '#' || *p == '\n' || *p == '\r' || *p == '\0') {
            continue;
        }
        if (feed->count == cap) {
            size_t grown = cap ? 2 * cap : 1024;
            feed_row_t *rows = realloc(feed->rows, grown * sizeof *rows);
            if (rows == NULL) {
                fprintf(stderr, "error: %s: out of memory\n", path);
                bad = true;
                break;
            }
            feed->rows = rows;
            cap = grown;
        }
        if (!parse_row(p, &feed->rows[feed->count], &why)) {
            fprintf(stderr, "error: %s:%lu: %s\n", path, (unsigned long)number, why);
            bad = true;
            break;
        }
        feed->count++;
    }
    if (bad) {
        /* reported */
    } else if (ferror(f)) {
        fprintf(stderr, "error: cannot read the feed %s: %s\n", path, strerror(errno));
    } else if (feed->count == 0) {
        fprintf(stderr, "error: the feed %s has no rows\n", path);
    } else {
        fclose(f);
        return true;
    }
    fclose(f);
    free(feed->rows);
    feed->rows = NULL;
    return false;
}

/* The row whose time of week is nearest tow. */
static const feed_row_t *nearest_row(const feed_t *feed, double tow) {
    const feed_row_t *best = &feed->rows[0];
    size_t i;
    for (i = 1; i < feed->count; i++) {
        if (fabs(feed->rows[i].tow - tow) < fabs(best->tow - tow)) {
            best = &feed->rows[i];
        }
    }
    return best;
}

/* ------------------------------------------------------------------------------- commands */
/* Reports a command that did not succeed (a NACK with its code, a timeout, a refusal, the
 * connection) and returns the exit status 1. */
static int failed(const char *command, const mipc_link_t *link) {
    fprintf(stderr, "error: %s: %s", command, mipc_result_kind_name(link->result.kind));
    if (link->result.kind == MIPC_RESULT_NACK) {
        fprintf(stderr, " (code %lu)", (unsigned long)link->result.code);
    }
    if (link->result.error != NULL && link->result.error[0] != '\0') {
        fprintf(stderr, ": %s", link->result.error);
    }
    fprintf(stderr, "\n");
    return 1;
}

#define RUN(command, call)                                                                                   \
    do {                                                                                                     \
        if ((call) != MIPC_RESULT_ACK) {                                                                     \
            return failed(command, link);                                                                    \
        }                                                                                                    \
    } while (0)

/* The length of a device information string without its padding (spaces, NULs). */
static int padded_length(const char *text, size_t size) {
    while (size > 0 && (text[size - 1] == ' ' || text[size - 1] == '\0')) {
        size--;
    }
    return (int)size;
}

/* The configuration steps of the flow, in the order of the README. */
static int configure(mipc_link_t *link) {
    static const uint8_t filter_fields[] = {
        MIPC_FILTER_DATA_GPS_TIMESTAMP_DESCRIPTOR, MIPC_FILTER_DATA_FILTER_STATUS_DESCRIPTOR,
        MIPC_FILTER_DATA_LLH_POSITION_DESCRIPTOR,  MIPC_FILTER_DATA_NED_VELOCITY_DESCRIPTOR,
        MIPC_FILTER_DATA_EULER_ANGLES_DESCRIPTOR,
    };
    static const uint8_t frames[] = {FRAME_HEADING, FRAME_GNSS, FRAME_BODY_VELOCITY};
    static const float zero[3] = {0.0f, 0.0f, 0.0f};
    mipc_base_device_info_t info;
    mipc_threedm_gyro_bias_response_t bias;
    mipc_threedm_base_rate_t base_rate;
    mipc_descriptor_rate_t format[sizeof filter_fields];
    mipc_aiding_frame_rotation_t rotation;
    size_t i;

    RUN("base.ping", mipc_base_ping(link));
    RUN("base.set_to_idle", mipc_base_set_to_idle(link));
    RUN("base.get_device_info", mipc_base_get_device_info(link, &info));
    fprintf(stderr, "device %.*s, serial %.*s, firmware %u\n",
            padded_length(info.info.model_name, sizeof info.info.model_name), info.info.model_name,
            padded_length(info.info.serial_number, sizeof info.info.serial_number), info.info.serial_number,
            (unsigned)info.info.firmware_version);
    RUN("threedm.device_startup_settings default", mipc_threedm_device_startup_settings_default(link));
    /* The reply comes after the capture: the typed call adds the averaging time to its timeout. */
    RUN("threedm.capture_gyro_bias", mipc_threedm_capture_gyro_bias(link, GYRO_BIAS_AVERAGING_MS, &bias));
    fprintf(stderr, "gyro bias %g %g %g rad/s\n", (double)bias.bias[0], (double)bias.bias[1],
            (double)bias.bias[2]);
    RUN("threedm.get_base_rate", mipc_threedm_get_base_rate(link, MIPC_FILTER_DATA_SET, &base_rate));
    if (base_rate.rate < BASE_RATE_HZ_OUT || base_rate.rate % BASE_RATE_HZ_OUT != 0) {
        fprintf(stderr, "error: filter data base rate %lu Hz: no decimation gives %u Hz\n",
                (unsigned long)base_rate.rate, BASE_RATE_HZ_OUT);
        return 1;
    }
    for (i = 0; i < sizeof filter_fields; i++) {
        format[i].descriptor = filter_fields[i];
        format[i].decimation = (uint16_t)(base_rate.rate / BASE_RATE_HZ_OUT);
    }
    RUN("threedm.message_format write",
        mipc_threedm_message_format_write(link, MIPC_FILTER_DATA_SET, format, sizeof filter_fields));
    memset(&rotation, 0, sizeof rotation); /* Euler angles 0, 0, 0 */
    for (i = 0; i < sizeof frames; i++) {
        RUN("aiding.frame_config write",
            mipc_aiding_frame_config_write(link, frames[i], MIPC_AIDING_FRAME_FORMAT_EULER, false, zero,
                                           &rotation));
    }
    RUN("filter.aiding_measurement_control write (GNSS)",
        mipc_filter_aiding_measurement_control_write(link, MIPC_AIDING_MEASUREMENT_SOURCE_GNSS_POS_VEL,
                                                     true));
    RUN("filter.aiding_measurement_control write (external heading)",
        mipc_filter_aiding_measurement_control_write(link, MIPC_AIDING_MEASUREMENT_SOURCE_EXTERNAL_HEADING,
                                                     true));
    RUN("filter.initialization_configuration write",
        mipc_filter_initialization_configuration_write(
            link, 0u, MIPC_FILTER_INITIAL_CONDITION_SOURCE_AUTO_POS_VEL_ATT,
            MIPC_HEADING_ALIGNMENT_METHODS_EXTERNAL_MASK, 0.0f, 0.0f, 0.0f, zero, zero,
            MIPC_FILTER_REFERENCE_FRAME_LLH));
    RUN("filter.reset_filter", mipc_filter_reset_filter(link));
    RUN("base.resume", mipc_base_resume(link));
    return 0;
}

/* Sends the aiding measurements of one feed row. */
static int send_aiding(mipc_link_t *link, const feed_row_t *row) {
    static const float position_uncertainty[3] = {1.0f, 1.0f, 1.0f};
    static const float velocity_uncertainty[3] = {0.1f, 0.1f, 0.1f};
    const mipc_aiding_llh_valid_flags_t llh_valid = MIPC_AIDING_LLH_VALID_FLAGS_LATITUDE_MASK |
                                                    MIPC_AIDING_LLH_VALID_FLAGS_LONGITUDE_MASK |
                                                    MIPC_AIDING_LLH_VALID_FLAGS_HEIGHT_MASK;
    const mipc_aiding_vector_valid_flags_t vector_valid = 7u; /* x, y, z */
    mipc_aiding_time_t measured, arrival;
    memset(&measured, 0, sizeof measured);
    measured.timebase = MIPC_AIDING_TIMEBASE_INTERNAL_REFERENCE;
    measured.nanoseconds = row->ns;
    memset(&arrival, 0, sizeof arrival);
    arrival.timebase = MIPC_AIDING_TIMEBASE_TIME_OF_ARRIVAL;

    RUN("aiding.true_heading",
        mipc_aiding_true_heading(link, &measured, FRAME_HEADING, row->heading, 0.01f, 1u));
    RUN("aiding.llh_position", mipc_aiding_llh_position(link, &measured, FRAME_GNSS, row->lat, row->lon,
                                                        row->height, position_uncertainty, llh_valid));
    RUN("aiding.ned_velocity",
        mipc_aiding_ned_velocity(link, &measured, FRAME_GNSS, row->ned, velocity_uncertainty, vector_valid));
    RUN("aiding.body_frame_velocity",
        mipc_aiding_body_frame_velocity(link, &arrival, FRAME_BODY_VELOCITY, row->body, velocity_uncertainty,
                                        vector_valid));
    return 0;
}

/* ------------------------------------------------------------------------------- navigation data */
typedef struct {
    bool have_tow; /* a GPS time was received */
    double tow;    /* the latest one */
    bool have_mode;
    unsigned mode;         /* the last mode printed */
    unsigned long printed; /* full-navigation samples printed */
    unsigned long wanted;
    bool decode_error; /* a filter field did not decode (reported once) */
} nav_t;

/* A JSON number; JSON has no NaN or infinity: null. */
static void json_number(double x) {
    if (isfinite(x)) {
        printf("%.17g", x);
    } else {
        fputs("null", stdout);
    }
}

/* Every data packet that is not a reply: the filter packets (0x82) are decoded field by field. */
static void on_packet(void *ctx, const mipc_event_t *event) {
    nav_t *nav = (nav_t *)ctx;
    mipc_filter_data_gps_timestamp_t time;
    mipc_filter_data_filter_status_cv7_ins_t status;
    mipc_filter_data_llh_position_t llh;
    mipc_filter_data_ned_velocity_t vel;
    mipc_filter_data_euler_angles_t euler;
    unsigned have = 0; /* bit per field above */
    mipc_field_iter_t it;
    mipc_field_entry_t entry;
    mipc_status_t st = MIPC_OK;
    if (mipc_packet_set(event->packet) != MIPC_FILTER_DATA_SET) {
        return;
    }
    mipc_field_iter_init(&it, MIPC_FILTER_DATA_SET, mipc_packet_payload(event->packet),
                         mipc_packet_payload_length(event->packet));
    while (mipc_field_iter_next(&it, &entry)) {
        if (entry.kind != MIPC_ENTRY_FIELD) {
            continue;
        }
        switch (entry.descriptor) {
        case MIPC_FILTER_DATA_GPS_TIMESTAMP_DESCRIPTOR:
            st = mipc_filter_data_gps_timestamp_decode(entry.data, entry.length, &time, NULL);
            have |= st == MIPC_OK ? 1u : 0u;
            break;
        case MIPC_FILTER_DATA_FILTER_STATUS_DESCRIPTOR:
            st = mipc_filter_data_filter_status_cv7_ins_decode(entry.data, entry.length, &status, NULL);
            have |= st == MIPC_OK ? 2u : 0u;
            break;
        case MIPC_FILTER_DATA_LLH_POSITION_DESCRIPTOR:
            st = mipc_filter_data_llh_position_decode(entry.data, entry.length, &llh, NULL);
            have |= st == MIPC_OK ? 4u : 0u;
            break;
        case MIPC_FILTER_DATA_NED_VELOCITY_DESCRIPTOR:
            st = mipc_filter_data_ned_velocity_decode(entry.data, entry.length, &vel, NULL);
            have |= st == MIPC_OK ? 8u : 0u;
            break;
        case MIPC_FILTER_DATA_EULER_ANGLES_DESCRIPTOR:
            st = mipc_filter_data_euler_angles_decode(entry.data, entry.length, &euler, NULL);
            have |= st == MIPC_OK ? 16u : 0u;
            break;
        default:
            st = MIPC_OK; /* another field: not ours */
            break;
        }
        if (st != MIPC_OK && !nav->decode_error) {
            fprintf(stderr, "warning: filter field 0x%02x: %s\n", entry.descriptor, mipc_status_text(st));
            nav->decode_error = true;
        }
    }
    if (have & 1u) {
        nav->have_tow = true;
        nav->tow = time.tow;
    }
    if (!(have & 2u)) {
        return;
    }
    if (!nav->have_mode || status.filter_state != nav->mode) {
        nav->have_mode = true;
        nav->mode = status.filter_state;
        printf("mode %u\n", nav->mode);
        fflush(stdout);
    }
    if (status.filter_state != MIPC_FILTER_MODE_CV7_FULL_NAV || have != 31u || nav->printed >= nav->wanted) {
        return;
    }
    fputs("{\"tow\":", stdout);
    json_number(time.tow);
    fputs(",\"lat\":", stdout);
    json_number(llh.latitude);
    fputs(",\"lon\":", stdout);
    json_number(llh.longitude);
    fputs(",\"height\":", stdout);
    json_number(llh.ellipsoid_height);
    fputs(",\"vel\":[", stdout);
    json_number((double)vel.north);
    putchar(',');
    json_number((double)vel.east);
    putchar(',');
    json_number((double)vel.down);
    fputs("],\"euler\":[", stdout);
    json_number((double)euler.roll);
    putchar(',');
    json_number((double)euler.pitch);
    putchar(',');
    json_number((double)euler.yaw);
    printf("],\"llh_valid\":%u,\"euler_valid\":%u}\n", (unsigned)llh.valid_flags,
           (unsigned)euler.valid_flags);
    fflush(stdout);
    nav->printed++;
}

/* Aids the filter every period until the samples are printed or the deadline passes. */
static int navigate(mipc_link_t *link, const feed_t *feed, const options_t *options) {
    static nav_t nav; /* the handler uses it while the link is open */
    uint64_t now = link->transport.now_ms(link->transport.ctx);
    const uint64_t deadline = now + (uint64_t)options->deadline_s * 1000u;
    uint64_t next_send = now;
    int status;
    memset(&nav, 0, sizeof nav);
    nav.wanted = options->samples;
    mipc_session_on_packet(&link->session, on_packet, &nav);
    while (nav.printed < nav.wanted) {
        if (now >= deadline) {
            fprintf(stderr,
                    "error: deadline of %lu s passed: %lu of %lu samples in full navigation (mode %s%u)\n",
                    options->deadline_s, nav.printed, nav.wanted, nav.have_mode ? "" : "none, ",
                    nav.have_mode ? nav.mode : 0u);
            return 1;
        }
        if (now >= next_send) {
            if (nav.have_tow && (status = send_aiding(link, nearest_row(feed, nav.tow))) != 0) {
                return status; /* data packets reach the handler while the replies are awaited */
            }
            next_send += options->period_ms;
            if (next_send <= now) { /* late (a slow reply): the next one a period from now */
                next_send = now + options->period_ms;
            }
        } else if (mipc_link_pump(link, (uint32_t)((next_send < deadline ? next_send : deadline) - now)) <
                   0) {
            fprintf(stderr, "error: the connection failed\n");
            return 1;
        }
        now = link->transport.now_ms(link->transport.ctx);
    }
    return 0;
}

int main(int argc, char **argv) {
    static mipc_link_t link; /* holds the receive buffers: not on the stack */
    options_t options = {NULL, NULL, 0, 0, 0};
    feed_t feed;
    mipc_posix_t port;
    mipc_transport_t transport;
    mipc_session_config_t config;
    int status = parse_options(argc, argv, &options);
    if (status >= 0) {
        return status;
    }
    if (!load_feed(options.feed, &feed)) {
        return 1;
    }
    if (mipc_posix_open(&port, options.address, BAUD) != MIPC_OK) { /* tcp:HOST:PORT or a serial port */
        fprintf(stderr, "error: %s\n", port.error);
        free(feed.rows);
        return 1;
    }
    mipc_posix_transport(&port, &transport);
    mipc_session_config_init(&config);
    config.device = MIPC_DEVICE_CV7_INS; /* commands the CV7-INS does not support are refused */
    if (mipc_link_init(&link, &transport, &config) != MIPC_OK) {
        fprintf(stderr, "error: cannot start the session\n");
        status = 1;
    } else {
        status = configure(&link);
        if (status == 0) {
            status = navigate(&link, &feed, &options);
        }
        mipc_link_close(&link);
    }
    mipc_posix_close(&port);
    free(feed.rows);
    return status;
}
