//! Canonical JSON writer (`docs/conformance.md` §4): no allocation, writes to any
//! [`core::fmt::Write`].

use core::fmt::{self, Write};

use crate::wire::Wire;

/// Writes `bytes` as lowercase hex without separators.
pub fn write_hex(w: &mut dyn Write, bytes: &[u8]) -> fmt::Result {
    for b in bytes {
        write!(w, "{b:02x}")?;
    }
    Ok(())
}

fn write_escaped_byte(w: &mut dyn Write, b: u8) -> fmt::Result {
    match b {
        b'"' => w.write_str("\\\""),
        b'\\' => w.write_str("\\\\"),
        0x20..=0x7e => w.write_char(char::from(b)),
        _ => write!(w, "\\u{b:04x}"),
    }
}

/// Writes a JSON string whose characters are the bytes `bytes` (byte b → U+00bb).
pub fn write_str_bytes(w: &mut dyn Write, bytes: &[u8]) -> fmt::Result {
    w.write_char('"')?;
    for &b in bytes {
        write_escaped_byte(w, b)?;
    }
    w.write_char('"')
}

/// Writes `text` (ASCII) as a JSON string.
pub fn write_str(w: &mut dyn Write, text: &str) -> fmt::Result {
    write_str_bytes(w, text.as_bytes())
}

struct Escaper<'a>(&'a mut dyn Write);

impl Write for Escaper<'_> {
    fn write_str(&mut self, s: &str) -> fmt::Result {
        for b in s.bytes() {
            write_escaped_byte(self.0, b)?;
        }
        Ok(())
    }
}

/// Writes the `Display` text of `value` as a JSON string (error messages).
pub fn write_display(w: &mut dyn Write, value: &dyn fmt::Display) -> fmt::Result {
    w.write_char('"')?;
    write!(Escaper(w), "{value}")?;
    w.write_char('"')
}

/// Writes `"name":`, preceded by a comma unless it is the first key of the object.
pub fn key(w: &mut dyn Write, first: &mut bool, name: &str) -> fmt::Result {
    if !*first {
        w.write_char(',')?;
    }
    *first = false;
    write_str(w, name)?;
    w.write_char(':')
}

/// Writes a JSON array of values.
pub fn write_array<T: Wire>(w: &mut dyn Write, items: &[T]) -> fmt::Result {
    w.write_char('[')?;
    for (i, v) in items.iter().enumerate() {
        if i > 0 {
            w.write_char(',')?;
        }
        v.write_json(w)?;
    }
    w.write_char(']')
}

/// Bits of the canonical quiet NaN of a double.
pub const F64_QUIET_NAN: u64 = 0x7ff8_0000_0000_0000;
/// Bits of the canonical quiet NaN of a float.
pub const F32_QUIET_NAN: u32 = 0x7fc0_0000;

/// Writes a double: shortest round-trip decimal laid out like Python's `repr`, or
/// `"inf"`, `"-inf"`, `"nan"`, `"nan:0x<16 hex digits>"`.
pub fn write_f64(w: &mut dyn Write, x: f64) -> fmt::Result {
    if x.is_nan() {
        let bits = x.to_bits();
        if bits == F64_QUIET_NAN {
            return w.write_str("\"nan\"");
        }
        return write!(w, "\"nan:0x{bits:016x}\"");
    }
    write_number(w, x)
}

/// Writes a float: widened to double (exactly) except NaNs, which keep their 32 bits
/// (`"nan"` or `"nan:0x<8 hex digits>"`).
pub fn write_f32(w: &mut dyn Write, x: f32) -> fmt::Result {
    if x.is_nan() {
        let bits = x.to_bits();
        if bits == F32_QUIET_NAN {
            return w.write_str("\"nan\"");
        }
        return write!(w, "\"nan:0x{bits:08x}\"");
    }
    write_number(w, f64::from(x))
}

/// A stack buffer to capture formatted text.
struct StackBuf<const N: usize> {
    buf: [u8; N],
    len: usize,
}

impl<const N: usize> StackBuf<N> {
    const fn new() -> Self {
        Self {
            buf: [0; N],
            len: 0,
        }
    }

    fn bytes(&self) -> &[u8] {
        &self.buf[..self.len]
    }
}

impl<const N: usize> Write for StackBuf<N> {
    fn write_str(&mut self, s: &str) -> fmt::Result {
        let end = self.len + s.len();
        if end > N {
            return Err(fmt::Error);
        }
        self.buf[self.len..end].copy_from_slice(s.as_bytes());
        self.len = end;
        Ok(())
    }
}

/// Splits Rust's `{:e}` text "d[.ddd]e[-]x" into its digits (into `digits`) and the exponent.
fn split_sci(text: &[u8], digits: &mut [u8]) -> (usize, i32) {
    let mut n = 0;
    let mut i = 0;
    while i < text.len() && text[i] != b'e' {
        if text[i].is_ascii_digit() && n < digits.len() {
            digits[n] = text[i];
            n += 1;
        }
        i += 1;
    }
    let mut exp: i32 = 0;
    let mut negative = false;
    for &c in text.get(i + 1..).unwrap_or(&[]) {
        if c == b'-' {
            negative = true;
        } else if c.is_ascii_digit() {
            exp = exp * 10 + i32::from(c - b'0');
        }
    }
    (n, if negative { -exp } else { exp })
}

/// Shortest digits that round-trip to `a` (> 0, finite) and the exponent of the first digit.
/// Like Python's `repr`, when `a` lies exactly halfway between the two shortest candidates the
/// one with the even last digit is chosen (Rust's `{:e}` may pick the other one).
fn shortest_digits(a: f64, digits: &mut [u8; 24]) -> Result<(usize, i32), fmt::Error> {
    let mut sci = StackBuf::<40>::new();
    write!(sci, "{a:e}")?;
    let (n, exp) = split_sci(sci.bytes(), digits);
    if digits[n - 1] & 1 == 0 || !tie_possible(a) {
        // '0' is even: the digit is already the even choice; or no tie can happen.
        return Ok((n, exp));
    }
    // A tie needs the exact value to end in a 5 right after the n-th digit. Cheap filter first:
    // n+1 correctly rounded digits.
    let mut probe = StackBuf::<48>::new();
    write!(probe, "{a:.n$e}")?;
    let mut probe_digits = [0u8; 24];
    let (pn, pexp) = split_sci(probe.bytes(), &mut probe_digits);
    if pexp != exp || pn != n + 1 || probe_digits[n] != b'5' {
        return Ok((n, exp));
    }
    break_tie(a, n, exp, digits)?;
    Ok((n, exp))
}

/// The rare tie case of [`shortest_digits`], kept apart so that its large buffers are on the
/// stack only when needed.
#[inline(never)]
fn break_tie(a: f64, n: usize, exp: i32, digits: &mut [u8; 24]) -> fmt::Result {
    // The exact decimal expansion (a double has at most 767 significant digits).
    let mut exact = StackBuf::<840>::new();
    write!(exact, "{a:.800e}")?;
    let mut exact_digits = [0u8; 810];
    let (en, eexp) = split_sci(exact.bytes(), &mut exact_digits);
    if eexp != exp
        || en <= n
        || exact_digits[n] != b'5'
        || exact_digits[n + 1..en].iter().any(|&d| d != b'0')
    {
        return Ok(());
    }
    // Exactly halfway between truncated (T) and T + 1 in the last digit: take the even one.
    let mut other = [0u8; 24];
    other[..n].copy_from_slice(&exact_digits[..n]);
    if other[..n] == digits[..n] {
        let mut i = n;
        loop {
            if i == 0 {
                return Ok(());
            }
            i -= 1;
            if other[i] == b'9' {
                other[i] = b'0';
            } else {
                other[i] += 1;
                break;
            }
        }
    }
    // Use it if it reads back as the same double.
    let mut text = StackBuf::<48>::new();
    write_digits(&mut text, &other[..1])?;
    text.write_char('.')?;
    write_digits(&mut text, &other[1..n])?;
    write!(text, "e{exp}")?;
    let back = core::str::from_utf8(text.bytes())
        .ok()
        .and_then(|t| t.parse::<f64>().ok());
    if back.map(f64::to_bits) == Some(a.to_bits()) {
        digits[..n].copy_from_slice(&other[..n]);
    }
    Ok(())
}

fn write_zeros(w: &mut dyn Write, n: usize) -> fmt::Result {
    const ZEROS: &str = "0000000000000000";
    let mut left = n;
    while left > 0 {
        let k = left.min(ZEROS.len());
        w.write_str(&ZEROS[..k])?;
        left -= k;
    }
    Ok(())
}

/// ASCII digits written as one string (a write per digit was a fifth of the decode CLI's time).
fn write_digits(w: &mut dyn Write, digits: &[u8]) -> fmt::Result {
    w.write_str(core::str::from_utf8(digits).map_err(|_| fmt::Error)?)
}

/// Whether the exact decimal expansion of `a` (> 0, finite) can have at most 18 significant
/// digits, which a tie between two shortest candidates needs (the exact value ends in a 5 right
/// after them, and there are at most 17 of them). `a` = m x 2^e with m odd: for e < 0 its
/// expansion is m x 5^-e / 10^-e, whose significant digits are those of m x 5^-e; a float32 value
/// widened to f64 has more than 18, so the exact-format probe below is skipped for almost all of
/// them. Integers (e >= 0) always take the probe.
fn tie_possible(a: f64) -> bool {
    let bits = a.to_bits();
    let biased = ((bits >> 52) & 0x7FF) as i32;
    let mut m = bits & 0x000F_FFFF_FFFF_FFFF;
    let mut e = if biased == 0 {
        -1074
    } else {
        m |= 1 << 52;
        biased - 1075
    };
    if m == 0 {
        return true;
    }
    let tz = m.trailing_zeros();
    m >>= tz;
    e += tz as i32;
    if e >= 0 {
        return true;
    }
    let mut v = u128::from(m);
    for _ in 0..-e {
        v *= 5;
        if v >= 1_000_000_000_000_000_000 {
            return false;
        }
    }
    true
}

fn write_number(w: &mut dyn Write, x: f64) -> fmt::Result {
    if x.is_infinite() {
        return w.write_str(if x > 0.0 { "\"inf\"" } else { "\"-inf\"" });
    }
    if x.is_sign_negative() {
        w.write_char('-')?;
    }
    // Not `x.abs()`: core has float `abs` only since Rust 1.85 (the crates support 1.65).
    let a = if x.is_sign_negative() { -x } else { x };
    if a == 0.0 {
        return w.write_str("0.0");
    }
    let mut buf = [0u8; 24];
    let (n, exp) = shortest_digits(a, &mut buf)?;
    let digits = &buf[..n];
    if (-4..16).contains(&exp) {
        if exp >= 0 {
            let int_len = exp as usize + 1;
            if n <= int_len {
                write_digits(w, digits)?;
                write_zeros(w, int_len - n)?;
                w.write_str(".0")
            } else {
                write_digits(w, &digits[..int_len])?;
                w.write_char('.')?;
                write_digits(w, &digits[int_len..])
            }
        } else {
            w.write_str("0.")?;
            write_zeros(w, (-exp - 1) as usize)?;
            write_digits(w, digits)
        }
    } else {
        write_digits(w, &digits[..1])?;
        if n > 1 {
            w.write_char('.')?;
            write_digits(w, &digits[1..])?;
        }
        write!(
            w,
            "e{}{:02}",
            if exp < 0 { '-' } else { '+' },
            exp.unsigned_abs()
        )
    }
}
