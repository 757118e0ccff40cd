// The C++ fuzz targets (parser, decode, json) in one translation unit: the generated headers are heavy to compile, so
// each package is compiled once per build (libFuzzer, and g++ for the regression replay) and
// entry.cpp, compiled with -DFZ_ENTRY=fz_cpp_<target>, makes each target binary.
#include "fuzz_json.cpp"
#include "fuzz_parser.cpp"
