// The minimal translation unit of the compile-cost benchmark (tests/bench/run.py --compile):
// includes the umbrella header, builds one command (ping) and feeds bytes to the stream parser.
// minimal.c is the same program with the C package; their compile costs are compared.
#include <cstddef>
#include <cstdint>
#include <cstdio>

#include "mipcodec/mipcodec.hpp"

namespace {

std::size_t packets = 0;

void on_event(const mipcodec::StreamEvent &event) {
    if (event.kind == mipcodec::StreamEvent::Kind::packet) {
        ++packets;
    }
}

} // namespace

int main() {
    mipcodec::PacketBuilder builder(mipcodec::base::Ping::kSet);
    if (builder.add(mipcodec::base::Ping{}) != mipcodec::EncodeError::none) {
        return 1;
    }
    const mipcodec::PacketView command = builder.finish();
    mipcodec::StreamParser parser;
    parser.feed(command.data, command.size, on_event);
    parser.flush(on_event);
    std::printf("%zu\n", packets);
    return packets == 1 ? 0 : 1;
}
