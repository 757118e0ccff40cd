// I/O of the command-line tools (docs/conformance.md section 5), shared by decode and encode:
// input read in blocks as it arrives, output written through stdio and checked, and the one rule
// for I/O faults: a closed pipe on stdout ends the tool by SIGPIPE, quietly (the Unix convention,
// as `cat` does); any other read or write error is one line on stderr and exit status 2.
#pragma once

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <string>

#if defined(__unix__) || defined(__APPLE__)
#include <sys/stat.h>
#include <unistd.h>
#define PROTOPKG_TOOL_POSIX 1
#else
#define PROTOPKG_TOOL_POSIX 0
#endif
#ifdef _WIN32
#include <fcntl.h>
#include <io.h>
#endif

namespace protopkg::tool_io {

/// Reads what is available, at most `cap` bytes (blocking only until some bytes arrive, so a
/// live stream is decoded as it comes). Returns the count, 0 at the end, or -1 with errno set.
inline long read_some(std::FILE *in, unsigned char *buf, std::size_t cap) {
#if PROTOPKG_TOOL_POSIX
    for (;;) {
        const ssize_t n = ::read(fileno(in), buf, cap);
        if (n >= 0) {
            return static_cast<long>(n);
        }
        if (errno != EINTR) {
            return -1;
        }
    }
#else
    const std::size_t n = std::fread(buf, 1, cap, in);
    if (n == 0 && std::ferror(in)) {
        if (errno == 0) {
            errno = EIO;
        }
        return -1;
    }
    return static_cast<long>(n);
#endif
}

/// Standard input and output carry bytes as they are. On Windows they start in text mode (a CR
/// before every LF written, input cut at a Ctrl-Z byte): switched to binary there, so that the
/// tools read and write the same bytes as on POSIX systems; nothing to do elsewhere.
inline void binary_stdio() {
#ifdef _WIN32
    (void)_setmode(_fileno(stdin), _O_BINARY);
    (void)_setmode(_fileno(stdout), _O_BINARY);
#endif
}

/// Whether stdout is a regular file (written in large blocks; otherwise, a pipe or a terminal,
/// the lines of every block of input are flushed as soon as they are printed).
inline bool stdout_is_file() {
#if PROTOPKG_TOOL_POSIX
    struct stat st{};
    return fstat(fileno(stdout), &st) == 0 && S_ISREG(st.st_mode);
#else
    return false;
#endif
}

/// Output to stdout that remembers the first failure (errno) instead of going on silently.
class Output {
  public:
    void put(const void *data, std::size_t n) {
        if (err_ != 0 || n == 0) {
            return;
        }
        errno = 0;
        if (std::fwrite(data, 1, n, stdout) != n) {
            err_ = errno != 0 ? errno : EIO;
        }
    }
    void put(const std::string &s) {
        put(s.data(), s.size());
    }
    void flush() {
        if (err_ != 0) {
            return;
        }
        errno = 0;
        if (std::fflush(stdout) != 0) {
            err_ = errno != 0 ? errno : EIO;
        }
    }
    bool failed() const {
        return err_ != 0;
    }
    /// After a failure: a closed pipe ends the process by SIGPIPE; otherwise one line on
    /// stderr. Returns the exit status 2.
    int report(const char *prog) const {
#if PROTOPKG_TOOL_POSIX
        if (err_ == EPIPE) {
            std::signal(SIGPIPE, SIG_DFL);
            std::raise(SIGPIPE);
        }
#endif
        std::fprintf(stderr, "%s: cannot write standard output: %s\n", prog, std::strerror(err_));
        return 2;
    }

  private:
    int err_ = 0;
};

/// A read failed with errno `err`: one line on stderr; returns the exit status 2.
inline int read_error(const char *prog, const std::string &name, int err) {
    std::fprintf(stderr, "%s: cannot read %s: %s\n", prog, name.c_str(), std::strerror(err));
    return 2;
}

} // namespace protopkg::tool_io
