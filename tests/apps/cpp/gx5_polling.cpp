// gx5_polling ADDRESS [--samples N] [--deadline-s N]
//
// The 3DM-GX5-45 polling flow (3dm-gx5-45-dcp.txt section 2.4 and the Poll IMU Data / Poll
// Estimation Filter Data commands; tests/apps/README.md), written against the mipcodec C++ package
// the way a user writes it: the typed command API (mipcodec::api::<set>::<command>::<function>), a
// Connection over the POSIX transports, and a packet handler for the polled IMU (0x80) and filter
// (0x82) data.
//
// It configures the device (ping, idle, the IMU and filter data base rates, the IMU message
// format: scaled accelerometer and gyro, the filter message format: GPS timestamp, filter status,
// LLH position, Euler angles) and leaves it idle: no stream is resumed. Then, every 100 ms, it
// polls the IMU data and the filter data (each poll answered by an ACK and a data packet): `imu ok`
// once the first IMU packet with both vectors came; `state N` whenever the filter state changes;
// once the state is "run solution valid", one JSON line per polled filter sample in that state
// until --samples were printed.
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
#include <vector>

#include "mipcodec/commands.hpp"
#include "mipcodec/mipcodec.hpp"
#include "mipcodec/session.hpp"
#include "mipcodec/transport_posix.hpp"

namespace api = mipcodec::api;
namespace types = mipcodec::types;
namespace fd = mipcodec::filter_data;
namespace sensor = mipcodec::sensor;

namespace {

constexpr const char *kUsageLine = "usage: gx5_polling ADDRESS [--samples N] [--deadline-s N]\n";
constexpr const char *kUsageHelp =
    "  ADDRESS  tcp:HOST:PORT or a serial device path (115200 baud)\n"
    "  --samples N     samples in 'run solution valid' to print (default 20)\n"
    "  --deadline-s N  give up waiting for them after N seconds (default 60)\n";

constexpr std::uint8_t kImuSet = 0x80;
constexpr std::uint8_t kFilterSet = 0x82;
constexpr unsigned kImuHz = 100;              // IMU data rate: decimation = IMU base rate / 100
constexpr unsigned kFilterHz = 10;            // filter data rate: decimation = filter base rate / 10
constexpr std::int64_t kCfEulerWaitMs = 1000; // how long the polled complementary filter angles are awaited
constexpr std::int64_t kPollPeriodMs = 100;   // how often the data is polled

struct Options {
    std::string address;
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
        if (arg == "--samples") {
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

/// The IMU and filter data read from the packets, and the output lines.
class Navigation {
  public:
    explicit Navigation(long samples) : wanted_(samples) {}

    /// Routes one packet that is not a reply.
    void on_packet(const mipcodec::PacketView &packet) {
        if (packet.set() == kImuSet) {
            on_imu(packet);
        } else if (packet.set() == kFilterSet) {
            on_filter(packet);
        }
    }

    bool done() const {
        return printed_ >= wanted_;
    }
    long printed() const {
        return printed_;
    }
    /// The complementary filter Euler angles of the first IMU packet holding them.
    const std::optional<sensor::CfEulerAngles> &cf_euler() const {
        return cf_euler_;
    }
    bool imu_ok() const {
        return imu_ok_;
    }
    const std::optional<unsigned> &state() const {
        return state_;
    }

  private:
    /// An IMU packet: `imu ok` once both vectors decoded; the complementary filter Euler angles of
    /// the filter initialization.
    void on_imu(const mipcodec::PacketView &packet) {
        std::optional<sensor::ScaledAccel> accel;
        std::optional<sensor::ScaledGyro> gyro;
        mipcodec::FieldIterator fields(packet);
        mipcodec::FieldEntry e;
        while (fields.next(e)) {
            if (e.kind != mipcodec::FieldEntry::Kind::field) {
                break;
            }
            if (e.descriptor == sensor::ScaledAccel::kDescriptor) {
                decode_into(e, accel);
            } else if (e.descriptor == sensor::ScaledGyro::kDescriptor) {
                decode_into(e, gyro);
            } else if (e.descriptor == sensor::CfEulerAngles::kDescriptor && !cf_euler_) {
                decode_into(e, cf_euler_);
            }
        }
        if (accel && gyro && !imu_ok_) {
            imu_ok_ = true;
            std::printf("imu ok\n");
            std::fflush(stdout);
        }
    }

    /// A filter packet: `state N` on a change, a JSON line in "run solution valid".
    void on_filter(const mipcodec::PacketView &packet) {
        std::optional<fd::GpsTimestamp> time;
        std::optional<fd::FilterStatusGx545> status;
        std::optional<fd::LlhPosition> llh;
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
            case fd::FilterStatusGx545::kDescriptor:
                decode_into(e, status);
                break;
            case fd::LlhPosition::kDescriptor:
                decode_into(e, llh);
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
        const auto state = static_cast<unsigned>(status->filter_state);
        if (!state_ || *state_ != state) {
            state_ = state;
            std::printf("state %u\n", state);
            std::fflush(stdout);
        }
        if (status->filter_state != types::FilterStateGx5::run_solution_valid || printed_ >= wanted_ ||
            !time || !llh || !euler) {
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
        line += ",\"euler\":[";
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

    template <class T> static void decode_into(const mipcodec::FieldEntry &e, std::optional<T> &out) {
        T value{};
        mipcodec::DecodeError err;
        if (mipcodec::decode(e.data, e.size, value, err)) {
            out = value;
        }
    }

    long wanted_;
    long printed_ = 0;
    bool imu_ok_ = false;
    std::optional<sensor::CfEulerAngles> cf_euler_;
    std::optional<unsigned> state_;
};

/// The IMU and filter data fields: the message formats and the polls.
constexpr std::array<std::uint8_t, 2> kImuFields{sensor::ScaledAccel::kDescriptor,
                                                 sensor::ScaledGyro::kDescriptor};
constexpr std::array<std::uint8_t, 4> kFilterFields{
    fd::GpsTimestamp::kDescriptor, fd::FilterStatusGx545::kDescriptor, fd::LlhPosition::kDescriptor,
    fd::EulerAngles::kDescriptor};

/// The decimation giving `hz` out of `base_hz`; nullopt when none does.
std::optional<std::uint16_t> decimation(unsigned base_hz, unsigned hz) {
    if (base_hz < hz || base_hz % hz != 0 || base_hz / hz > 0xFFFF) {
        return std::nullopt;
    }
    return static_cast<std::uint16_t>(base_hz / hz);
}

/// The configuration flow: the message formats, the device left idle.
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
    std::printf("model %s\nserial %s\nfirmware %u\n", unpadded(info.value->info.model_name).c_str(),
                unpadded(info.value->info.serial_number).c_str(),
                static_cast<unsigned>(info.value->info.firmware_version));
    std::fflush(stdout);
    const auto imu_base = api::threedm::get_imu_base_rate::call(device);
    if (!imu_base.value) {
        return failed("threedm.get_imu_base_rate", imu_base.call);
    }
    const auto filter_base = api::threedm::get_filter_base_rate::call(device);
    if (!filter_base.value) {
        return failed("threedm.get_filter_base_rate", filter_base.call);
    }
    const auto imu_decimation = decimation(imu_base.value->rate, kImuHz);
    if (!imu_decimation) {
        return error(
            "threedm.get_imu_base_rate",
            ("no decimation of " + std::to_string(imu_base.value->rate) + " Hz gives 100 Hz").c_str());
    }
    const auto filter_decimation = decimation(filter_base.value->rate, kFilterHz);
    if (!filter_decimation) {
        return error(
            "threedm.get_filter_base_rate",
            ("no decimation of " + std::to_string(filter_base.value->rate) + " Hz gives 10 Hz").c_str());
    }
    decltype(mipcodec::threedm::ImuMessageFormat::descriptors)::value_type imu_format;
    for (const std::uint8_t d : kImuFields) {
        imu_format.push_back(types::DescriptorRate{d, *imu_decimation});
    }
    call = api::threedm::imu_message_format::write(device, imu_format);
    if (!call.ok()) {
        return failed("threedm.imu_message_format write", call);
    }
    decltype(mipcodec::threedm::FilterMessageFormat::descriptors)::value_type filter_format;
    for (const std::uint8_t d : kFilterFields) {
        filter_format.push_back(types::DescriptorRate{d, *filter_decimation});
    }
    call = api::threedm::filter_message_format::write(device, filter_format);
    if (!call.ok()) {
        return failed("threedm.filter_message_format write", call);
    }
    // No resume: the device stays idle and sends data only when polled.
    return 0;
}

/// The manual's step 7, Initialize the Filter (3dm-gx5-45-dcp.txt line 431): poll the complementary
/// filter's Euler angles (0x80,0x0C), then Set Initial Attitude (0x0D,0x02) with them. A device
/// with auto-initialization enabled does not need it, but neither manual states that option's
/// factory setting, so the program does not rely on it. The packet handler is installed.
int initialize_filter(mipcodec::Connection &device, const Navigation &nav) {
    decltype(mipcodec::threedm::PollImuData::descriptors) cf_euler;
    cf_euler.push_back(types::Gx5PollDescriptor{sensor::CfEulerAngles::kDescriptor, 0});
    const mipcodec::Call call =
        api::threedm::poll_imu_data::call(device, types::Gx5PollOption::normal, cf_euler);
    if (!call.ok()) {
        return failed("threedm.poll_imu_data (complementary filter Euler angles)", call);
    }
    const std::int64_t end = device.now_ms() + kCfEulerWaitMs; // the data packet follows the ACK
    while (!nav.cf_euler() && device.now_ms() < end) {
        mipcodec::ErrorText io;
        if (!device.listen(std::min<std::int64_t>(10, end - device.now_ms()), &io)) {
            return error("connection", io.c_str());
        }
    }
    if (!nav.cf_euler()) {
        return error("threedm.poll_imu_data", ("no complementary filter Euler angles (0x80,0x0C) within " +
                                               std::to_string(kCfEulerWaitMs) + " ms")
                                                  .c_str());
    }
    const sensor::CfEulerAngles &angles = *nav.cf_euler();
    const mipcodec::Call set =
        api::filter::set_initial_attitude::call(device, angles.roll, angles.pitch, angles.yaw);
    if (!set.ok()) {
        return failed("filter.set_initial_attitude", set);
    }
    return 0;
}

/// Polls the IMU and the filter data (normal option: an ACK, then the data packet).
int poll_once(mipcodec::Connection &device) {
    decltype(mipcodec::threedm::PollImuData::descriptors) imu;
    for (const std::uint8_t d : kImuFields) {
        imu.push_back(types::Gx5PollDescriptor{d, 0});
    }
    mipcodec::Call call = api::threedm::poll_imu_data::call(device, types::Gx5PollOption::normal, imu);
    if (!call.ok()) {
        return failed("threedm.poll_imu_data", call);
    }
    decltype(mipcodec::threedm::PollFilterData::descriptors) filter;
    for (const std::uint8_t d : kFilterFields) {
        filter.push_back(types::Gx5PollDescriptor{d, 0});
    }
    call = api::threedm::poll_filter_data::call(device, types::Gx5PollOption::normal, filter);
    if (!call.ok()) {
        return failed("threedm.poll_filter_data", call);
    }
    return 0;
}

/// Polls every period until the samples were printed or the deadline passed.
int read_data(mipcodec::Connection &device, Navigation &nav, const Options &opt, std::int64_t deadline) {
    std::int64_t next_poll = device.now_ms();
    while (!nav.done()) {
        const std::int64_t now = device.now_ms();
        if (now >= deadline) {
            char why[200];
            std::snprintf(
                why, sizeof why,
                "%ld of %ld samples in 'run solution valid' in %ld s (IMU data %s, filter state %s)",
                nav.printed(), opt.samples, opt.deadline_s, nav.imu_ok() ? "seen" : "none",
                nav.state() ? std::to_string(*nav.state()).c_str() : "unknown");
            return error("deadline passed", why);
        }
        if (now >= next_poll) {
            next_poll = now + kPollPeriodMs;
            if (const int status = poll_once(device); status != 0) {
                return status; // the data packets reach the handler while the replies are awaited
            }
            continue;
        }
        mipcodec::ErrorText io;
        if (!device.listen(std::min(next_poll, deadline) - now, &io)) {
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
    options.device = mipcodec::Device::gx5_45; // what the GX5-45 does not support is refused unsent
    mipcodec::Connection device(*transport, options);
    const std::int64_t deadline = device.now_ms() + opt.deadline_s * 1000; // counted from the start
    Navigation nav(opt.samples);
    int status = configure(device);
    if (status == 0) {
        // Every packet that is not a reply (the polled data) reaches the handler.
        device.session().on_packet(
            [&nav](const mipcodec::PacketView &packet, std::uint64_t) { nav.on_packet(packet); });
        status = initialize_filter(device, nav);
    }
    if (status == 0) {
        status = read_data(device, nav, opt, deadline);
    }
    device.close();
    return status;
}
