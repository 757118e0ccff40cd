// protopkg-encode: JSON lines (as printed by protopkg-decode) on stdin -> bytes on stdout.
// A bad line is reported on stderr with its line number and nothing is written for it; the
// other lines are still encoded and the exit status is 1. Input is read in blocks and encoded
// line by line; I/O faults as in tool_io.hpp (one line on stderr, exit 2; a closed pipe: SIGPIPE).
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "protopkg/json_lines.hpp"
#include "tool_io.hpp"

namespace {

const char *const kProg = "protopkg-encode";

/// RFC 8259 whitespace only: a line of nothing else is blank.
bool blank(const std::string &line) {
    return line.find_first_not_of(" \t\r\n") == std::string::npos;
}

} // namespace

int main(int argc, char **argv) {
    if (argc > 1) {
        const std::string arg = argv[1];
        if (arg == "-h" || arg == "--help") {
            std::printf("usage: protopkg-encode < lines.jsonl > stream.bin\n");
            return 0;
        }
        std::fprintf(
            stderr,
            "protopkg-encode: unexpected argument '%s' (usage: protopkg-encode < lines.jsonl > stream.bin)\n",
            argv[1]);
        return 2;
    }
    protopkg::tool_io::binary_stdio();
    static char out_buf[1 << 16];
    std::setvbuf(stdout, out_buf, _IOFBF, sizeof out_buf);
    const bool flush_blocks = !protopkg::tool_io::stdout_is_file();
    protopkg::tool_io::Output out;
    std::string line;
    std::string error;
    std::vector<std::uint8_t> bytes;
    std::vector<unsigned char> buf(1 << 16);
    unsigned long number = 0;
    int status = 0;
    auto encode_one = [&]() {
        ++number;
        if (blank(line)) {
            return;
        }
        bytes.clear();
        if (!protopkg::encode_json_line(line, bytes, error)) {
            std::fprintf(stderr, "protopkg-encode: line %lu: %s\n", number, error.c_str());
            status = 1;
            return;
        }
        out.put(bytes.data(), bytes.size());
    };
    for (;;) {
        const long n = protopkg::tool_io::read_some(stdin, buf.data(), buf.size());
        if (n < 0) {
            const int err = errno;
            out.flush();
            return out.failed() ? out.report(kProg)
                                : protopkg::tool_io::read_error(kProg, "standard input", err);
        }
        if (n == 0) {
            break;
        }
        const char *p = reinterpret_cast<const char *>(buf.data());
        const char *end = p + n;
        while (p < end) {
            const char *nl =
                static_cast<const char *>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
            line.append(p, nl != nullptr ? nl : end);
            if (nl == nullptr) {
                break;
            }
            p = nl + 1;
            encode_one();
            line.clear();
        }
        if (flush_blocks) {
            out.flush();
        }
        if (out.failed()) {
            return out.report(kProg);
        }
    }
    if (!line.empty()) {
        encode_one();
    }
    out.flush();
    return out.failed() ? out.report(kProg) : status;
}
