// Shared by the C++ fuzz harnesses: one source serves every generated C++ package. The build
// passes -DFZ_PACKAGE_HEADER='"mipcodec/json_lines.hpp"' -DFZ_NS=mipcodec. A failed check prints
// what went wrong and aborts (a finding for libFuzzer and for the replay runner).
#pragma once

#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include FZ_PACKAGE_HEADER

namespace fz {

namespace pkg = ::FZ_NS;

[[noreturn]] inline void fail(const char *file, int line, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

inline void fail(const char *file, int line, const char *fmt, ...) {
    std::fprintf(stderr, "FUZZ CHECK FAILED at %s:%d: ", file, line);
    va_list ap;
    va_start(ap, fmt);
    std::vfprintf(stderr, fmt, ap);
    va_end(ap);
    std::fputc('\n', stderr);
    std::fflush(stderr);
    std::abort();
}

inline std::string hex(const std::uint8_t *p, std::size_t n) {
    static const char digits[] = "0123456789abcdef";
    std::string s;
    for (std::size_t i = 0; i < n && i < 64; ++i) {
        s += digits[p[i] >> 4];
        s += digits[p[i] & 15];
    }
    if (n > 64) {
        s += "...";
    }
    return s;
}

// Chunk sizes of the chunked parse (the same plan as tests/fuzz/c/fuzz_common.h).
struct Chunks {
    unsigned state;
    unsigned max;
    explicit Chunks(std::uint8_t control) : state(control), max((control & 0x3fu) + 1u) {}
    std::size_t next() {
        state = (state * 73u + 41u) & 0xffu;
        return 1u + state % max;
    }
};

// The devices of the package, in enum order.
inline std::vector<pkg::Device> devices() {
    std::vector<pkg::Device> out;
    for (unsigned i = 0; i < 256; ++i) {
        const auto d = static_cast<pkg::Device>(i);
        if (pkg::device_name(d)[0] == '\0') {
            break;
        }
        out.push_back(d);
    }
    return out;
}

} // namespace fz

#define FZ_CHECK(cond, ...)                                                                                 \
    do {                                                                                                    \
        if (!(cond)) {                                                                                      \
            ::fz::fail(__FILE__, __LINE__, __VA_ARGS__);                                                    \
        }                                                                                                   \
    } while (0)
