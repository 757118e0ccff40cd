// The JSON lines encoder of json_lines.hpp compiled once (its default instances, declared
// `extern template` there): a JSON line to bytes, through the encoder of every layout. The writer
// is json_lines.cpp.
#include "protopkg/json_lines.hpp"

namespace protopkg {

namespace detail {
template bool encode_field<void>(const json::Value &, PacketBuilder &, JsonError &);
} // namespace detail
template bool encode_json_line<void>(const std::string &, std::vector<std::uint8_t> &, std::string &);

} // namespace protopkg
