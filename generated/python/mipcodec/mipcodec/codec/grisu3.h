/* Grisu3: the shortest round-trip digits of a double with 64-bit integer arithmetic (Florian
 * Loitsch, "Printing Floating-Point Numbers Quickly and Accurately with Integers", PLDI 2010).
 *
 * One source for two users: the C runtime's JSON float printer (src/json_writer.c, the C decode
 * CLI) and the Python package's C accelerator (copied there as grisu3.h and #included by
 * _speedups.c). grisu3() either yields the shortest digits closest to the value, provably, or
 * returns 0 (about 0.5% of doubles); each user then falls back to its exact printer (the C
 * runtime's big-integer search, Python's PyOS_double_to_string), so the text never changes: the
 * C runtime's tests compare it with Python's repr (json_float_test.cpp, test_c_float_repr.py),
 * the accelerator's with repr on random doubles, float32 values and boundaries.
 *
 * Header-only, static functions, C99, no libm, no allocation. */
#ifndef CODEC_GRISU3_H
#define CODEC_GRISU3_H

#include <string.h>

typedef struct {
    unsigned long long f;
    int e;
} DiyFp;

/* 10^k = f x 2^e (f rounded to 64 bits, top bit set) for k = -348, -340, ..., 340. */
static const struct {
    unsigned long long f;
    short e, k;
} cached_powers[] = {
    {0xfa8fd5a0081c0288ull, -1220, -348}, {0xbaaee17fa23ebf76ull, -1193, -340},
    {0x8b16fb203055ac76ull, -1166, -332}, {0xcf42894a5dce35eaull, -1140, -324},
    {0x9a6bb0aa55653b2dull, -1113, -316}, {0xe61acf033d1a45dfull, -1087, -308},
    {0xab70fe17c79ac6caull, -1060, -300}, {0xff77b1fcbebcdc4full, -1034, -292},
    {0xbe5691ef416bd60cull, -1007, -284}, {0x8dd01fad907ffc3cull, -980, -276},
    {0xd3515c2831559a83ull, -954, -268},  {0x9d71ac8fada6c9b5ull, -927, -260},
    {0xea9c227723ee8bcbull, -901, -252},  {0xaecc49914078536dull, -874, -244},
    {0x823c12795db6ce57ull, -847, -236},  {0xc21094364dfb5637ull, -821, -228},
    {0x9096ea6f3848984full, -794, -220},  {0xd77485cb25823ac7ull, -768, -212},
    {0xa086cfcd97bf97f4ull, -741, -204},  {0xef340a98172aace5ull, -715, -196},
    {0xb23867fb2a35b28eull, -688, -188},  {0x84c8d4dfd2c63f3bull, -661, -180},
    {0xc5dd44271ad3cdbaull, -635, -172},  {0x936b9fcebb25c996ull, -608, -164},
    {0xdbac6c247d62a584ull, -582, -156},  {0xa3ab66580d5fdaf6ull, -555, -148},
    {0xf3e2f893dec3f126ull, -529, -140},  {0xb5b5ada8aaff80b8ull, -502, -132},
    {0x87625f056c7c4a8bull, -475, -124},  {0xc9bcff6034c13053ull, -449, -116},
    {0x964e858c91ba2655ull, -422, -108},  {0xdff9772470297ebdull, -396, -100},
    {0xa6dfbd9fb8e5b88full, -369, -92},   {0xf8a95fcf88747d94ull, -343, -84},
    {0xb94470938fa89bcfull, -316, -76},   {0x8a08f0f8bf0f156bull, -289, -68},
    {0xcdb02555653131b6ull, -263, -60},   {0x993fe2c6d07b7facull, -236, -52},
    {0xe45c10c42a2b3b06ull, -210, -44},   {0xaa242499697392d3ull, -183, -36},
    {0xfd87b5f28300ca0eull, -157, -28},   {0xbce5086492111aebull, -130, -20},
    {0x8cbccc096f5088ccull, -103, -12},   {0xd1b71758e219652cull, -77, -4},
    {0x9c40000000000000ull, -50, 4},      {0xe8d4a51000000000ull, -24, 12},
    {0xad78ebc5ac620000ull, 3, 20},       {0x813f3978f8940984ull, 30, 28},
    {0xc097ce7bc90715b3ull, 56, 36},      {0x8f7e32ce7bea5c70ull, 83, 44},
    {0xd5d238a4abe98068ull, 109, 52},     {0x9f4f2726179a2245ull, 136, 60},
    {0xed63a231d4c4fb27ull, 162, 68},     {0xb0de65388cc8ada8ull, 189, 76},
    {0x83c7088e1aab65dbull, 216, 84},     {0xc45d1df942711d9aull, 242, 92},
    {0x924d692ca61be758ull, 269, 100},    {0xda01ee641a708deaull, 295, 108},
    {0xa26da3999aef774aull, 322, 116},    {0xf209787bb47d6b85ull, 348, 124},
    {0xb454e4a179dd1877ull, 375, 132},    {0x865b86925b9bc5c2ull, 402, 140},
    {0xc83553c5c8965d3dull, 428, 148},    {0x952ab45cfa97a0b3ull, 455, 156},
    {0xde469fbd99a05fe3ull, 481, 164},    {0xa59bc234db398c25ull, 508, 172},
    {0xf6c69a72a3989f5cull, 534, 180},    {0xb7dcbf5354e9beceull, 561, 188},
    {0x88fcf317f22241e2ull, 588, 196},    {0xcc20ce9bd35c78a5ull, 614, 204},
    {0x98165af37b2153dfull, 641, 212},    {0xe2a0b5dc971f303aull, 667, 220},
    {0xa8d9d1535ce3b396ull, 694, 228},    {0xfb9b7cd9a4a7443cull, 720, 236},
    {0xbb764c4ca7a44410ull, 747, 244},    {0x8bab8eefb6409c1aull, 774, 252},
    {0xd01fef10a657842cull, 800, 260},    {0x9b10a4e5e9913129ull, 827, 268},
    {0xe7109bfba19c0c9dull, 853, 276},    {0xac2820d9623bf429ull, 880, 284},
    {0x80444b5e7aa7cf85ull, 907, 292},    {0xbf21e44003acdd2dull, 933, 300},
    {0x8e679c2f5e44ff8full, 960, 308},    {0xd433179d9c8cb841ull, 986, 316},
    {0x9e19db92b4e31ba9ull, 1013, 324},   {0xeb96bf6ebadf77d9ull, 1039, 332},
    {0xaf87023b9bf0ee6bull, 1066, 340},
};

static DiyFp diy_times(DiyFp a, DiyFp b) {
    unsigned long long a1 = a.f >> 32, a0 = a.f & 0xFFFFFFFFu, b1 = b.f >> 32, b0 = b.f & 0xFFFFFFFFu;
    unsigned long long ac = a1 * b1, bc = a0 * b1, ad = a1 * b0, bd = a0 * b0;
    unsigned long long mid =
        (bd >> 32) + (ad & 0xFFFFFFFFu) + (bc & 0xFFFFFFFFu) + (1ull << 31); /* rounded */
    DiyFp r = {ac + (ad >> 32) + (bc >> 32) + (mid >> 32), a.e + b.e + 64};
    return r;
}

static int round_weed(char *buf, int len, unsigned long long dist_high_w, unsigned long long unsafe,
                      unsigned long long rest, unsigned long long ten_kappa, unsigned long long unit) {
    unsigned long long small = dist_high_w - unit, big = dist_high_w + unit;
    while (rest < small && unsafe - rest >= ten_kappa &&
           (rest + ten_kappa < small || small - rest >= rest + ten_kappa - small)) {
        buf[len - 1]--;
        rest += ten_kappa;
    }
    if (rest < big && unsafe - rest >= ten_kappa &&
        (rest + ten_kappa < big || big - rest > rest + ten_kappa - big)) {
        return 0;
    }
    return 2 * unit <= rest && rest <= unsafe - 4 * unit;
}

/* Digits of a finite positive value w whose lower neighbour is closer than its upper one when
 * lower_closer (a power of two, not the smallest exponent), halfway to each the boundaries (the
 * value's format's: a double's, or a float's for grisu3_single in the Python accelerator), into
 * buf (17 chars): their count in *len and the decimal exponent of the last in *exp10; 0 when
 * Grisu3 cannot tell. */
static int grisu3_bounded(DiyFp w, int lower_closer, char *buf, int *len, int *exp10) {
    /* Boundaries: halfway to the neighbours (the lower one closer at a power of two). */
    DiyFp plus = {(w.f << 1) + 1, w.e - 1};
    while (!(plus.f & 0xFFC0000000000000ull)) { /* normalize: the top bit at 63 */
        plus.f <<= 10;
        plus.e -= 10;
    }
    while (!(plus.f & 0x8000000000000000ull)) {
        plus.f <<= 1;
        plus.e--;
    }
    DiyFp minus;
    if (lower_closer) {
        minus.f = (w.f << 2) - 1;
        minus.e = w.e - 2;
    } else {
        minus.f = (w.f << 1) - 1;
        minus.e = w.e - 1;
    }
    minus.f <<= minus.e - plus.e;
    minus.e = plus.e;
    /* w normalized */
    while (!(w.f & 0xFFC0000000000000ull)) {
        w.f <<= 10;
        w.e -= 10;
    }
    while (!(w.f & 0x8000000000000000ull)) {
        w.f <<= 1;
        w.e--;
    }
    /* A cached power c with -60 <= w.e + c.e + 64 <= -32. */
    int min_exp = -60 - (w.e + 64);
    double k_real = (min_exp + 63) * 0.30102999566398114;
    int k = (int)k_real; /* ceil, without libm: truncation is the ceiling below 0 */
    if ((double)k < k_real) {
        k++;
    }
    int index = (348 + k - 1) / 8 + 1;
    if (index < 0 || index >= (int)(sizeof cached_powers / sizeof cached_powers[0])) {
        return 0;
    }
    DiyFp c = {cached_powers[index].f, cached_powers[index].e};
    int mk = cached_powers[index].k;
    int scaled_e = w.e + c.e + 64;
    if (scaled_e < -60 || scaled_e > -32) {
        return 0;
    }
    DiyFp sw = diy_times(w, c), low = diy_times(minus, c), high = diy_times(plus, c);
    /* Digit generation (DigitGen): too_low/too_high widened by the unit of imprecision. */
    unsigned long long unit = 1;
    DiyFp too_low = {low.f - unit, low.e}, too_high = {high.f + unit, high.e};
    unsigned long long unsafe = too_high.f - too_low.f;
    int shift = -sw.e;
    unsigned long long one = 1ull << shift;
    unsigned int integrals = (unsigned int)(too_high.f >> shift);
    unsigned long long fractionals = too_high.f & (one - 1);
    unsigned int divisor = 1;
    int kappa = 1; /* the number of decimal digits of integrals (at least one) */
    while (kappa < 10 && integrals >= divisor * 10u) {
        divisor *= 10u;
        kappa++;
    }
    if (integrals >= 1000000000u) {
        divisor = 1000000000u;
        kappa = 10;
    }
    int n = 0;
    while (kappa > 0) {
        buf[n++] = (char)('0' + integrals / divisor);
        integrals %= divisor;
        kappa--;
        unsigned long long rest = ((unsigned long long)integrals << shift) + fractionals;
        if (rest < unsafe) {
            if (n > 17 || !round_weed(buf, n, too_high.f - sw.f, unsafe, rest,
                                      (unsigned long long)divisor << shift, unit)) {
                return 0;
            }
            *len = n;
            *exp10 = kappa - mk;
            return 1;
        }
        divisor /= 10u;
    }
    for (;;) {
        fractionals *= 10;
        unit *= 10;
        unsafe *= 10;
        buf[n++] = (char)('0' + (int)(fractionals >> shift));
        fractionals &= one - 1;
        kappa--;
        if (fractionals < unsafe) {
            if (n > 17 || !round_weed(buf, n, (too_high.f - sw.f) * unit, unsafe, fractionals, one, unit)) {
                return 0;
            }
            *len = n;
            *exp10 = kappa - mk;
            return 1;
        }
        if (n >= 17) {
            return 0;
        }
    }
}

/* Digits of a finite positive double into buf (17 chars), their count in *len and the decimal
 * exponent of the last in *exp10; 0 when Grisu3 cannot tell. */
static int grisu3(double v, char *buf, int *len, int *exp10) {
    unsigned long long bits;
    memcpy(&bits, &v, 8);
    unsigned long long frac = bits & 0x000FFFFFFFFFFFFFull;
    int bexp = (int)((bits >> 52) & 0x7FF);
    DiyFp w;
    if (bexp) {
        w.f = frac | 0x0010000000000000ull;
        w.e = bexp - 1075;
    } else {
        w.f = frac;
        w.e = -1074;
    }
    return grisu3_bounded(w, frac == 0 && bexp > 1, buf, len, exp10);
}

#endif /* CODEC_GRISU3_H */
