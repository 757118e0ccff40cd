/* cv7_gnss_ins ADDRESS [--antennas 1|2] [--samples N] [--deadline-s N]
 *
 * The 3DM-CV7-GNSS/INS navigating on its internal GNSS receivers (3dm-cv7-ins-docs.txt: the
 * getting-started and Filter pages; tests/apps/README.md), written against the generated C package
 * mipcodec: its typed session API (mipc_<set>_<command>_<function>(&link, ...)), the link of
 * mipcodec/link.h and the POSIX transports of mipcodec/posix_transport.h.
 *
 * It configures the device (ping, idle, device information, the filter data base rate, the
 * filter message: GPS timestamp, filter status, LLH position, NED velocity, Euler angles at 10 Hz;
 * the antenna offsets of receiver 1 (and 2); the aiding sources: GNSS position and velocity, and
 * GNSS heading with two antennas or the magnetometer with one; the filter initialization:
 * automatic position, velocity and attitude, heading from the dual antenna or the magnetometer;
 * a filter reset, resume). Then it reads the data. stdout: "model ...", "serial ...",
 * "firmware N"; "mode N" whenever the filter mode changes; once in full navigation, one JSON
 * object per full-navigation filter packet until --samples were printed. Exit status 0; 1 with
 * "error: ..." on stderr (a command not acknowledged, the connection, the deadline); 2 with
 * "usage: ..." for wrong arguments. */
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
#define FILTER_HZ_OUT 10u           /* the filter data rate asked for: filter base rate / 10 */
#define MAX_MILLISECONDS 86400000ul /* upper bound of --deadline-s (in ms) */

#define USAGE_LINE "usage: cv7_gnss_ins ADDRESS [--antennas 1|2] [--samples N] [--deadline-s N]\n"
static const char USAGE[] = USAGE_LINE
    "  ADDRESS  tcp:HOST:PORT or a serial device path (115200 baud)\n"
    "  --antennas N    GNSS antennas: 1 (heading from the magnetometer) or 2 (dual antenna; default 1)\n"
    "  --samples N     full-navigation samples to print (default 20)\n"
    "  --deadline-s N  give up after N seconds of waiting (default 60)\n";

/* ------------------------------------------------------------------------------- arguments */
typedef struct {
    const char *address;
    unsigned long antennas; /* GNSS antennas: 1 or 2 */
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
    options->antennas = 1;
    options->samples = 20;
    options->deadline_s = 60;
    for (i = 1; i < argc; i++) {
        const char *arg = argv[i];
        unsigned long *value = NULL, max = 0;
        if (strcmp(arg, "-h") == 0 || strcmp(arg, "--help") == 0) {
            fputs(USAGE, stdout);
            return 0;
        }
        if (strcmp(arg, "--antennas") == 0) {
            value = &options->antennas;
            max = 2;
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
        } else {
            fprintf(stderr, "usage: unexpected argument %s\n" USAGE_LINE, arg);
            return 2;
        }
    }
    if (positional != 1) {
        fputs(USAGE, stderr);
        return 2;
    }
    return -1;
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

/* The decimation giving hz out of base_hz; 0 (reported) when none does. */
static uint16_t decimation(const char *what, unsigned long base_hz, unsigned hz) {
    if (base_hz < hz || base_hz % hz != 0 || base_hz / hz > 0xFFFFu) {
        fprintf(stderr, "error: %s base rate %lu Hz: no decimation gives %u Hz\n", what, base_hz, hz);
        return 0;
    }
    return (uint16_t)(base_hz / hz);
}

/* The configuration steps of the flow, in the order of the README. */
static int configure(mipc_link_t *link, unsigned long antennas) {
    static const uint8_t filter_fields[] = {
        MIPC_FILTER_DATA_GPS_TIMESTAMP_DESCRIPTOR, MIPC_FILTER_DATA_FILTER_STATUS_DESCRIPTOR,
        MIPC_FILTER_DATA_LLH_POSITION_DESCRIPTOR,  MIPC_FILTER_DATA_NED_VELOCITY_DESCRIPTOR,
        MIPC_FILTER_DATA_EULER_ANGLES_DESCRIPTOR,
    };
    /* The antennas of receivers 1 and 2 in the vehicle frame (x forward, y right, z down) [m]:
     * 0.5 m left and right of the device, 0.2 m above it. */
    static const float antenna_offsets[2][3] = {{0.0f, -0.5f, -0.2f}, {0.0f, 0.5f, -0.2f}};
    static const float zero[3] = {0.0f, 0.0f, 0.0f};
    const bool dual = antennas == 2;
    mipc_base_device_info_t info;
    mipc_threedm_base_rate_t base_rate;
    mipc_descriptor_rate_t format[sizeof filter_fields];
    uint16_t filter_decimation;
    size_t i;

    RUN("base.ping", mipc_base_ping(link));
    RUN("base.set_to_idle", mipc_base_set_to_idle(link));
    RUN("base.get_device_info", mipc_base_get_device_info(link, &info));
    printf("model %.*s\nserial %.*s\nfirmware %u\n",
           padded_length(info.info.model_name, sizeof info.info.model_name), info.info.model_name,
           padded_length(info.info.serial_number, sizeof info.info.serial_number), info.info.serial_number,
           (unsigned)info.info.firmware_version);
    fflush(stdout);
    RUN("threedm.get_base_rate", mipc_threedm_get_base_rate(link, MIPC_FILTER_DATA_SET, &base_rate));
    filter_decimation = decimation("filter data", base_rate.rate, FILTER_HZ_OUT);
    if (filter_decimation == 0) {
        return 1;
    }
    for (i = 0; i < sizeof filter_fields; i++) {
        format[i].descriptor = filter_fields[i];
        format[i].decimation = filter_decimation;
    }
    RUN("threedm.message_format write",
        mipc_threedm_message_format_write(link, MIPC_FILTER_DATA_SET, format, sizeof filter_fields));
    for (i = 0; i < antennas; i++) { /* receivers 1 and 2 */
        RUN("filter.multi_antenna_offset write",
            mipc_filter_multi_antenna_offset_write(link, (uint8_t)(i + 1u), antenna_offsets[i]));
    }
    RUN("filter.aiding_measurement_control write (GNSS position and velocity)",
        mipc_filter_aiding_measurement_control_write(link, MIPC_AIDING_MEASUREMENT_SOURCE_GNSS_POS_VEL,
                                                     true));
    RUN("filter.aiding_measurement_control write (GNSS heading)",
        mipc_filter_aiding_measurement_control_write(link, MIPC_AIDING_MEASUREMENT_SOURCE_GNSS_HEADING,
                                                     dual));
    RUN("filter.aiding_measurement_control write (magnetometer)",
        mipc_filter_aiding_measurement_control_write(link, MIPC_AIDING_MEASUREMENT_SOURCE_MAGNETOMETER,
                                                     !dual));
    /* No wait for the run command, automatic position, velocity and attitude, the initial heading
     * from the dual antenna or the magnetometer, reference frame LLH, zeros elsewhere. */
    RUN("filter.initialization_configuration write",
        mipc_filter_initialization_configuration_write(
            link, 0u, MIPC_FILTER_INITIAL_CONDITION_SOURCE_AUTO_POS_VEL_ATT,
            dual ? MIPC_HEADING_ALIGNMENT_METHODS_DUAL_ANTENNA_MASK
                 : MIPC_HEADING_ALIGNMENT_METHODS_MAGNETOMETER_MASK,
            0.0f, 0.0f, 0.0f, zero, zero, MIPC_FILTER_REFERENCE_FRAME_LLH));
    RUN("filter.reset_filter", mipc_filter_reset_filter(link));
    RUN("base.resume", mipc_base_resume(link));
    return 0;
}

/* ------------------------------------------------------------------------------- data */
typedef struct {
    bool have_mode;
    unsigned mode;         /* the last mode printed */
    unsigned long printed; /* samples printed */
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
            have |= st == MIPC_OK ? 8u : 0u;
            break;
        case MIPC_FILTER_DATA_NED_VELOCITY_DESCRIPTOR:
            st = mipc_filter_data_ned_velocity_decode(entry.data, entry.length, &vel, NULL);
            have |= st == MIPC_OK ? 16u : 0u;
            break;
        case MIPC_FILTER_DATA_EULER_ANGLES_DESCRIPTOR:
            st = mipc_filter_data_euler_angles_decode(entry.data, entry.length, &euler, NULL);
            have |= st == MIPC_OK ? 4u : 0u;
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

/* Reads the filter data until the samples are printed or the deadline passes. */
static int read_data(mipc_link_t *link, nav_t *nav, const options_t *options, uint64_t deadline) {
    uint64_t now = link->transport.now_ms(link->transport.ctx);
    while (nav->printed < nav->wanted) {
        if (now >= deadline) {
            fprintf(stderr,
                    "error: deadline of %lu s passed: %lu of %lu samples in full navigation (mode %s%u)\n",
                    options->deadline_s, nav->printed, nav->wanted, nav->have_mode ? "" : "none, ",
                    nav->have_mode ? nav->mode : 0u);
            return 1;
        }
        if (mipc_link_pump(link, (uint32_t)(deadline - now)) < 0) {
            fprintf(stderr, "error: the connection failed\n");
            return 1;
        }
        now = link->transport.now_ms(link->transport.ctx);
    }
    return 0;
}

int main(int argc, char **argv) {
    static mipc_link_t link; /* holds the receive buffers: not on the stack */
    static nav_t nav;        /* the handler uses it while the link is open */
    options_t options = {NULL, 0, 0, 0};
    mipc_posix_t port;
    mipc_transport_t transport;
    mipc_session_config_t config;
    int status = parse_options(argc, argv, &options);
    if (status >= 0) {
        return status;
    }
    if (mipc_posix_open(&port, options.address, BAUD) != MIPC_OK) { /* tcp:HOST:PORT or a serial port */
        fprintf(stderr, "error: %s\n", port.error);
        return 1;
    }
    mipc_posix_transport(&port, &transport);
    mipc_session_config_init(&config);
    config.device = MIPC_DEVICE_CV7_INS; /* commands the CV7-INS does not support are refused */
    if (mipc_link_init(&link, &transport, &config) != MIPC_OK) {
        fprintf(stderr, "error: cannot start the session\n");
        status = 1;
    } else {
        /* The deadline counts from the start. */
        const uint64_t deadline = transport.now_ms(transport.ctx) + (uint64_t)options.deadline_s * 1000u;
        memset(&nav, 0, sizeof nav);
        nav.wanted = options.samples;
        status = configure(&link, options.antennas);
        if (status == 0) {
            /* Data packets reach the handler from here on (the filter data runs after resume). */
            mipc_session_on_packet(&link.session, on_packet, &nav);
            status = read_data(&link, &nav, &options, deadline);
        }
        mipc_link_close(&link);
    }
    mipc_posix_close(&port);
    return status;
}
