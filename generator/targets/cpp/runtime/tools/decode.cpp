// protopkg-decode [--device ID] [--samples] [FILE|-]: a binary stream -> canonical JSON lines on stdout.
// Usage and I/O errors: one line on stderr, exit status 2.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "protopkg/devices.hpp"
#include "protopkg/json_lines.hpp"

namespace {

const char *const kUsage = "usage: protopkg-decode [--device ID] [--samples] [FILE|-]";

int usage_error(const std::string &message) {
    std::fprintf(stderr, "protopkg-decode: %s (%s)\n", message.c_str(), kUsage);
    return 2;
}

int io_error(const std::string &message) {
    std::fprintf(stderr, "protopkg-decode: %s\n", message.c_str());
    return 2;
}

/// The protocol's device ids, in spec order, for the unknown-device message.
std::string known_devices() {
    std::string out;
    for (const protopkg::Device d : protopkg::kDevices) {
        out += out.empty() ? "" : ", ";
        out += protopkg::device_name(d);
    }
    return out;
}

bool read_all(std::FILE *f, std::vector<std::uint8_t> &out) {
    std::uint8_t buf[65536];
    for (;;) {
        const std::size_t n = std::fread(buf, 1, sizeof buf, f);
        out.insert(out.end(), buf, buf + n);
        if (n < sizeof buf) {
            return std::ferror(f) == 0;
        }
    }
}

} // namespace

int main(int argc, char **argv) {
    std::optional<protopkg::Device> device;
    const char *path = nullptr;
    bool options_done = false;
    bool samples = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (!options_done && (arg == "-h" || arg == "--help")) {
            std::printf("%s\n", kUsage);
            return 0;
        }
        if (!options_done && (arg == "--device" || arg.compare(0, 9, "--device=") == 0)) {
            std::string id;
            if (arg == "--device") {
                if (i + 1 >= argc) {
                    return usage_error("--device needs a device id");
                }
                id = argv[++i];
            } else {
                id = arg.substr(9);
            }
            device = protopkg::device_from_name(id.c_str());
            if (!device) {
                return usage_error("unknown device '" + id + "' (known: " + known_devices() + ")");
            }
            continue;
        }
        if (!options_done && arg == "--samples") {
            samples = true;
            continue;
        }
        if (!options_done && arg == "--") {
            options_done = true;
            continue;
        }
        if (!options_done && arg.size() > 1 && arg[0] == '-') {
            return usage_error("unknown option '" + arg + "'");
        }
        if (path != nullptr) {
            return usage_error("more than one FILE");
        }
        path = argv[i];
    }
    std::vector<std::uint8_t> input;
    if (path == nullptr || std::strcmp(path, "-") == 0) {
        if (!read_all(stdin, input)) {
            return io_error("cannot read standard input");
        }
    } else {
        std::FILE *f = std::fopen(path, "rb");
        if (f == nullptr) {
            return io_error(std::string("cannot open '") + path + "': " + std::strerror(errno));
        }
        const bool ok = read_all(f, input);
        std::fclose(f);
        if (!ok) {
            return io_error(std::string("cannot read '") + path + "'");
        }
    }
    protopkg::decode_to_json_lines(
        input.data(), input.size(), 4096, device,
        [](const std::string &line) {
            std::fwrite(line.data(), 1, line.size(), stdout);
            std::fputc('\n', stdout);
        },
        samples);
    if (std::fflush(stdout) != 0) {
        std::fprintf(stderr, "protopkg-decode: cannot write standard output\n");
        return 2;
    }
    return 0;
}
