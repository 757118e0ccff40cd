// The library's one instance of the field dispatch without a value (dispatch.hpp decodes_field).
#include "protopkg/dispatch.hpp"

namespace protopkg {

namespace {

/// Whether a field decodes, and its error when not.
struct DecodeCheck {
    bool raw_seen = false;
    DecodeError err;
    template <class T> void field(const T &) {}
    void raw(const DecodeError &e) {
        err = e;
        raw_seen = true;
    }
};

} // namespace

bool decodes_field(std::uint8_t set, std::uint8_t descriptor, const std::uint8_t *data, std::size_t size,
                   const std::optional<Device> &device, DecodeError &err) {
    DecodeCheck check;
    decode_field(set, descriptor, data, size, device, check);
    if (check.raw_seen) {
        err = check.err;
        return false;
    }
    return true;
}

} // namespace protopkg
