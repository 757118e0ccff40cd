/* codec-device ADDRESS SUBCOMMAND [OPTIONS]: the device command line of docs/configure-a-device.md
 * in C, for machines without Python: the same subcommands, arguments, output and exit statuses as
 * the Python package's device CLI (ping, info, send, save-startup, factory-reset, stream, settings
 * dump|diff|apply, record, timesync).
 *
 * What the spec says comes from tools/device_facts.h (generated from the same derivation as the
 * Python package's _settings.py: generator/settings_rows.py); values travel as the library's
 * canonical JSON (a command line -> mipc_json_command_line, a result -> mipc_json_result_line), so
 * the layouts are the library's own.
 *
 * Settings files: the YAML subset that the dumps of this tool and of the Python CLI are written in
 * (docs/configure-a-device.md "The YAML subset of the C tool"):
 *   - one document of block mappings and block sequences, indented with spaces;
 *   - flow sequences and flow mappings on one line ([1, 2], {descriptor: 4, decimation: 10});
 *   - plain, 'single-quoted' and "double-quoted" scalars (null, true/false, integers, floats and
 *     .inf/.nan as YAML 1.1 resolves them; everything else a string);
 *   - comments (# to the end of the line) and blank lines; a leading "---".
 * Anything else (anchors, aliases, tags, block scalars | >, multi-line flow collections, complex
 * keys, tabs in indentation, several documents) is refused with one located FILE:LINE: line.
 *
 * Exit status: 0 done (diff: the device matches the file); 1 the device said no or differs; 2
 * nothing was changed (usage, bad file, refused before sending, no connection); 130 interrupted
 * (stream: 0). */
/* The tool's parts, each file's functions declared here under its name: text.c (messages,
 * buffers), values.c (the value model; JSON lines read through the runtime's JSON reader),
 * yaml.c (settings files), connect.c (the spec's tables, the connection), settings.c (one
 * setting's command values, read and normalized), budget.c (the link budget), requests.c (ping,
 * info, send, save-startup, factory-reset, settings dump), plan.c (settings diff and apply),
 * stream.c (stream, auto ping), record.c (record: the device's stream to a log file), timesync.c
 * (timesync: the device's time synchronization set up and monitored), main.c (the options). */
#ifndef CODEC_DEVICE_TOOL_H
#define CODEC_DEVICE_TOOL_H

#if !defined(_POSIX_C_SOURCE) || _POSIX_C_SOURCE < 200809L
#undef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif
#include <errno.h>
#include <glob.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "codec/json.h"
#include "codec/link.h"
#include "codec/posix_transport.h"
#include "device_facts.h"
#include "hex.h"
#include "json_reader.h" /* the package's src/ (its private headers) */

#define PROG "codec-device"
#define DEFAULT_BAUD 115200UL
#define MAX_PROBLEMS 200

/* A growing string. */
typedef struct {
    char *s;
    size_t n;
    size_t cap;
} buf_t;

typedef enum { V_NULL, V_BOOL, V_INT, V_NUM, V_STR, V_LIST, V_MAP } vkind_t;

typedef struct val val_t;

struct val {
    vkind_t kind;
    int line;   /* where it starts in a file (0: not from a file) */
    char *text; /* V_INT, V_NUM: canonical JSON text of the number; V_STR: the bytes */
    size_t len; /* V_STR: length */
    bool b;
    size_t n;
    size_t cap;
    val_t **items;  /* V_LIST: items; V_MAP: values */
    char **keys;    /* V_MAP: keys */
    int *key_lines; /* V_MAP: the line of each key */
};

typedef struct {
    int number; /* 1-based line number */
    int indent;
    char *text; /* without indentation and comment, right-trimmed (owned) */
} yline_t;

typedef struct {
    yline_t *lines;
    size_t count;
    size_t at;
    char err[300];
    int err_line;
    bool rule; /* err is a settings file's rule, not a YAML subset's */
} yp_t;

typedef struct {
    codec_posix_t posix;
    codec_transport_t transport;
    codec_port_t port;
    codec_link_t link;
    codec_device_t device;
    const dev_model_t *model;
    val_t *identity;    /* item -> value */
    unsigned long baud; /* the serial port's rate (0: TCP) */
    const char *address;
    bool open;
    /* stream: the data set printed, how, and what was seen */
    int stream_set;
    bool stream_json;
    unsigned long stream_limit;
    unsigned long stream_count;
    double stream_first;
    double stream_last;
    /* every data packet's event also goes here (NULL: nowhere): timesync's monitor */
    void (*packet_hook)(void *ctx, const codec_session_event_t *ev);
    void *hook_ctx;
} conn_t;

typedef enum { R_OK = 0, R_FAILED = 1, R_VALUE = 2, R_LOST = 3 } run_t;

typedef struct {
    codec_result_kind_t kind;
    val_t *line; /* the result line, parsed */
    char describe[CODEC_SESSION_ERROR_MAX + 200];
    char json[8192]; /* the result line */
} result_t;

/* Every subcommand returns its exit status; the messages are printed where they arise. */
#define EXIT_REFUSED 1

#define EXIT_TROUBLE 2

#define FORMAT_MAX 256

typedef struct {
    bool present;
    size_t n;
    uint16_t descriptor[FORMAT_MAX];
    uint32_t decimation[FORMAT_MAX];
} format_t;

/* set -> message format; set -> base rate (0: unknown) */
typedef struct {
    format_t set[256];
} formats_t;

typedef struct {
    const char *model;
    unsigned long baud;
    unsigned long timeout_ms;
    double rate;
    double duration;
    bool duration_given;
    const char *pps_source; /* timesync: --pps-source NAME (NULL: not given) */
    unsigned long count;
    double split_size; /* record: --split-size BYTES, --split-time S */
    double split_time;
    bool json;
    bool force;
    bool keep;
    bool save;
    const char **pos; /* the positional arguments after the subcommand (and its action) */
    size_t npos;
    const char **ports; /* auto: --ports PATH ... (NULL: the system's serial ports) */
    size_t nports;
} opts_t;

typedef struct {
    const dev_setting_t *setting;
    val_t **entries; /* normalized */
    int *lines;
    size_t count;
} planned_t;

typedef struct {
    planned_t *items;
    size_t count;
    char **problems;
    size_t problem_count;
} plan_t;

typedef struct {
    const dev_setting_t *setting;
    char key[300];
    val_t *device; /* normalized device values */
    const val_t *file;
} change_t;

#define USAGE                                                                                                \
    "usage: " PROG " ADDRESS SUBCOMMAND [OPTIONS]\n"                                                         \
    "  ADDRESS: tcp:HOST:PORT, a serial port path, or auto (auto ping [--ports PATH ...])\n"                 \
    "  ping | info | send NAME [FUNCTION] [PARAM=VALUE ...] [--json] | save-startup | factory-reset\n"       \
    "  stream FIELD ... [--rate HZ] [--duration S] [--count N] [--json] [--force] [--keep]\n"                \
    "  settings dump [FILE|-] | settings diff FILE | settings apply FILE [--save] [--force]\n"               \
    "  record FILE [--duration S] [--split-size BYTES] [--split-time S] (docs/record.md)\n"                  \
    "  timesync [--duration S] [--json] [--pps-source NAME] (docs/timesync.md)\n"                            \
    "  options of every subcommand: --device ID, --baud N, --timeout-ms N\n"                                 \
    "Exit status: 0 done; 1 the device said no or differs; 2 nothing was changed (usage, bad file, refused " \
    "before sending)."

extern bool quiet_notes;
extern char g_line[64 * 1024];
extern char g_value_error[CODEC_ERROR_MESSAGE_MAX + 400];

/* budget.c */
void formats_from_list(format_t *f, const val_t *list, const dev_format_t *spec);
/* The setting that holds a data set's message format on the model, and the key parameter (NULL:
 * unkeyed). */
const dev_setting_t *format_setting(const conn_t *c, int set, const char **param);
val_t *key_map(const char *param, int set);
/* Every data set's current message format; 0, or the exit status (the message printed). */
int read_formats(conn_t *c, formats_t *out);
/* The base rate of every data set, read from the device (the spec's where no command reads one). */
int read_base_rates(conn_t *c, double *rates);
/* Prints each line of text with a prefix. */
void print_lines(FILE *to, const char *prefix, const char *text);
/* The budget check of apply and stream: 0 (the lines in lines), or 2 when over budget and not
 * forced (the lines and the refusal printed). */
int check_budget(const conn_t *c, const formats_t *formats, const double *base, unsigned long baud,
                 const char *where, bool force, buf_t *lines);
/* The baud rate the budget is checked against and where it comes from. */
unsigned long link_baud(conn_t *c, unsigned long option, char *where, size_t cap);

/* requests.c */
int cmd_ping(conn_t *c, const opts_t *o);
int cmd_info(conn_t *c, const opts_t *o);
int cmd_send(conn_t *c, const opts_t *o);
int run_all_settings(conn_t *c, const char *function);
int cmd_save(conn_t *c, const opts_t *o);
int cmd_factory(conn_t *c, const opts_t *o);
int cmd_dump(conn_t *c, const opts_t *o);

/* connect.c */
const dev_model_t *model_by_id(const char *id);
int64_t function_value(const char *name);
const char *set_name(uint8_t id);
const char *enum_member(int index, int64_t value);
/* "3DM-CV7-GNSS/INS (3dm-cv7-ins-docs.txt)" */
const char *describe_model(codec_device_t d);
/* The field of a command set named name (the first set that has one). */
const codec_field_info_t *command_field(const char *name, uint8_t *set);
double now_s(void);
void result_free(result_t *r);
/* Builds the command line of (set, descriptor) with the values (a JSON object) and runs it.
 * R_VALUE: the values do not fit the layout (g_value_error says why); R_LOST: the connection is
 * gone; R_OK: ack or sent; R_FAILED: nack, timeout, invalid, refused. */
run_t run_values(conn_t *c, uint8_t set, uint8_t descriptor, const char *variant, const char *values,
                 result_t *r);
/* The values of the first reply field named name (NULL: none). */
const val_t *reply_values(const result_t *r, const char *name);
const char *identity_text(const conn_t *c, const char *item, buf_t *b);
/* Opens ADDRESS and identifies the device: 0, or the exit status. */
int connect_device(conn_t *c, const char *address, const char *model, unsigned long baud,
                   unsigned long timeout_ms);
void disconnect(conn_t *c);

/* main.c */
int usage(const char *fmt, const char *arg);

/* plan.c */
int cmd_diff(conn_t *c, const opts_t *o);
int cmd_apply(conn_t *c, const opts_t *o);

/* record.c */
/* `record FILE`: the device's stream into a log file (docs/record.md); its own exit statuses (0
 * stopped, 1 no answer or the device gone, 2 no connection or a file problem). */
int cmd_record(const char *address, const opts_t *o);

/* settings.c */
const dev_format_t *format_of(const dev_setting_t *s);
const char *baud_param(const dev_setting_t *s);
bool is_keyed(const dev_setting_t *s, const char *attr);
const dev_attr_t *attr_of(const dev_setting_t *s, const char *name);
/* Python's str() of a key value in messages ("desc_set 128", "enable True"). */
void py_str(buf_t *b, const val_t *v);
void key_text(buf_t *b, const dev_setting_t *s, const val_t *entry);
/* Whether a equals b ignoring ASCII case (an enum member given in any case, as value.upper()). */
bool strcasecmp_ascii_eq(const char *a, const char *b);
/* The JSON values of the command that writes an entry (function write) or reads it (read: its key
 * parameters only). false with the reason in err. */
bool command_values(const dev_setting_t *s, const val_t *entry, int64_t function, buf_t *out, char *err,
                    size_t cap);
/* Reads one setting for one key (a map of its key parameters): R_OK with *entry, R_FAILED with
 * the result's description in msg (a NACK: *nack), R_VALUE, R_LOST. */
run_t read_entry(conn_t *c, const dev_setting_t *s, const val_t *key, val_t **entry, bool *nack, char *msg,
                 size_t cap);
/* An entry as the device would report it: through the command's encoding (f32 rounding, enum
 * names), so that a file and a device compare equal when the wire values are. NULL with err. */
val_t *normalized(conn_t *c, const dev_setting_t *s, const val_t *entry, char *err, size_t cap);

/* stream.c */
int cmd_stream(conn_t *c, const opts_t *o);
/* Turns the data set's stream on where the model's stream control addresses it: 0, or the exit
 * status (the message printed). */
int enable_stream(conn_t *c, int set);
/* The message format entry to write: the previous one with the fields (at the decimation) as its
 * list and the key parameters of key. */
val_t *stream_entry(const val_t *previous, const val_t *key, const dev_format_t *spec, const int *fields,
                    size_t nf, unsigned long decimation);
/* Writes an entry of the message format setting: 0, or the exit status (the note printed; what
 * is the note's text, NULL: the reason). */
int write_format(conn_t *c, const dev_setting_t *s, const val_t *entry, const char *what);
/* `auto ping`: pings every serial port at the rates above, one line per device that answers
 * (port, rate, model, serial number); a port that answers at no rate is one note. Exit 0 when a
 * device answered, 1 when none did. */
int cmd_auto(const opts_t *o);

/* timesync.c */
/* `timesync`: the checks of its options before connecting (0, or 2 with the message printed). */
int timesync_check(const opts_t *o);
/* `timesync` (docs/timesync.md): exit 0 synchronized at the end, 1 not (the reason on stderr) or
 * the device refused a command, 2 a usage error or no connection. */
int cmd_timesync(conn_t *c, const opts_t *o);

/* text.c */
/* src into dst[cap], cut to fit. Not snprintf("%s"): gcc -O3 warns that it may truncate, which is
 * the point here. */
void copy_text(char *dst, size_t cap, const char *src);
void note(const char *fmt, ...);
void say(const char *fmt, ...);
void *xalloc(size_t n);
void *xrealloc(void *p, size_t n);
char *xstrndup(const char *s, size_t n);
void buf_add(buf_t *b, const char *s, size_t n);
void buf_str(buf_t *b, const char *s);
void buf_fmt(buf_t *b, const char *fmt, ...);
void buf_reset(buf_t *b);
const char *buf_text(const buf_t *b);

/* values.c */
val_t *val_new(vkind_t kind, int line);
void val_free(val_t *v);
val_t *val_str(const char *s, size_t n, int line);
val_t *val_number(vkind_t kind, const char *text, int line);
void val_push(val_t *list, val_t *item);
void val_put(val_t *map, const char *key, size_t klen, int line, val_t *value);
long val_index(const val_t *map, const char *key);
val_t *val_get(const val_t *map, const char *key);
val_t *val_copy(const val_t *v);
void json_string(buf_t *b, const char *s, size_t n);
/* The canonical JSON of a value (no spaces; the library's number text kept). */
void val_json(buf_t *b, const val_t *v);
bool val_equal(const val_t *a, const val_t *b);
/* One JSON value (a line of the library's canonical JSON), or NULL when it is not one. */
val_t *json_parse(const char *s, size_t n);
const char *flow_text(buf_t *b, const val_t *v);

/* yaml.c */
/* A flow value (inside [ ] or { }, or a whole inline value when flow is false) at s[*i]. */
val_t *yp_flow(yp_t *p, const char *s, size_t n, size_t *i, int line, int depth, bool flow);
/* The document of a settings file: a mapping with line numbers, or NULL with "FILE:LINE: ..." in
 * msg. */
val_t *yaml_load(const char *text, size_t n, const char *filename, char *msg, size_t cap);

#endif
