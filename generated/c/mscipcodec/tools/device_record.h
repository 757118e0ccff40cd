/* The recorder of the device tool: mscipcodec-device ADDRESS record FILE [--duration S] [--split-size
 * BYTES] [--split-time S] (docs/record.md; the Python CLI's recorder.py does the same).
 * Generated: do not edit. */
#ifndef MSCIPC_DEVICE_RECORD_H
#define MSCIPC_DEVICE_RECORD_H

#include <stdint.h>

typedef struct {
    const char *address;
    const char *path;
    unsigned long baud;
    unsigned long timeout_ms; /* the wait for the Device Information reply */
    double duration;          /* seconds; 0: until stopped */
    double split_size;        /* bytes; 0: one file */
    double split_time;        /* seconds; 0: one file */
    uint8_t command_set;      /* the Device Information command */
    uint8_t command_descriptor;
    uint8_t reply_set; /* its reply field */
    uint8_t reply_descriptor;
} device_record_options_t;

/* Records the device: the exit status (0 stopped by --duration, SIGINT or SIGTERM; 1 the device
 * did not answer or went away; 2 no connection, a file that exists or cannot be created, a failed
 * write), the messages on stderr. */
int device_record(const device_record_options_t *o);

#endif
