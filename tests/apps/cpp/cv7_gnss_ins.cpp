// cv7_gnss_ins ADDRESS [--antennas 1|2] [--samples N] [--deadline-s N]
//
// The 3DM-CV7-GNSS/INS navigating on its internal GNSS receivers (3dm-cv7-ins-docs.txt: the
// getting-started and Filter pages; tests/apps/README.md), written against the mipcodec C++ package
// the way a user writes it: the typed command API (mipcodec::api::<set>::<command>::<function>), a
// Connection over the POSIX transports, and a packet handler for the filter data (0x82).
//
// It configures the device (ping, idle, device information, the filter data base rate, the filter
// message: GPS timestamp, filter status, LLH position, NED velocity, Euler angles at 10 Hz; the
// antenna offsets of receiver 1 (and 2); the aiding sources: GNSS position and velocity, and GNSS
// heading with two antennas or the magnetometer with one; the filter initialization: automatic
// position, velocity and attitude, heading from the dual antenna or the magnetometer; a filter
// reset, resume). Then it reads the data: `model ...`, `serial ...`, `firmware N`; `mode N`
// whenever the filter mode changes; once in full navigation, one JSON line per full-navigation
// filter packet until --samples were printed.
//
// Exit status: 0 done; 1 a command not acknowledged, the connection failed or the deadline passed
// (`error: ...` on stderr); 2 wrong arguments (`usage: ...` on stderr).
#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mipcodec/commands.hpp"
#include "mipcodec/mipcodec.hpp"
#include "mipcodec/session.hpp"
#include "mipcodec/transport_posix.hpp"

namespace api = mipcodec::api;
namespace types = mipcodec::types;
namespace fd = mipcodec::filter_data;

namespace {

constexpr const char *kUsageLine =
    "usage: cv7_gnss_ins ADDRESS [--antennas 1|2] [--samples N] [--deadline-s N]\n";
constexpr const char *kUsageHelp =
    "  ADDRESS  tcp:HOST:PORT or a serial device path (115200 baud)\n"
    "  --antennas N    GNSS antennas: 1 (heading from the magnetometer) or 2 (dual antenna; default 1)\n"
    "  --samples N     full-navigation samples to print (default 20)\n"
    "  --deadline-s N  give up waiting for them after N seconds (default 60)\n";

constexpr std::uint8_t kFilterSet = 0x82;
constexpr unsigned kFilterHz = 10;          // filter data rate: decimation = filter base rate / 10
constexpr std::int64_t kListenSliceMs = 20; // how long one listen() receives

struct Options {
    std::string address;
    long antennas = 1; ///< GNSS antennas: 1 or 2
    long samples = 20;
    long deadline_s = 60;
};

/// Wrong arguments: `usage: WHY`, then the usage line; exit status 2.
int usage(const std::string &why) {
    if (!why.empty()) {
        std::fprintf(stderr, "usage: %s\n", why.c_str());
    }
    std::fputs(kUsageLine, stderr);
    std::fputs(kUsageHelp, stderr);
    return 2;
}

int error(const char *what, const char *why) {
    std::fprintf(stderr, "error: %s: %s\n", what, why);
    return 1;
}

int failed(const char *command, const mipcodec::Call &call) {
    return error(command, call.describe().c_str());
}

/// A whole positive decimal number (at most `max`).
bool parse_positive(const char *text, long max, long &out) {
    if (text[0] < '0' || text[0] > '9') {
        return false;
    }
    char *end = nullptr;
    errno = 0;
    const long n = std::strtol(text, &end, 10);
    if (errno != 0 || *end != '\0' || n < 1 || n > max) {
        return false;
    }
    out = n;
    return true;
}

/// Nothing when the arguments are fine, else why not (empty: no argument).
std::optional<std::string> parse_args(int argc, char **argv, Options &opt) {
    std::vector<const char *> positional;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        long *value = nullptr;
        long max = 0;
        if (arg == "--antennas") {
            value = &opt.antennas;
            max = 2;
        } else if (arg == "--samples") {
            value = &opt.samples;
            max = 100000000;
        } else if (arg == "--deadline-s") {
            value = &opt.deadline_s;
            max = 86400 * 365;
        } else if (arg.size() > 1 && arg[0] == '-') {
            return "unknown option " + arg;
        } else {
            positional.push_back(argv[i]);
            continue;
        }
        if (i + 1 >= argc) {
            return arg + " needs a value";
        }
        if (!parse_positive(argv[i + 1], max, *value)) {
            return arg + " " + argv[i + 1] + ": not a number from 1 to " + std::to_string(max);
        }
        ++i;
    }
    if (positional.size() != 1) {
        return positional.empty() ? "" : std::string("unexpected argument ") + positional[1];
    }
    opt.address = positional[0];
    return std::nullopt;
}

/// A number as JSON that reads back to the same double (null when not finite).
void put_number(std::string &out, double v) {
    char buf[32];
    if (std::isfinite(v)) {
        std::snprintf(buf, sizeof buf, "%.17g", v);
    } else {
        std::snprintf(buf, sizeof buf, "null");
    }
    out += buf;
}

/// A device information string without its padding (spaces, NULs).
std::string unpadded(const std::array<char, 16> &text) {
    std::string s(text.begin(), text.end());
    while (!s.empty() && (s.back() == ' ' || s.back() == '\0')) {
        s.pop_back();
    }
    return s;
}

/// The filter data read from the packets (0x82), and the output lines.
class Navigation {
  public:
    explicit Navigation(long samples) : wanted_(samples) {}

    /// Routes one packet that is not a reply: decodes the filter fields of a 0x82 packet.
    void on_packet(const mipcodec::PacketView &packet) {
        if (packet.set() != kFilterSet) {
            return;
        }
        std::optional<fd::GpsTimestamp> time;
        std::optional<fd::FilterStatusCv7Ins> status;
        std::optional<fd::LlhPosition> llh;
        std::optional<fd::NedVelocity> vel;
        std::optional<fd::EulerAngles> euler;
        mipcodec::FieldIterator fields(packet);
        mipcodec::FieldEntry e;
        while (fields.next(e)) {
            if (e.kind != mipcodec::FieldEntry::Kind::field) {
                break;
            }
            switch (e.descriptor) {
            case fd::GpsTimestamp::kDescriptor:
                decode_into(e, time);
                break;
            case fd::FilterStatusCv7Ins::kDescriptor:
                decode_into(e, status);
                break;
            case fd::LlhPosition::kDescriptor:
                decode_into(e, llh);
                break;
            case fd::NedVelocity::kDescriptor:
                decode_into(e, vel);
                break;
            case fd::EulerAngles::kDescriptor:
                decode_into(e, euler);
                break;
            default:
                break;
            }
        }
        if (!status) {
            return;
        }
        const auto mode = static_cast<unsigned>(status->filter_state);
        if (!mode_ || *mode_ != mode) {
            mode_ = mode;
            std::printf("mode %u\n", mode);
            std::fflush(stdout);
        }
        if (status->filter_state != types::FilterModeCv7::full_nav || printed_ >= wanted_ || !time || !llh ||
            !vel || !euler) {
            return;
        }
        std::string line = "{\"tow\":";
        put_number(line, time->tow);
        line += ",\"lat\":";
        put_number(line, llh->latitude);
        line += ",\"lon\":";
        put_number(line, llh->longitude);
        line += ",\"height\":";
        put_number(line, llh->ellipsoid_height);
        line += ",\"vel\":[";
        put_number(line, vel->north);
        line += ",";
        put_number(line, vel->east);
        line += ",";
        put_number(line, vel->down);
        line += "],\"euler\":[";
        put_number(line, euler->roll);
        line += ",";
        put_number(line, euler->pitch);
        line += ",";
        put_number(line, euler->yaw);
        line += "],\"llh_valid\":" + std::to_string(llh->valid_flags.raw());
        line += ",\"euler_valid\":" + std::to_string(euler->valid_flags.raw()) + "}";
        std::printf("%s\n", line.c_str());
        std::fflush(stdout);
        ++printed_;
    }

    bool done() const {
        return printed_ >= wanted_;
    }
    long printed() const {
        return printed_;
    }
    const std::optional<unsigned> &mode() const {
        return mode_;
    }

  private:
    template <class T> static void decode_into(const mipcodec::FieldEntry &e, std::optional<T> &out) {
        T value{};
        mipcodec::DecodeError err;
        if (mipcodec::decode(e.data, e.size, value, err)) {
            out = value;
        }
    }

    long wanted_;
    long printed_ = 0;
    std::optional<unsigned> mode_;
};

/// The decimation giving `hz` out of `base_hz`; nullopt when none does.
std::optional<std::uint16_t> decimation(unsigned base_hz, unsigned hz) {
    if (base_hz < hz || base_hz % hz != 0 || base_hz / hz > 0xFFFF) {
        return std::nullopt;
    }
    return static_cast<std::uint16_t>(base_hz / hz);
}

/// The configuration flow, in the order of the README.
int configure(mipcodec::Connection &device, long antennas) {
    mipcodec::Call call = api::base::ping::call(device);
    if (!call.ok()) {
        return failed("base.ping", call);
    }
    call = api::base::set_to_idle::call(device);
    if (!call.ok()) {
        return failed("base.set_to_idle", call);
    }
    const auto info = api::base::get_device_info::call(device);
    if (!info.value) {
        return failed("base.get_device_info", info.call);
    }
    std::printf("model %s\nserial %s\nfirmware %u\n", unpadded(info.value->info.model_name).c_str(),
                unpadded(info.value->info.serial_number).c_str(),
                static_cast<unsigned>(info.value->info.firmware_version));
    std::fflush(stdout);
    const auto base = api::threedm::get_base_rate::call(device, kFilterSet);
    if (!base.value) {
        return failed("threedm.get_base_rate", base.call);
    }
    const auto filter_decimation = decimation(base.value->rate, kFilterHz);
    if (!filter_decimation) {
        return error("threedm.get_base_rate",
                     ("no decimation of " + std::to_string(base.value->rate) + " Hz gives 10 Hz").c_str());
    }
    decltype(mipcodec::threedm::MessageFormat::descriptors)::value_type format;
    for (const std::uint8_t d :
         {fd::GpsTimestamp::kDescriptor, fd::FilterStatusCv7Ins::kDescriptor, fd::LlhPosition::kDescriptor,
          fd::NedVelocity::kDescriptor, fd::EulerAngles::kDescriptor}) {
        format.push_back(types::DescriptorRate{d, *filter_decimation});
    }
    call = api::threedm::message_format::write(device, kFilterSet, format);
    if (!call.ok()) {
        return failed("threedm.message_format write", call);
    }
    // The antennas of receivers 1 and 2 in the vehicle frame (x forward, y right, z down) [m]:
    // 0.5 m left and right of the device, 0.2 m above it.
    const std::array<std::array<float, 3>, 2> antenna_offsets{{{0.0f, -0.5f, -0.2f}, {0.0f, 0.5f, -0.2f}}};
    for (long receiver = 1; receiver <= antennas; ++receiver) {
        call =
            api::filter::multi_antenna_offset::write(device, static_cast<std::uint8_t>(receiver),
                                                     antenna_offsets[static_cast<std::size_t>(receiver - 1)]);
        if (!call.ok()) {
            return failed("filter.multi_antenna_offset write", call);
        }
    }
    const bool dual = antennas == 2;
    const std::array<std::pair<types::AidingMeasurementSource, bool>, 3> sources{{
        {types::AidingMeasurementSource::gnss_pos_vel, true},
        {types::AidingMeasurementSource::gnss_heading, dual},
        {types::AidingMeasurementSource::magnetometer, !dual},
    }};
    for (const auto &[source, enable] : sources) {
        call = api::filter::aiding_measurement_control::write(device, source, enable);
        if (!call.ok()) {
            return failed("filter.aiding_measurement_control write", call);
        }
    }
    types::HeadingAlignmentMethods alignment;
    if (dual) {
        alignment.set_dual_antenna(true); // the initial heading from the dual antenna (0x01)
    } else {
        alignment.set_magnetometer(true); // the initial heading from the magnetometer (0x04)
    }
    // No wait for the run command, automatic position, velocity and attitude, reference frame LLH
    // (value 2 in the manual's Reference Frame Selector table), zeros elsewhere.
    call = api::filter::initialization_configuration::write(
        device, 0, types::FilterInitialConditionSource::auto_pos_vel_att, alignment, 0.0f, 0.0f, 0.0f,
        {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, types::FilterReferenceFrame::llh);
    if (!call.ok()) {
        return failed("filter.initialization_configuration write", call);
    }
    call = api::filter::reset_filter::call(device);
    if (!call.ok()) {
        return failed("filter.reset_filter", call);
    }
    call = api::base::resume::call(device);
    if (!call.ok()) {
        return failed("base.resume", call);
    }
    return 0;
}

/// Reads the filter data until the samples were printed or the deadline passed.
int read_data(mipcodec::Connection &device, Navigation &nav, const Options &opt, std::int64_t deadline) {
    while (!nav.done()) {
        const std::int64_t now = device.now_ms();
        if (now >= deadline) {
            char why[200];
            std::snprintf(why, sizeof why, "%ld of %ld full-navigation samples in %ld s (filter mode %s)",
                          nav.printed(), opt.samples, opt.deadline_s,
                          nav.mode() ? std::to_string(*nav.mode()).c_str() : "unknown");
            return error("deadline passed", why);
        }
        mipcodec::ErrorText io;
        // listen() receives for the whole duration: a short slice, then the samples are counted.
        if (!device.listen(std::min(kListenSliceMs, deadline - now), &io)) {
            return error("connection", io.c_str());
        }
    }
    return 0;
}

} // namespace

int main(int argc, char **argv) {
    Options opt;
    if (argc == 2 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
        std::fputs(kUsageLine, stdout);
        std::fputs(kUsageHelp, stdout);
        return 0;
    }
    if (const auto why = parse_args(argc, argv, opt)) {
        return usage(*why);
    }
    std::string why;
    std::unique_ptr<mipcodec::Transport> transport = mipcodec::open_transport(opt.address, 115200, why);
    if (!transport) {
        return error("connection", why.c_str());
    }
    mipcodec::Session<1>::Options options;
    options.device = mipcodec::Device::cv7_ins; // what the CV7-INS does not support is refused unsent
    mipcodec::Connection device(*transport, options);
    const std::int64_t deadline = device.now_ms() + opt.deadline_s * 1000; // counted from the start
    Navigation nav(opt.samples);
    int status = configure(device, opt.antennas);
    if (status == 0) {
        // Every packet that is not a reply reaches the handler from here on.
        device.session().on_packet(
            [&nav](const mipcodec::PacketView &packet, std::uint64_t) { nav.on_packet(packet); });
        status = read_data(device, nav, opt, deadline);
    }
    device.close();
    return status;
}
