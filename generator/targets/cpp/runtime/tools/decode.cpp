// protopkg-decode [--device ID] [--samples] [FILE|-]: a binary stream -> canonical JSON lines on stdout.
// Usage and I/O errors: one line on stderr, exit status 2 (a closed pipe on stdout: SIGPIPE, see
// tool_io.hpp). The input is read in blocks as it arrives and decoded in bounded memory
// (JsonLinesDecoder keeps only the bytes the parser has not decided on); when stdout is not a
// regular file, the lines of every block are flushed as soon as they are printed.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "protopkg/devices.hpp"
#include "protopkg/json_lines.hpp"
#include "tool_io.hpp"

namespace {

const char *const kProg = "protopkg-decode";
const char *const kUsage = "usage: protopkg-decode [--device ID] [--samples] [FILE|-]";

int usage_error(const std::string &message) {
    std::fprintf(stderr, "%s: %s (%s)\n", kProg, message.c_str(), kUsage);
    return 2;
}

int io_error(const std::string &message) {
    std::fprintf(stderr, "%s: %s\n", kProg, message.c_str());
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

/// Decodes `in` to stdout; returns the exit status.
int run(std::FILE *in, const std::string &name, const std::optional<protopkg::Device> &device, bool samples) {
    protopkg::tool_io::binary_stdio();
    static char out_buf[1 << 16];
    std::setvbuf(stdout, out_buf, _IOFBF, sizeof out_buf);
    const bool flush_blocks = !protopkg::tool_io::stdout_is_file();
    protopkg::tool_io::Output out;
    protopkg::JsonLinesDecoder decoder(device, samples);
    auto on_line = [&out](const std::string &line) {
        out.put(line);
        out.put("\n", 1);
    };
    std::vector<unsigned char> buf(1 << 16);
    for (;;) {
        const long n = protopkg::tool_io::read_some(in, buf.data(), buf.size());
        if (n < 0) {
            const int err = errno;
            out.flush();
            return out.failed() ? out.report(kProg) : protopkg::tool_io::read_error(kProg, name, err);
        }
        if (n == 0) {
            break;
        }
        decoder.feed(buf.data(), static_cast<std::size_t>(n), on_line);
        if (flush_blocks) {
            out.flush();
        }
        if (out.failed()) {
            return out.report(kProg);
        }
    }
    decoder.finish(on_line);
    out.flush();
    return out.failed() ? out.report(kProg) : 0;
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
    std::FILE *in = stdin;
    std::string name = "standard input";
    if (path != nullptr && std::strcmp(path, "-") != 0) {
        in = std::fopen(path, "rb");
        if (in == nullptr) {
            return io_error(std::string("cannot open '") + path + "': " + std::strerror(errno));
        }
        name = std::string("'") + path + "'";
    }
    const int status = run(in, name, device, samples);
    if (in != stdin) {
        std::fclose(in);
    }
    return status;
}
