// protopkg-encode: JSON lines (as printed by protopkg-decode) on stdin -> bytes on stdout.
// A bad line is reported on stderr with its line number and nothing is written for it; the
// other lines are still encoded and the exit status is 1.
#include <cstdio>
#include <string>
#include <vector>

#include "protopkg/json_lines.hpp"

namespace {

bool read_line(std::FILE *f, std::string &line) {
    line.clear();
    int c;
    bool any = false;
    while ((c = std::fgetc(f)) != EOF) {
        any = true;
        if (c == '\n') {
            break;
        }
        line.push_back(static_cast<char>(c));
    }
    if (!line.empty() && line.back() == '\r') {
        line.pop_back();
    }
    return any;
}

bool blank(const std::string &line) {
    return line.find_first_not_of(" \t") == std::string::npos;
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
    std::string line;
    std::string error;
    std::vector<std::uint8_t> bytes;
    unsigned long number = 0;
    int status = 0;
    while (read_line(stdin, line)) {
        ++number;
        if (blank(line)) {
            continue;
        }
        bytes.clear();
        if (!protopkg::encode_json_line(line, bytes, error)) {
            std::fprintf(stderr, "protopkg-encode: line %lu: %s\n", number, error.c_str());
            status = 1;
            continue;
        }
        std::fwrite(bytes.data(), 1, bytes.size(), stdout);
    }
    if (std::ferror(stdin)) {
        std::fprintf(stderr, "protopkg-encode: cannot read standard input\n");
        return 2;
    }
    if (std::fflush(stdout) != 0) {
        std::fprintf(stderr, "protopkg-encode: cannot write standard output\n");
        return 2;
    }
    return status;
}
