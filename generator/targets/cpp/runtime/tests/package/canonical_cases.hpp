// The case table that package_tests/test_canonical.cpp includes, for the in-place runtime tests:
// hand-written in the shape of the generated tests/canonical_cases.hpp
// (templates/cpp/tests/canonical_cases.hpp.j2), with a few rows of generator/testcases.py's table
// and its whole string case.
#pragma once

#include <cstdint>

namespace canonical_cases {

struct DoubleCase {
    std::uint64_t bits;
    const char *text;
};

struct FloatCase {
    std::uint32_t bits;
    const char *text;
};

inline constexpr DoubleCase kDoubles[] = {
    {0x0000000000000000ULL, "0.0"},
    {0x8000000000000000ULL, "-0.0"},
    {0x3FB999999999999AULL, "0.1"},
    {0x4341C37937E08000ULL, "1e+16"},
    {0xAB2BFF2EE48E0530ULL, "-1e-100"},
    {0x7FF8000000000000ULL, "\"nan\""},
    {0xFFF8000000000000ULL, "\"nan:0xfff8000000000000\""},
};

inline constexpr FloatCase kFloats[] = {
    {0x00000000U, "0.0"},
    {0x80000000U, "-0.0"},
    {0x3DCCCCCDU, "0.10000000149011612"},
};

inline constexpr char kAllBytes[] =
    "\"\\u0000\\u0001\\u0002\\u0003\\u0004\\u0005\\u0006\\u0007\\u0008\\u0009\\u000a\\u000b\\u000c\\u000d\\u0"
    "00e\\u000f\\u0010\\u0011\\u0012\\u0013\\u0014\\u0015\\u0016\\u0017\\u0018\\u0019\\u001a\\u001b\\u001c\\u"
    "001d\\u001e\\u001f "
    "!\\\"#$%&'()*+,-./"
    "0123456789:;<=>?@ABCDEFGHIJKLMNOPQRSTUVWXYZ[\\\\]^_`abcdefghijklmnopqrstuvwxyz{|}~"
    "\\u007f\\u0080\\u0081\\u0082\\u0083\\u0084\\u0085\\u0086\\u0087\\u0088\\u0089\\u008a\\u008b\\u008c\\u008"
    "d\\u008e\\u008f\\u0090\\u0091\\u0092\\u0093\\u0094\\u0095\\u0096\\u0097\\u0098\\u0099\\u009a\\u009b\\u00"
    "9c\\u009d\\u009e\\u009f\\u00a0\\u00a1\\u00a2\\u00a3\\u00a4\\u00a5\\u00a6\\u00a7\\u00a8\\u00a9\\u00aa\\u0"
    "0ab\\u00ac\\u00ad\\u00ae\\u00af\\u00b0\\u00b1\\u00b2\\u00b3\\u00b4\\u00b5\\u00b6\\u00b7\\u00b8\\u00b9\\u"
    "00ba\\u00bb\\u00bc\\u00bd\\u00be\\u00bf\\u00c0\\u00c1\\u00c2\\u00c3\\u00c4\\u00c5\\u00c6\\u00c7\\u00c8\\"
    "u00c9\\u00ca\\u00cb\\u00cc\\u00cd\\u00ce\\u00cf\\u00d0\\u00d1\\u00d2\\u00d3\\u00d4\\u00d5\\u00d6\\u00d7"
    "\\u00d8\\u00d9\\u00da\\u00db\\u00dc\\u00dd\\u00de\\u00df\\u00e0\\u00e1\\u00e2\\u00e3\\u00e4\\u00e5\\u00e"
    "6\\u00e7\\u00e8\\u00e9\\u00ea\\u00eb\\u00ec\\u00ed\\u00ee\\u00ef\\u00f0\\u00f1\\u00f2\\u00f3\\u00f4\\u00"
    "f5\\u00f6\\u00f7\\u00f8\\u00f9\\u00fa\\u00fb\\u00fc\\u00fd\\u00fe\\u00ff\"";

} // namespace canonical_cases
