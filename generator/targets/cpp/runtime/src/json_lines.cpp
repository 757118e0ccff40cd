// The JSON lines writer of json_lines.hpp compiled once (its default instances, declared
// `extern template` there): the field dispatch with the JSON writer of every layout. The encoder
// (a second dispatch, JSON to every layout's encoder) is json_encode.cpp: two sources of about
// half the cost each, so that no library source dominates a build (compile cost, issue 39).
#include "protopkg/json_lines.hpp"

namespace protopkg {

template void write_field_entry_json<void>(JsonWriter &, std::uint8_t, const FieldEntry &,
                                           const std::optional<Device> &);
template void write_packet_json<void>(JsonWriter &, std::uint64_t, const PacketView &,
                                      const std::optional<Device> &);

} // namespace protopkg
