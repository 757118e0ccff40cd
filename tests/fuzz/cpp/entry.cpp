// The libFuzzer entry point of one C++ target: FZ_ENTRY is fz_cpp_parser, fz_cpp_decode or fz_cpp_json
// (defined in fuzz_targets.cpp).
#include <cstddef>
#include <cstdint>

extern "C" int FZ_ENTRY(const std::uint8_t *data, std::size_t size);

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    return FZ_ENTRY(data, size);
}
