// Both C++ fuzz targets in one translation unit: the generated headers are heavy to compile, so
// each package is compiled once per build (libFuzzer, and g++ for the regression replay) and
// entry.cpp, compiled with -DFZ_ENTRY=fz_cpp_parser or fz_cpp_json, makes each target binary.
#include "fuzz_json.cpp"
#include "fuzz_parser.cpp"
