// protopkg-decode [--device ID] [--samples] [--decoder general|straight|cached] [FILE|-]: a binary stream
// -> canonical JSON lines on stdout. --decoder straight or cached decodes the data packets with
// decode_packet or LayoutCache (packets.hpp, issue 38) and writes their typed members with the same
// writer (the same lines: the conformance corpus checks those decoders with it); a packet whose
// decoded fields and passed-on entries do not make up its entries ends the tool with exit status 1.
// Usage and I/O errors: one line on stderr, exit status 2 (a closed pipe on stdout: SIGPIPE, see
// tool_io.hpp). The input is read in blocks as it arrives and decoded in bounded memory
// (JsonLinesDecoder keeps only the bytes the parser has not decided on); when stdout is not a
// regular file, the lines of every block are flushed as soon as they are printed.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "protopkg/devices.hpp"
#include "protopkg/json_lines.hpp"
#include "protopkg/packets.hpp"
#include "tool_io.hpp"

namespace {

const char *const kProg = "protopkg-decode";
const char *const kUsage =
    "usage: protopkg-decode [--device ID] [--samples] [--decoder general|straight|cached] [FILE|-]";

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

enum class Decoder { general, straight, cached };

/// The lines of JsonLinesDecoder with the data packets decoded by decode_packet (straight) or a
/// LayoutCache (cached): each decoded field written from its typed member by the writer of
/// write_field_entry_json, every entry the decoder passed on by write_field_entry_json itself.
class TypedJsonLines {
  public:
    TypedJsonLines(const std::optional<protopkg::Device> &device, bool samples, bool cached)
        : device_(device), samples_(samples), cached_(cached) {}

    template <class OnLine> void feed(const std::uint8_t *data, std::size_t size, OnLine &&on_line) {
        hist_.insert(hist_.end(), data, data + size);
        parser_.feed(data, size, [&](const protopkg::StreamEvent &e) { on_event(e, on_line); });
        trim();
    }
    template <class OnLine> void finish(OnLine &&on_line) {
        parser_.flush([&](const protopkg::StreamEvent &e) { on_event(e, on_line); });
        trim();
    }
    /// Stream offset + 1 of the first packet the decoder did not cover, 0 if none.
    std::uint64_t mismatch() const {
        return mismatch_;
    }

  private:
    template <class OnLine> void on_event(const protopkg::StreamEvent &e, OnLine &on_line) {
        if (mismatch_ != 0) {
            return;
        }
        line_.clear();
        protopkg::JsonWriter w(protopkg::string_sink, &line_);
        if (e.kind == protopkg::StreamEvent::Kind::packet) {
            if (!write_packet(w, e.offset, e.packet)) {
                mismatch_ = e.offset + 1;
                return;
            }
            const std::optional<protopkg::SamplePlace> place =
                samples_ ? tracker_.feed(e.packet) : std::nullopt;
            const std::size_t at = line_.find(",\"fields\":");
            if (place && at != std::string::npos) {
                line_.insert(at, ",\"sample\":" + std::to_string(place->number));
            }
        } else if (e.kind == protopkg::StreamEvent::Kind::skip) {
            protopkg::write_skip_json(w, e.offset, hist_.data() + (e.offset - hist_base_),
                                      static_cast<std::size_t>(e.count));
        } else {
            protopkg::write_foreign_json(w, e);
        }
        on_line(static_cast<const std::string &>(line_));
    }

    /// write_packet_json from the decoder's result; false when the decoded fields and the
    /// entries passed on do not make up the packet's entries in order.
    bool write_packet(protopkg::JsonWriter &w, std::uint64_t offset, const protopkg::PacketView &packet) {
        others_.clear();
        auto keep = [this](const protopkg::FieldEntry &e) { others_.push_back(e); };
        const protopkg::PacketIndex *index =
            cached_ ? cache_.decode(packet, *any_, keep) : protopkg::decode_packet(packet, *any_, keep);
        typed_.clear();
        any_->visit([this](const auto &value) {
            using T = std::decay_t<decltype(value)>;
            typed_.emplace_back(T::kDescriptor, [&value](protopkg::JsonWriter &out) {
                protopkg::detail::FieldJsonVisitor{out, T::kDescriptor, nullptr, 0}.field(value);
            });
        });
        if (index == nullptr ? !typed_.empty() : typed_.size() != index->count) {
            return false;
        }
        protopkg::write_packet_head(w, offset, packet.set());
        // The entries in packet order (the walk only places them): each is the next entry passed
        // on when it starts where that one does, else the next decoded field, of its descriptor.
        protopkg::FieldIterator it(packet);
        protopkg::FieldEntry e;
        std::size_t passed = 0;
        std::size_t decoded = 0;
        while (it.next(e)) {
            if (passed < others_.size() && others_[passed].payload_offset == e.payload_offset &&
                others_[passed].kind == e.kind) {
                protopkg::write_field_entry_json(w, packet.set(), others_[passed++], device_);
            } else if (e.kind == protopkg::FieldEntry::Kind::field && decoded < typed_.size() &&
                       typed_[decoded].first == e.descriptor) {
                typed_[decoded++].second(w);
            } else {
                return false;
            }
        }
        w.end_array();
        w.end_object();
        return passed == others_.size() && decoded == typed_.size();
    }

    void trim() {
        const std::uint64_t keep = parser_.retain_from();
        const auto drop = static_cast<std::size_t>(keep - hist_base_);
        if (drop > 0) {
            hist_.erase(hist_.begin(), hist_.begin() + static_cast<std::ptrdiff_t>(drop));
            hist_base_ = keep;
        }
    }

    std::optional<protopkg::Device> device_;
    bool samples_;
    bool cached_;
    protopkg::StreamParser parser_;
    protopkg::SampleTracker tracker_;
    std::vector<std::uint8_t> hist_; ///< input from stream offset hist_base_ on
    std::uint64_t hist_base_ = 0;
    std::string line_;
    std::uint64_t mismatch_ = 0;
    std::unique_ptr<protopkg::AnyPacket> any_ = std::make_unique<protopkg::AnyPacket>(); // large
    protopkg::LayoutCache cache_;
    std::vector<protopkg::FieldEntry> others_;
    std::vector<std::pair<std::uint8_t, std::function<void(protopkg::JsonWriter &)>>> typed_;
};

/// The mismatch of a TypedJsonLines (none for JsonLinesDecoder).
std::uint64_t mismatch_of(const protopkg::JsonLinesDecoder &) {
    return 0;
}
std::uint64_t mismatch_of(const TypedJsonLines &d) {
    return d.mismatch();
}

/// Decodes `in` to stdout with `decoder`; returns the exit status.
template <class LinesDecoder>
int run_with(std::FILE *in, const std::string &name, LinesDecoder &decoder, const char *decoder_name) {
    protopkg::tool_io::binary_stdio();
    static char out_buf[1 << 16];
    std::setvbuf(stdout, out_buf, _IOFBF, sizeof out_buf);
    const bool flush_blocks = !protopkg::tool_io::stdout_is_file();
    protopkg::tool_io::Output out;
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
        if (mismatch_of(decoder) != 0) {
            break;
        }
        if (flush_blocks) {
            out.flush();
        }
        if (out.failed()) {
            return out.report(kProg);
        }
    }
    if (mismatch_of(decoder) == 0) {
        decoder.finish(on_line);
    }
    out.flush();
    if (out.failed()) {
        return out.report(kProg);
    }
    if (const std::uint64_t at = mismatch_of(decoder)) {
        std::fprintf(
            stderr,
            "%s: the %s decoder's fields and passed-on entries of the packet at offset %llu do not make up "
            "its entries\n",
            kProg, decoder_name, static_cast<unsigned long long>(at - 1));
        return 1;
    }
    return 0;
}

/// Decodes `in` to stdout; returns the exit status.
int run(std::FILE *in, const std::string &name, const std::optional<protopkg::Device> &device, bool samples,
        Decoder which) {
    if (which == Decoder::general) {
        protopkg::JsonLinesDecoder decoder(device, samples);
        return run_with(in, name, decoder, "general");
    }
    TypedJsonLines decoder(device, samples, which == Decoder::cached);
    return run_with(in, name, decoder, which == Decoder::cached ? "cached" : "straight");
}

} // namespace

int main(int argc, char **argv) {
    std::optional<protopkg::Device> device;
    const char *path = nullptr;
    bool options_done = false;
    bool samples = false;
    Decoder which = Decoder::general;
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
        if (!options_done && (arg == "--decoder" || arg.compare(0, 10, "--decoder=") == 0)) {
            std::string d;
            if (arg == "--decoder") {
                if (i + 1 >= argc) {
                    return usage_error("--decoder needs general, straight or cached");
                }
                d = argv[++i];
            } else {
                d = arg.substr(10);
            }
            if (d == "general") {
                which = Decoder::general;
            } else if (d == "straight") {
                which = Decoder::straight;
            } else if (d == "cached") {
                which = Decoder::cached;
            } else {
                return usage_error("unknown decoder '" + d + "' (expected general, straight or cached)");
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
    const int status = run(in, name, device, samples, which);
    if (in != stdin) {
        std::fclose(in);
    }
    return status;
}
