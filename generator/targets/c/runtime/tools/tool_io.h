/* I/O of the command-line tools (docs/conformance.md section 5), shared by decode and encode:
 * input read in blocks as it arrives, output written through stdio and checked, and the one rule
 * for I/O faults: a closed pipe on stdout ends the tool by SIGPIPE, quietly (the Unix convention,
 * as `cat` does); any other read or write error is one line on stderr and exit status 2. The
 * tools may allocate; the library does not. */
#ifndef CODEC_TOOLS_TOOL_IO_H
#define CODEC_TOOLS_TOOL_IO_H

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if defined(__unix__) || defined(__APPLE__)
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>
#define CODEC_TOOL_POSIX 1
#else
#define CODEC_TOOL_POSIX 0
#endif
#ifdef _WIN32
#include <fcntl.h>
#include <io.h>
#endif

/* Standard input and output carry bytes as they are. On Windows they start in text mode (a CR
 * before every LF written, input cut at a Ctrl-Z byte): switched to binary there, so that the tools
 * read and write the same bytes as on POSIX systems; nothing to do elsewhere. */
static void tool_binary_stdio(void) {
#ifdef _WIN32
    (void)_setmode(_fileno(stdin), _O_BINARY);
    (void)_setmode(_fileno(stdout), _O_BINARY);
#endif
}

/* Reads what is available, at most cap bytes (blocking only until some bytes arrive, so a live
 * stream is decoded as it comes). Returns the count, 0 at the end, or -1 with errno set. */
static long tool_read(FILE *in, unsigned char *buf, size_t cap) {
#if CODEC_TOOL_POSIX
    for (;;) {
        ssize_t n = read(fileno(in), buf, cap);
        if (n >= 0) {
            return (long)n;
        }
        if (errno != EINTR) {
            return -1;
        }
    }
#else
    size_t n = fread(buf, 1, cap, in);
    if (n == 0 && ferror(in)) {
        if (errno == 0) {
            errno = EIO;
        }
        return -1;
    }
    return (long)n;
#endif
}

/* Whether stdout is a regular file (then it is written in large blocks; otherwise, a pipe or a
 * terminal, every block of input read is flushed as soon as its lines are printed). */
static int tool_stdout_is_file(void) {
#if CODEC_TOOL_POSIX
    struct stat st;
    return fstat(fileno(stdout), &st) == 0 && S_ISREG(st.st_mode);
#else
    return 0;
#endif
}

/* A write to stdout failed with errno err: a closed pipe ends the process by SIGPIPE (as if the
 * signal had not been ignored); otherwise one line on stderr. Returns the exit status 2. */
static int tool_write_error(const char *prog, int err) {
#if CODEC_TOOL_POSIX
    if (err == EPIPE) {
        signal(SIGPIPE, SIG_DFL);
        raise(SIGPIPE);
    }
#endif
    fprintf(stderr, "%s: cannot write standard output: %s\n", prog, err ? strerror(err) : "write error");
    return 2;
}

/* A read failed with errno err: one line on stderr; returns the exit status 2. */
static int tool_read_error(const char *prog, const char *name, int err) {
    fprintf(stderr, "%s: cannot read %s: %s\n", prog, name, err ? strerror(err) : "read error");
    return 2;
}

/* Writes n bytes to stdout; on failure keeps the first errno in *err (0: no failure yet). */
static void tool_put(const void *data, size_t n, int *err) {
    if (*err != 0 || n == 0) {
        return;
    }
    errno = 0;
    if (fwrite(data, 1, n, stdout) != n) {
        *err = errno ? errno : EIO;
    }
}

/* Flushes stdout; on failure keeps the errno in *err. */
static void tool_flush(int *err) {
    if (*err != 0) {
        return;
    }
    errno = 0;
    if (fflush(stdout) != 0) {
        *err = errno ? errno : EIO;
    }
}

#endif
