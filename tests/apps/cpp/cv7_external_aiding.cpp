// cv7_external_aiding ADDRESS FEED [--period-ms N] [--samples N] [--deadline-s N]
//
// The CV7-INS navigation application with external aiding (tests/apps/README.md), written against
// the mipcodec C++ package the way a user writes it: the typed command API
// (mipcodec::api::<set>::<command>::<function>), a Connection over the POSIX transports, and a
// packet handler for the filter data (0x82).
//
// It configures the device (ping, idle, device information, default settings, gyro bias capture,
// the filter data message, the aiding frames and sources, filter initialization, filter reset,
// resume), then sends the aiding measurements of FEED every --period-ms while it reads, prints
// `mode N` whenever the filter mode changes and, in full navigation, one JSON line per filter
// packet until --samples were printed.
//
// Exit status: 0 done; 1 a command not acknowledged, the connection failed, FEED unreadable or the
// deadline passed (`error: ...` on stderr); 2 wrong arguments (`usage: ...` on stderr).
#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mipcodec/commands.hpp"
#include "mipcodec/mipcodec.hpp"
#include "mipcodec/session.hpp"
#include "mipcodec/transport_posix.hpp"

namespace api = mipcodec::api;
namespace types = mipcodec::types;
namespace fd = mipcodec::filter_data;

namespace {

constexpr const char *kUsage =
    "usage: cv7_external_aiding ADDRESS FEED [--period-ms N] [--samples N] [--deadline-s N]\n"
    "  ADDRESS  tcp:HOST:PORT or a serial device path (115200 baud)\n"
    "  FEED     aiding rows: tow ns lat lon height vn ve vd heading bx by bz ('#' comments)\n"
    "  --period-ms N   how often aiding is sent (default 500)\n"
    "  --samples N     full-navigation samples to print (default 30)\n"
    "  --deadline-s N  give up waiting for them after N seconds (default 60)\n";

constexpr std::uint8_t kFilterSet = 0x82;
constexpr std::uint16_t kGyroCaptureMs = 2000;
constexpr unsigned kOutputHz = 10; // filter data rate: decimation = base rate / 10

// Aiding frames (aiding frame configuration IDs).
constexpr std::uint8_t kHeadingFrame = 1;
constexpr std::uint8_t kGnssFrame = 2;
constexpr std::uint8_t kBodyVelocityFrame = 3;

struct Options {
    std::string address;
    std::string feed;
    long period_ms = 500;
    long samples = 30;
    long deadline_s = 60;
};

/// One row of the aiding feed: what the application's own sensors measured at one instant.
struct FeedRow {
    double tow = 0;       ///< GPS time of week [s]
    std::uint64_t ns = 0; ///< the same instant in the device's internal reference timebase [ns]
    double lat = 0, lon = 0, height = 0;
    std::array<float, 3> ned{};  ///< NED velocity [m/s]
    float heading = 0;           ///< true heading [rad]
    std::array<float, 3> body{}; ///< body-frame velocity [m/s]
};

int usage() {
    std::fputs(kUsage, stderr);
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

bool parse_args(int argc, char **argv, Options &opt) {
    std::vector<const char *> positional;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        long *value = nullptr;
        long max = 0;
        if (arg == "--period-ms") {
            value = &opt.period_ms;
            max = 3600000;
        } else if (arg == "--samples") {
            value = &opt.samples;
            max = 100000000;
        } else if (arg == "--deadline-s") {
            value = &opt.deadline_s;
            max = 86400 * 365;
        } else if (arg.size() > 1 && arg[0] == '-') {
            std::fprintf(stderr, "cv7_external_aiding: unknown option %s\n", argv[i]);
            return false;
        } else {
            positional.push_back(argv[i]);
            continue;
        }
        if (i + 1 >= argc || !parse_positive(argv[i + 1], max, *value)) {
            std::fprintf(stderr, "cv7_external_aiding: %s needs a whole number from 1 to %ld\n", argv[i],
                         max);
            return false;
        }
        ++i;
    }
    if (positional.size() != 2) {
        return false;
    }
    opt.address = positional[0];
    opt.feed = positional[1];
    return true;
}

/// Reads the feed (rows sorted by time of week); false with `why` when it cannot be read.
bool read_feed(const std::string &path, std::vector<FeedRow> &rows, std::string &why) {
    std::ifstream in(path);
    if (!in) {
        why = std::strerror(errno);
        return false;
    }
    std::string line;
    for (long number = 1; std::getline(in, line); ++number) {
        const char *p = line.c_str();
        while (*p == ' ' || *p == '\t' || *p == '\r') {
            ++p;
        }
        if (*p == '\0' || *p == '#') {
            continue;
        }
        double v[12] = {};
        std::uint64_t ns = 0;
        bool ok = true;
        for (int k = 0; k < 12 && ok; ++k) {
            char *end = nullptr;
            errno = 0;
            if (k == 1) { // nanoseconds: an unsigned whole number
                while (*p == ' ' || *p == '\t') {
                    ++p;
                }
                const unsigned long long n = *p >= '0' && *p <= '9' ? std::strtoull(p, &end, 10) : 0;
                ok = end != nullptr && end != p && errno == 0;
                ns = n;
            } else {
                v[k] = std::strtod(p, &end);
                ok = end != p && errno == 0 && std::isfinite(v[k]);
            }
            ok = ok && (*end == ' ' || *end == '\t' || *end == '\r' || *end == '\0');
            p = end;
        }
        while (ok && (*p == ' ' || *p == '\t' || *p == '\r')) {
            ++p;
        }
        if (!ok || *p != '\0') {
            why = "line " + std::to_string(number) +
                  ": expected 12 numbers: tow ns lat lon height vn ve vd heading bx by bz";
            return false;
        }
        FeedRow r;
        r.tow = v[0];
        r.ns = ns;
        r.lat = v[2];
        r.lon = v[3];
        r.height = v[4];
        r.ned = {static_cast<float>(v[5]), static_cast<float>(v[6]), static_cast<float>(v[7])};
        r.heading = static_cast<float>(v[8]);
        r.body = {static_cast<float>(v[9]), static_cast<float>(v[10]), static_cast<float>(v[11])};
        rows.push_back(r);
    }
    if (in.bad()) {
        why = std::strerror(errno);
        return false;
    }
    if (rows.empty()) {
        why = "no rows";
        return false;
    }
    std::stable_sort(rows.begin(), rows.end(),
                     [](const FeedRow &a, const FeedRow &b) { return a.tow < b.tow; });
    return true;
}

/// The feed row nearest time of week `tow`.
const FeedRow &nearest(const std::vector<FeedRow> &rows, double tow) {
    auto it =
        std::lower_bound(rows.begin(), rows.end(), tow, [](const FeedRow &r, double t) { return r.tow < t; });
    if (it == rows.end()) {
        return rows.back();
    }
    if (it != rows.begin() && tow - std::prev(it)->tow <= it->tow - tow) {
        return *std::prev(it);
    }
    return *it;
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

/// The navigation state read from the filter data (0x82) packets, and the output lines.
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
        if (time) {
            tow_ = time->tow;
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
    /// The latest GPS time of week (0x82,0x11), when one came.
    const std::optional<double> &tow() const {
        return tow_;
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
    std::optional<double> tow_;
    std::optional<unsigned> mode_;
};

/// The configuration flow of the CV7-INS with external aiding, in the order of the manuals.
int configure(mipcodec::Connection &device) {
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
    call = api::threedm::device_startup_settings::default_(device); // load the default settings
    if (!call.ok()) {
        return failed("threedm.device_startup_settings default", call);
    }
    // A long command: the device replies after the capture. The command's spec timeout adds the
    // averaging time to the session's reply timeout, so this call waits long enough.
    const auto bias = api::threedm::capture_gyro_bias::call(device, kGyroCaptureMs);
    if (!bias.value) {
        return failed("threedm.capture_gyro_bias", bias.call);
    }
    const auto base = api::threedm::get_base_rate::call(device, kFilterSet);
    if (!base.value) {
        return failed("threedm.get_base_rate", base.call);
    }
    if (base.value->rate == 0) {
        return error("threedm.get_base_rate", "the filter data base rate is 0 (variable)");
    }
    const auto decimation = static_cast<std::uint16_t>(std::max<unsigned>(1, base.value->rate / kOutputHz));
    decltype(mipcodec::threedm::MessageFormat::descriptors)::value_type format;
    for (const std::uint8_t d :
         {fd::GpsTimestamp::kDescriptor, fd::FilterStatusCv7Ins::kDescriptor, fd::LlhPosition::kDescriptor,
          fd::NedVelocity::kDescriptor, fd::EulerAngles::kDescriptor}) {
        format.push_back(types::DescriptorRate{d, decimation});
    }
    call = api::threedm::message_format::write(device, kFilterSet, format);
    if (!call.ok()) {
        return failed("threedm.message_format write", call);
    }
    // The heading sensor, the GNSS antenna and the body-frame velocity sensor: at the vehicle
    // origin, aligned with it.
    for (const std::uint8_t frame : {kHeadingFrame, kGnssFrame, kBodyVelocityFrame}) {
        types::AidingFrameRotation rotation;
        rotation.value = types::AidingFrameEuler{{0.0f, 0.0f, 0.0f}};
        call = api::aiding::frame_config::write(device, frame, types::AidingFrameFormat::euler, false,
                                                {0.0f, 0.0f, 0.0f}, rotation);
        if (!call.ok()) {
            return failed("aiding.frame_config write", call);
        }
    }
    for (const auto source :
         {types::AidingMeasurementSource::gnss_pos_vel, types::AidingMeasurementSource::external_heading}) {
        call = api::filter::aiding_measurement_control::write(device, source, true);
        if (!call.ok()) {
            return failed("filter.aiding_measurement_control write", call);
        }
    }
    types::HeadingAlignmentMethods alignment;
    alignment.set_external(true); // heading alignment by external heading (0x08)
    // The reference frame of the (unused, automatic) initial position and velocity: LLH, value 2
    // in the manual's Reference Frame Selector table.
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

/// Sends the aiding measurements of one feed row: heading, position and velocity stamped with the
/// row's time in the internal reference timebase, body-frame velocity with its time of arrival.
int send_aiding(mipcodec::Connection &device, const FeedRow &row) {
    const types::AidingTime measured{types::AidingTimebase::internal_reference, 0, row.ns};
    const types::AidingTime arrival{types::AidingTimebase::time_of_arrival, 0, 0};
    const types::AidingVectorValidFlags xyz(7);
    mipcodec::Call call =
        api::aiding::true_heading::call(device, measured, kHeadingFrame, row.heading, 0.01f, 1);
    if (!call.ok()) {
        return failed("aiding.true_heading", call);
    }
    call = api::aiding::llh_position::call(device, measured, kGnssFrame, row.lat, row.lon, row.height,
                                           {1.0f, 1.0f, 1.0f}, types::AidingLlhValidFlags(7));
    if (!call.ok()) {
        return failed("aiding.llh_position", call);
    }
    call = api::aiding::ned_velocity::call(device, measured, kGnssFrame, row.ned, {0.1f, 0.1f, 0.1f}, xyz);
    if (!call.ok()) {
        return failed("aiding.ned_velocity", call);
    }
    call = api::aiding::body_frame_velocity::call(device, arrival, kBodyVelocityFrame, row.body,
                                                  {0.1f, 0.1f, 0.1f}, xyz);
    if (!call.ok()) {
        return failed("aiding.body_frame_velocity", call);
    }
    return 0;
}

/// Aids the filter every period while reading, until the samples were printed or the deadline.
int navigate(mipcodec::Connection &device, Navigation &nav, const std::vector<FeedRow> &feed,
             const Options &opt) {
    const std::int64_t deadline = device.now_ms() + opt.deadline_s * 1000;
    std::int64_t next_aiding = device.now_ms();
    while (!nav.done()) {
        const std::int64_t now = device.now_ms();
        if (now >= deadline) {
            char why[160];
            std::snprintf(why, sizeof why, "%ld of %ld full-navigation samples in %ld s (filter mode %s)",
                          nav.printed(), opt.samples, opt.deadline_s,
                          nav.mode() ? std::to_string(*nav.mode()).c_str() : "unknown");
            return error("deadline passed", why);
        }
        if (now >= next_aiding) {
            next_aiding = now + opt.period_ms;
            if (nav.tow()) {
                if (const int status = send_aiding(device, nearest(feed, *nav.tow())); status != 0) {
                    return status;
                }
            }
            continue;
        }
        mipcodec::ErrorText io;
        if (!device.listen(std::min(next_aiding, deadline) - now, &io)) {
            return error("connection", io.c_str());
        }
    }
    return 0;
}

} // namespace

int main(int argc, char **argv) {
    Options opt;
    if (argc == 2 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
        std::fputs(kUsage, stdout);
        return 0;
    }
    if (!parse_args(argc, argv, opt)) {
        return usage();
    }
    std::vector<FeedRow> feed;
    std::string why;
    if (!read_feed(opt.feed, feed, why)) {
        return error(opt.feed.c_str(), why.c_str());
    }
    std::unique_ptr<mipcodec::Transport> transport = mipcodec::open_transport(opt.address, 115200, why);
    if (!transport) {
        return error("connection", why.c_str());
    }
    mipcodec::Session<1>::Options options;
    options.device = mipcodec::Device::cv7_ins; // what the CV7-INS does not support is refused unsent
    mipcodec::Connection device(*transport, options);
    // Every packet that is not a reply reaches the handler, also while a command waits.
    Navigation nav(opt.samples);
    device.session().on_packet(
        [&nav](const mipcodec::PacketView &packet, std::uint64_t) { nav.on_packet(packet); });
    int status = configure(device);
    if (status == 0) {
        status = navigate(device, nav, feed, opt);
    }
    device.close();
    return status;
}
