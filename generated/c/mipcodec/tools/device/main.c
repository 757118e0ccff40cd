/* mipcodec-device ADDRESS SUBCOMMAND [OPTIONS]: the options read and the subcommand run (device.h).
 * Generated: do not edit. */
#include "device.h"

int usage(const char *fmt, const char *arg) {
    fprintf(stderr, PROG ": ");
    fprintf(stderr, fmt, arg);
    fprintf(stderr, " (" PROG " --help)\n");
    return EXIT_TROUBLE;
}

static bool number_option(const char *name, const char *text, double *out) {
    char *end;
    errno = 0;
    *out = strtod(text, &end);
    if (*text == '\0' || *end != '\0' || errno != 0 || !(*out >= 0) || *out > 4e9) {
        fprintf(stderr, PROG ": %s needs a number >= 0, not '%s'\n", name, text);
        return false;
    }
    return true;
}

static bool int_option(const char *name, const char *text, unsigned long *out) {
    double v;
    if (!number_option(name, text, &v)) {
        return false;
    }
    if (v != floor(v)) {
        fprintf(stderr, PROG ": %s needs an integer, not '%s'\n", name, text);
        return false;
    }
    *out = (unsigned long)v;
    return true;
}

#define OPTIONS_READ (-1)

/* One option at argv[*i] (--NAME, --NAME=VALUE or --NAME VALUE; --ports PATH ...) into o: OPTIONS_READ,
 * or the exit status (usage printed). */
static int read_option(int argc, char **argv, int *i, opts_t *o) {
    const char *a = argv[*i];
    const char *eq = strchr(a, '=');
    char name[32];
    const char *value = NULL;
    size_t n = eq ? (size_t)(eq - a) : strlen(a);
    if (n >= sizeof name) {
        return usage("unknown option '%s'", a);
    }
    memcpy(name, a, n);
    name[n] = '\0';
    if (strcmp(name, "--json") == 0 || strcmp(name, "--force") == 0 || strcmp(name, "--keep") == 0 ||
        strcmp(name, "--save") == 0) {
        if (eq) {
            return usage("%s takes no value", name);
        }
        o->json = o->json || strcmp(name, "--json") == 0;
        o->force = o->force || strcmp(name, "--force") == 0;
        o->keep = o->keep || strcmp(name, "--keep") == 0;
        o->save = o->save || strcmp(name, "--save") == 0;
        return OPTIONS_READ;
    }
    if (strcmp(name, "--ports") == 0) {
        /* auto: the paths up to the next option */
        if (eq) {
            return usage("%s takes paths after it, not '='", name);
        }
        if (o->ports != NULL) {
            return usage("%s is given once", name);
        }
        o->ports = (const char **)(argv + *i + 1); /* the paths stay in argv */
        while (*i + 1 < argc && strncmp(argv[*i + 1], "--", 2) != 0) {
            o->nports++;
            (*i)++;
        }
        if (o->nports == 0) {
            return usage("%s needs at least one path", name);
        }
        return OPTIONS_READ;
    }
    if (strcmp(name, "--device") != 0 && strcmp(name, "--baud") != 0 && strcmp(name, "--timeout-ms") != 0 &&
        strcmp(name, "--rate") != 0 && strcmp(name, "--duration") != 0 && strcmp(name, "--count") != 0 &&
        strcmp(name, "--split-size") != 0 && strcmp(name, "--split-time") != 0 &&
        strcmp(name, "--pps-source") != 0) {
        return usage("unknown option '%s'", a);
    }
    if (eq) {
        value = eq + 1;
    } else if (*i + 1 < argc) {
        value = argv[++*i];
    } else {
        return usage("%s needs a value", name);
    }
    o->duration_given = o->duration_given || strcmp(name, "--duration") == 0;
    if (strcmp(name, "--device") == 0) {
        o->model = value;
    } else if (strcmp(name, "--pps-source") == 0) {
        o->pps_source = value;
    } else if ((strcmp(name, "--baud") == 0 && !int_option(name, value, &o->baud)) ||
               (strcmp(name, "--timeout-ms") == 0 && !int_option(name, value, &o->timeout_ms)) ||
               (strcmp(name, "--count") == 0 && !int_option(name, value, &o->count)) ||
               (strcmp(name, "--rate") == 0 && !number_option(name, value, &o->rate)) ||
               (strcmp(name, "--duration") == 0 && !number_option(name, value, &o->duration)) ||
               (strcmp(name, "--split-size") == 0 && !number_option(name, value, &o->split_size)) ||
               (strcmp(name, "--split-time") == 0 && !number_option(name, value, &o->split_time))) {
        return EXIT_TROUBLE;
    }
    return OPTIONS_READ;
}

/* The options into o and the positional arguments into pos[*npos]: OPTIONS_READ, or the exit
 * status (0 after --help). */
static int read_options(int argc, char **argv, opts_t *o, const char **pos, size_t *npos) {
    int i;
    memset(o, 0, sizeof *o);
    o->timeout_ms = 1000;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        int status;
        if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0) {
            printf("%s\n", USAGE);
            return 0;
        }
        if (strncmp(a, "--", 2) != 0 || a[2] == '\0') {
            pos[(*npos)++] = a;
            continue;
        }
        status = read_option(argc, argv, &i, o);
        if (status != OPTIONS_READ) {
            return status;
        }
    }
    return OPTIONS_READ;
}

/* The subcommand (and the settings action) known, and the options fit it: OPTIONS_READ, or the
 * exit status. */
static int check_subcommand(const opts_t *o, const char *sub, const char *action) {
    if (strcmp(sub, "settings") == 0) {
        if (action == NULL) {
            return usage("%s", "settings: give dump, diff or apply");
        }
        if (strcmp(action, "dump") != 0 && strcmp(action, "diff") != 0 && strcmp(action, "apply") != 0) {
            if (strcmp(action, "schema") == 0) {
                return usage(
                    "%s", "settings schema: the JSON Schema is the Python package's (settings.schema.json)");
            }
            return usage("settings: unknown action '%s' (dump, diff, apply)", action);
        }
    } else if (strcmp(sub, "ping") != 0 && strcmp(sub, "info") != 0 && strcmp(sub, "send") != 0 &&
               strcmp(sub, "stream") != 0 && strcmp(sub, "save-startup") != 0 &&
               strcmp(sub, "factory-reset") != 0 && strcmp(sub, "record") != 0 &&
               strcmp(sub, "timesync") != 0) {
        return usage("unknown subcommand '%s'", sub);
    }
    if (strcmp(sub, "timesync") == 0 && timesync_check(o) != 0) {
        return EXIT_TROUBLE;
    }
    if (o->model != NULL && model_by_id(o->model) == NULL) {
        buf_t ids = {0};
        size_t m;
        for (m = 0; m < DEV_MODEL_COUNT; m++) {
            buf_fmt(&ids, "%s%s", m ? ", " : "", DEV_MODELS[m].id);
        }
        note("unknown device '%s' (one of: %s)", o->model, buf_text(&ids));
        free(ids.s);
        return EXIT_TROUBLE;
    }
    return OPTIONS_READ;
}

/* Connects to address and runs the subcommand: its exit status. */
static int run(const char *address, const char *sub, const char *action, const opts_t *o) {
    static conn_t conn;
    int status = connect_device(&conn, address, o->model, o->baud, o->timeout_ms);
    if (status == 0) {
        if (action != NULL) {
            status = strcmp(action, "dump") == 0   ? cmd_dump(&conn, o)
                     : strcmp(action, "diff") == 0 ? cmd_diff(&conn, o)
                                                   : cmd_apply(&conn, o);
        } else if (strcmp(sub, "ping") == 0) {
            status = cmd_ping(&conn, o);
        } else if (strcmp(sub, "info") == 0) {
            status = cmd_info(&conn, o);
        } else if (strcmp(sub, "send") == 0) {
            status = cmd_send(&conn, o);
        } else if (strcmp(sub, "stream") == 0) {
            status = cmd_stream(&conn, o);
        } else if (strcmp(sub, "timesync") == 0) {
            status = cmd_timesync(&conn, o);
        } else if (strcmp(sub, "save-startup") == 0) {
            status = cmd_save(&conn, o);
        } else {
            status = cmd_factory(&conn, o);
        }
    }
    disconnect(&conn);
    return status;
}

static int tool(int argc, char **argv, const char **pos) {
    opts_t o;
    size_t npos = 0;
    const char *sub;
    const char *action = NULL;
    int status = read_options(argc, argv, &o, pos, &npos);
    if (status != OPTIONS_READ) {
        return status;
    }
    if (npos < 2) {
        return usage("%s", "give ADDRESS and SUBCOMMAND");
    }
    sub = pos[1];
    o.pos = pos + 2;
    o.npos = npos - 2;
    if (strcmp(sub, "settings") == 0 && o.npos >= 1) {
        action = o.pos[0];
        o.pos++;
        o.npos--;
    }
    status = check_subcommand(&o, sub, action);
    if (status != OPTIONS_READ) {
        return status;
    }
    if (strcmp(pos[0], "auto") == 0) {
        if (strcmp(sub, "ping") != 0) {
            return usage("%s", "auto lists the devices that answer: use `auto ping`");
        }
        return cmd_auto(&o);
    }
    if (o.ports != NULL) {
        return usage("%s", "--ports goes with auto");
    }
    if (strcmp(sub, "record") == 0) { /* the device's own bytes: no session in between */
        return cmd_record(pos[0], &o);
    }
    return run(pos[0], sub, action, &o);
}

int main(int argc, char **argv) {
    const char **pos = (const char **)xalloc((size_t)argc * sizeof *pos);
    int status = tool(argc, argv, pos);
    free(pos);
    return status;
}
