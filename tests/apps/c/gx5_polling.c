/* gx5_polling ADDRESS [--samples N] [--deadline-s N]
 *
 * The 3DM-GX5-45 polling flow (3dm-gx5-45-dcp.txt section 2.4 and the Poll IMU Data / Poll
 * Estimation Filter Data commands; tests/apps/README.md), written against the generated C package
 * mipcodec: its typed session API (mipc_<set>_<command>_<function>(&link, ...)), the link of
 * mipcodec/link.h and the POSIX transports of mipcodec/posix_transport.h.
 *
 * It configures the device (ping, idle, the IMU and filter data base rates, the IMU message
 * format: scaled accelerometer and gyro, the filter message format: GPS timestamp, filter status,
 * LLH position, Euler angles) and leaves it idle: no stream is resumed. Then, every 100 ms, it
 * polls the IMU data and the filter data (each poll answered by an ACK and a data packet).
 * stdout: "imu ok" once the first IMU packet with both vectors came; "state N" whenever the filter
 * state changes; once the state is "run solution valid", one JSON object per polled filter sample
 * in that state until --samples were printed. Exit status 0; 1 with "error: ..." on stderr (a
 * command not acknowledged, the connection, the deadline); 2 with "usage: ..." for wrong
 * arguments. */
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
#define IMU_HZ_OUT 100u             /* the IMU data rate asked for: decimation imu base rate / 100 */
#define FILTER_HZ_OUT 10u           /* the filter data rate asked for: filter base rate / 10 */
#define POLL_PERIOD_MS 100u         /* how often the data is polled */
#define CF_EULER_WAIT_MS 1000u      /* how long the polled complementary filter angles are awaited */
#define MAX_MILLISECONDS 86400000ul /* upper bound of --deadline-s (in ms) */

#define USAGE_LINE "usage: gx5_polling ADDRESS [--samples N] [--deadline-s N]\n"
static const char USAGE[] =
    USAGE_LINE "  ADDRESS  tcp:HOST:PORT or a serial device path (115200 baud)\n"
               "  --samples N     samples in 'run solution valid' to print (default 20)\n"
               "  --deadline-s N  give up after N seconds of waiting (default 60)\n";

/* ------------------------------------------------------------------------------- arguments */
typedef struct {
    const char *address;
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
    options->samples = 20;
    options->deadline_s = 60;
    for (i = 1; i < argc; i++) {
        const char *arg = argv[i];
        unsigned long *value = NULL, max = 0;
        if (strcmp(arg, "-h") == 0 || strcmp(arg, "--help") == 0) {
            fputs(USAGE, stdout);
            return 0;
        }
        if (strcmp(arg, "--samples") == 0) {
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

/* The IMU and filter data fields: the message formats and the polls. */
static const uint8_t imu_fields[] = {MIPC_SENSOR_SCALED_ACCEL_DESCRIPTOR, MIPC_SENSOR_SCALED_GYRO_DESCRIPTOR};
static const uint8_t filter_fields[] = {
    MIPC_FILTER_DATA_GPS_TIMESTAMP_DESCRIPTOR,
    MIPC_FILTER_DATA_FILTER_STATUS_DESCRIPTOR,
    MIPC_FILTER_DATA_LLH_POSITION_DESCRIPTOR,
    MIPC_FILTER_DATA_EULER_ANGLES_DESCRIPTOR,
};

/* The configuration steps of the flow: the message formats, the device left idle. */
static int configure(mipc_link_t *link) {
    mipc_base_device_info_t info;
    mipc_threedm_imu_base_rate_t imu_rate;
    mipc_threedm_filter_base_rate_t filter_rate;
    mipc_descriptor_rate_t imu_format[sizeof imu_fields];
    mipc_descriptor_rate_t filter_format[sizeof filter_fields];
    uint16_t imu_decimation, filter_decimation;
    size_t i;

    RUN("base.ping", mipc_base_ping(link));
    RUN("base.set_to_idle", mipc_base_set_to_idle(link));
    RUN("base.get_device_info", mipc_base_get_device_info(link, &info));
    printf("model %.*s\nserial %.*s\nfirmware %u\n",
           padded_length(info.info.model_name, sizeof info.info.model_name), info.info.model_name,
           padded_length(info.info.serial_number, sizeof info.info.serial_number), info.info.serial_number,
           (unsigned)info.info.firmware_version);
    fflush(stdout);
    RUN("threedm.get_imu_base_rate", mipc_threedm_get_imu_base_rate(link, &imu_rate));
    RUN("threedm.get_filter_base_rate", mipc_threedm_get_filter_base_rate(link, &filter_rate));
    imu_decimation = decimation("IMU data", imu_rate.rate, IMU_HZ_OUT);
    filter_decimation = decimation("filter data", filter_rate.rate, FILTER_HZ_OUT);
    if (imu_decimation == 0 || filter_decimation == 0) {
        return 1;
    }
    for (i = 0; i < sizeof imu_fields; i++) {
        imu_format[i].descriptor = imu_fields[i];
        imu_format[i].decimation = imu_decimation;
    }
    for (i = 0; i < sizeof filter_fields; i++) {
        filter_format[i].descriptor = filter_fields[i];
        filter_format[i].decimation = filter_decimation;
    }
    RUN("threedm.imu_message_format write",
        mipc_threedm_imu_message_format_write(link, imu_format, sizeof imu_fields));
    RUN("threedm.filter_message_format write",
        mipc_threedm_filter_message_format_write(link, filter_format, sizeof filter_fields));
    /* No resume: the device stays idle and sends data only when polled. */
    return 0;
}

/* ------------------------------------------------------------------------------- data */
typedef struct {
    bool imu_ok;                            /* "imu ok" printed */
    bool have_cf_euler;                     /* complementary filter Euler angles received */
    mipc_sensor_cf_euler_angles_t cf_euler; /* the first ones */
    bool have_state;
    unsigned state;        /* the last filter state printed */
    unsigned long printed; /* samples printed in "run solution valid" */
    unsigned long wanted;
    bool decode_error; /* a field did not decode (reported once) */
} nav_t;

/* A JSON number; JSON has no NaN or infinity: null. */
static void json_number(double x) {
    if (isfinite(x)) {
        printf("%.17g", x);
    } else {
        fputs("null", stdout);
    }
}

static void decode_warning(nav_t *nav, uint8_t set, uint8_t descriptor, mipc_status_t st) {
    if (st != MIPC_OK && !nav->decode_error) {
        fprintf(stderr, "warning: field 0x%02x,0x%02x: %s\n", set, descriptor, mipc_status_text(st));
        nav->decode_error = true;
    }
}

/* An IMU packet (0x80): "imu ok" once both vectors decoded; the complementary filter Euler
 * angles of the filter initialization. */
static void on_imu(nav_t *nav, const mipc_event_t *event) {
    mipc_sensor_scaled_accel_t accel;
    mipc_sensor_scaled_gyro_t gyro;
    unsigned have = 0;
    mipc_field_iter_t it;
    mipc_field_entry_t entry;
    mipc_status_t st = MIPC_OK;
    mipc_field_iter_init(&it, MIPC_SENSOR_SET, mipc_packet_payload(event->packet),
                         mipc_packet_payload_length(event->packet));
    while (mipc_field_iter_next(&it, &entry)) {
        if (entry.kind != MIPC_ENTRY_FIELD) {
            continue;
        }
        if (entry.descriptor == MIPC_SENSOR_SCALED_ACCEL_DESCRIPTOR) {
            st = mipc_sensor_scaled_accel_decode(entry.data, entry.length, &accel, NULL);
            have |= st == MIPC_OK ? 1u : 0u;
        } else if (entry.descriptor == MIPC_SENSOR_SCALED_GYRO_DESCRIPTOR) {
            st = mipc_sensor_scaled_gyro_decode(entry.data, entry.length, &gyro, NULL);
            have |= st == MIPC_OK ? 2u : 0u;
        } else if (entry.descriptor == MIPC_SENSOR_CF_EULER_ANGLES_DESCRIPTOR && !nav->have_cf_euler) {
            st = mipc_sensor_cf_euler_angles_decode(entry.data, entry.length, &nav->cf_euler, NULL);
            nav->have_cf_euler = st == MIPC_OK;
        } else {
            st = MIPC_OK; /* another field: not ours */
        }
        decode_warning(nav, MIPC_SENSOR_SET, entry.descriptor, st);
    }
    if (have == 3u && !nav->imu_ok) {
        nav->imu_ok = true;
        puts("imu ok");
        fflush(stdout);
    }
}

/* A filter packet (0x82), decoded field by field. */
static void on_filter(nav_t *nav, const mipc_event_t *event) {
    mipc_filter_data_gps_timestamp_t time;
    mipc_filter_data_filter_status_gx5_45_t status;
    mipc_filter_data_llh_position_t llh;
    mipc_filter_data_euler_angles_t euler;
    unsigned have = 0; /* bit per field above */
    mipc_field_iter_t it;
    mipc_field_entry_t entry;
    mipc_status_t st = MIPC_OK;
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
            st = mipc_filter_data_filter_status_gx5_45_decode(entry.data, entry.length, &status, NULL);
            have |= st == MIPC_OK ? 2u : 0u;
            break;
        case MIPC_FILTER_DATA_LLH_POSITION_DESCRIPTOR:
            st = mipc_filter_data_llh_position_decode(entry.data, entry.length, &llh, NULL);
            have |= st == MIPC_OK ? 4u : 0u;
            break;
        case MIPC_FILTER_DATA_EULER_ANGLES_DESCRIPTOR:
            st = mipc_filter_data_euler_angles_decode(entry.data, entry.length, &euler, NULL);
            have |= st == MIPC_OK ? 8u : 0u;
            break;
        default:
            st = MIPC_OK; /* another field: not ours */
            break;
        }
        decode_warning(nav, MIPC_FILTER_DATA_SET, entry.descriptor, st);
    }
    if (!(have & 2u)) {
        return;
    }
    if (!nav->have_state || status.filter_state != nav->state) {
        nav->have_state = true;
        nav->state = status.filter_state;
        printf("state %u\n", nav->state);
        fflush(stdout);
    }
    if (status.filter_state != MIPC_FILTER_STATE_GX5_RUN_SOLUTION_VALID || have != 15u ||
        nav->printed >= nav->wanted) {
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
    fputs(",\"euler\":[", stdout);
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

/* Every data packet that is not a reply. */
static void on_packet(void *ctx, const mipc_event_t *event) {
    nav_t *nav = (nav_t *)ctx;
    if (mipc_packet_set(event->packet) == MIPC_SENSOR_SET) {
        on_imu(nav, event);
    } else if (mipc_packet_set(event->packet) == MIPC_FILTER_DATA_SET) {
        on_filter(nav, event);
    }
}

/* The manual's step 7, Initialize the Filter (3dm-gx5-45-dcp.txt line 431): poll the
 * complementary filter's Euler angles (0x80,0x0C), then Set Initial Attitude (0x0D,0x02) with them.
 * A device with auto-initialization enabled does not need it, but neither manual states that
 * option's factory setting, so the program does not rely on it. The handler is installed. */
static int initialize_filter(mipc_link_t *link, const nav_t *nav) {
    mipc_gx5_poll_descriptor_t cf_euler;
    uint64_t now = link->transport.now_ms(link->transport.ctx);
    const uint64_t end = now + CF_EULER_WAIT_MS; /* the data packet follows the ACK */
    memset(&cf_euler, 0, sizeof cf_euler);
    cf_euler.descriptor = MIPC_SENSOR_CF_EULER_ANGLES_DESCRIPTOR;
    RUN("threedm.poll_imu_data (complementary filter Euler angles)",
        mipc_threedm_poll_imu_data(link, MIPC_GX5_POLL_OPTION_NORMAL, &cf_euler, 1));
    while (!nav->have_cf_euler && now < end) {
        if (mipc_link_pump(link, (uint32_t)(end - now)) < 0) {
            fprintf(stderr, "error: the connection failed\n");
            return 1;
        }
        now = link->transport.now_ms(link->transport.ctx);
    }
    if (!nav->have_cf_euler) {
        fprintf(
            stderr,
            "error: threedm.poll_imu_data: no complementary filter Euler angles (0x80,0x0C) within %u ms\n",
            CF_EULER_WAIT_MS);
        return 1;
    }
    RUN("filter.set_initial_attitude",
        mipc_filter_set_initial_attitude(link, nav->cf_euler.roll, nav->cf_euler.pitch, nav->cf_euler.yaw));
    return 0;
}

/* Polls the IMU and the filter data (normal option: an ACK, then the data packet). */
static int poll_once(mipc_link_t *link) {
    mipc_gx5_poll_descriptor_t imu[sizeof imu_fields], filter[sizeof filter_fields];
    size_t i;
    memset(imu, 0, sizeof imu);
    memset(filter, 0, sizeof filter);
    for (i = 0; i < sizeof imu_fields; i++) {
        imu[i].descriptor = imu_fields[i];
    }
    for (i = 0; i < sizeof filter_fields; i++) {
        filter[i].descriptor = filter_fields[i];
    }
    RUN("threedm.poll_imu_data",
        mipc_threedm_poll_imu_data(link, MIPC_GX5_POLL_OPTION_NORMAL, imu, sizeof imu_fields));
    RUN("threedm.poll_filter_data",
        mipc_threedm_poll_filter_data(link, MIPC_GX5_POLL_OPTION_NORMAL, filter, sizeof filter_fields));
    return 0;
}

/* Polls every period until the samples are printed or the deadline passes. */
static int read_data(mipc_link_t *link, nav_t *nav, const options_t *options, uint64_t deadline) {
    uint64_t now = link->transport.now_ms(link->transport.ctx);
    uint64_t next_poll = now;
    int status;
    while (nav->printed < nav->wanted) {
        if (now >= deadline) {
            fprintf(
                stderr,
                "error: deadline of %lu s passed: %lu of %lu samples in 'run solution valid' (IMU data %s, "
                "filter state %s%u)\n",
                options->deadline_s, nav->printed, nav->wanted, nav->imu_ok ? "seen" : "none",
                nav->have_state ? "" : "none, ", nav->have_state ? nav->state : 0u);
            return 1;
        }
        if (now >= next_poll) {
            if ((status = poll_once(link)) != 0) {
                return status; /* the data packets reach the handler while the replies are awaited */
            }
            next_poll += POLL_PERIOD_MS;
            if (next_poll <= now) { /* late (a slow reply): the next one a period from now */
                next_poll = now + POLL_PERIOD_MS;
            }
        } else if (mipc_link_pump(link, (uint32_t)((next_poll < deadline ? next_poll : deadline) - now)) <
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
    static nav_t nav;        /* the handler uses it while the link is open */
    options_t options = {NULL, 0, 0};
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
    config.device = MIPC_DEVICE_GX5_45; /* commands the GX5-45 does not support are refused */
    if (mipc_link_init(&link, &transport, &config) != MIPC_OK) {
        fprintf(stderr, "error: cannot start the session\n");
        status = 1;
    } else {
        /* The deadline counts from the start. */
        const uint64_t deadline = transport.now_ms(transport.ctx) + (uint64_t)options.deadline_s * 1000u;
        memset(&nav, 0, sizeof nav);
        nav.wanted = options.samples;
        status = configure(&link);
        if (status == 0) {
            /* Data packets reach the handler from here on: the polled ones. */
            mipc_session_on_packet(&link.session, on_packet, &nav);
            status = initialize_filter(&link, &nav);
        }
        if (status == 0) {
            status = read_data(&link, &nav, &options, deadline);
        }
        mipc_link_close(&link);
    }
    mipc_posix_close(&port);
    return status;
}
