// The JSON lines functions of json_lines.hpp compiled once (their default instances, declared
// `extern template` there): the field dispatch with the JSON writer and the encoder of every layout.
#include "protopkg/json_lines.hpp"

namespace protopkg {

template void write_field_entry_json<void>(JsonWriter &, std::uint8_t, const FieldEntry &,
                                           const std::optional<Device> &);
template void write_packet_json<void>(JsonWriter &, std::uint64_t, const PacketView &,
                                      const std::optional<Device> &);
namespace detail {
template bool encode_field<void>(const json::Value &, PacketBuilder &, JsonError &);
} // namespace detail
template bool encode_json_line<void>(const std::string &, std::vector<std::uint8_t> &, std::string &);

} // namespace protopkg
