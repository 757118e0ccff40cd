//! JSON reader (std): parses the canonical JSON lines of `docs/conformance.md` §4 (and any
//! other valid JSON) into a small tree, and [`FromJson`] turns values back into typed values.

use std::fmt;

use crate::bounded::BoundedVec;
use crate::wire::{Char, Str, Wire};

/// A parsed JSON value. Numbers keep their text so that each type parses it exactly.
#[derive(Clone, Debug, PartialEq)]
pub enum Json {
    Null,
    Bool(bool),
    Number(String),
    String(String),
    Array(Vec<Json>),
    Object(Vec<(String, Json)>),
}

impl Json {
    /// What kind of value this is, for messages.
    pub fn kind(&self) -> &'static str {
        match self {
            Json::Null => "null",
            Json::Bool(_) => "a bool",
            Json::Number(_) => "a number",
            Json::String(_) => "a string",
            Json::Array(_) => "an array",
            Json::Object(_) => "an object",
        }
    }

    /// The value of `key` if this is an object that has it.
    pub fn get(&self, key: &str) -> Option<&Json> {
        match self {
            Json::Object(items) => items.iter().find(|(k, _)| k == key).map(|(_, v)| v),
            _ => None,
        }
    }
}

/// A JSON reading error: the path of the value and what is wrong.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct JsonError {
    pub path: String,
    pub message: String,
}

impl JsonError {
    /// An error about the value itself.
    pub fn new(message: impl Into<String>) -> Self {
        Self {
            path: String::new(),
            message: message.into(),
        }
    }

    /// The error is inside member `key`.
    pub fn at(mut self, key: &str) -> Self {
        self.path = if self.path.is_empty() {
            key.to_string()
        } else if self.path.starts_with('[') {
            format!("{key}{}", self.path)
        } else {
            format!("{key}.{}", self.path)
        };
        self
    }

    /// The error is inside array element `index`.
    pub fn index(mut self, index: usize) -> Self {
        self.path = if self.path.is_empty() || self.path.starts_with('[') {
            format!("[{index}]{}", self.path)
        } else {
            format!("[{index}].{}", self.path)
        };
        self
    }
}

impl fmt::Display for JsonError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.path.is_empty() {
            f.write_str(&self.message)
        } else {
            write!(f, "{}: {}", self.path, self.message)
        }
    }
}

impl std::error::Error for JsonError {}

/// Parses one JSON text (surrounding whitespace allowed).
pub fn parse(text: &str) -> Result<Json, JsonError> {
    let mut p = JsonParser {
        s: text.as_bytes(),
        pos: 0,
    };
    p.ws();
    let v = p.value(0)?;
    p.ws();
    if p.pos != p.s.len() {
        return Err(p.err("unexpected text after the JSON value"));
    }
    Ok(v)
}

struct JsonParser<'a> {
    s: &'a [u8],
    pos: usize,
}

const MAX_DEPTH: usize = 64;

impl JsonParser<'_> {
    fn err(&self, what: &str) -> JsonError {
        JsonError::new(format!("invalid JSON at column {}: {what}", self.pos + 1))
    }

    fn ws(&mut self) {
        while self.pos < self.s.len() && matches!(self.s[self.pos], b' ' | b'\t' | b'\n' | b'\r') {
            self.pos += 1;
        }
    }

    fn peek(&self) -> Option<u8> {
        self.s.get(self.pos).copied()
    }

    fn literal(&mut self, word: &str, v: Json) -> Result<Json, JsonError> {
        if self.s[self.pos..].starts_with(word.as_bytes()) {
            self.pos += word.len();
            Ok(v)
        } else {
            Err(self.err("expected a value"))
        }
    }

    fn value(&mut self, depth: usize) -> Result<Json, JsonError> {
        if depth > MAX_DEPTH {
            return Err(self.err("nested too deeply"));
        }
        match self.peek() {
            Some(b'{') => self.object(depth),
            Some(b'[') => self.array(depth),
            Some(b'"') => self.string().map(Json::String),
            Some(b't') => self.literal("true", Json::Bool(true)),
            Some(b'f') => self.literal("false", Json::Bool(false)),
            Some(b'n') => self.literal("null", Json::Null),
            Some(b'-' | b'0'..=b'9') => self.number(),
            Some(_) => Err(self.err("expected a value")),
            None => Err(self.err("unexpected end of input")),
        }
    }

    fn object(&mut self, depth: usize) -> Result<Json, JsonError> {
        self.pos += 1;
        let mut items: Vec<(String, Json)> = Vec::new();
        self.ws();
        if self.peek() == Some(b'}') {
            self.pos += 1;
            return Ok(Json::Object(items));
        }
        loop {
            self.ws();
            if self.peek() != Some(b'"') {
                return Err(self.err("expected a key string"));
            }
            let key_pos = self.pos;
            let key = self.string()?;
            if items.iter().any(|(k, _)| *k == key) {
                self.pos = key_pos;
                return Err(self.err(&format!("duplicate key \"{key}\"")));
            }
            self.ws();
            if self.peek() != Some(b':') {
                return Err(self.err("expected ':'"));
            }
            self.pos += 1;
            self.ws();
            let v = self.value(depth + 1)?;
            items.push((key, v));
            self.ws();
            match self.peek() {
                Some(b',') => self.pos += 1,
                Some(b'}') => {
                    self.pos += 1;
                    return Ok(Json::Object(items));
                }
                _ => return Err(self.err("expected ',' or '}'")),
            }
        }
    }

    fn array(&mut self, depth: usize) -> Result<Json, JsonError> {
        self.pos += 1;
        let mut items = Vec::new();
        self.ws();
        if self.peek() == Some(b']') {
            self.pos += 1;
            return Ok(Json::Array(items));
        }
        loop {
            self.ws();
            items.push(self.value(depth + 1)?);
            self.ws();
            match self.peek() {
                Some(b',') => self.pos += 1,
                Some(b']') => {
                    self.pos += 1;
                    return Ok(Json::Array(items));
                }
                _ => return Err(self.err("expected ',' or ']'")),
            }
        }
    }

    fn hex4(&mut self) -> Result<u32, JsonError> {
        let digits = self
            .s
            .get(self.pos..self.pos + 4)
            .ok_or_else(|| self.err("short \\u escape"))?;
        let text = std::str::from_utf8(digits).map_err(|_| self.err("bad \\u escape"))?;
        let v = u32::from_str_radix(text, 16).map_err(|_| self.err("bad \\u escape"))?;
        if !digits.iter().all(u8::is_ascii_hexdigit) {
            return Err(self.err("bad \\u escape"));
        }
        self.pos += 4;
        Ok(v)
    }

    fn string(&mut self) -> Result<String, JsonError> {
        self.pos += 1;
        let mut out = String::new();
        loop {
            let start = self.pos;
            while self.pos < self.s.len()
                && self.s[self.pos] != b'"'
                && self.s[self.pos] != b'\\'
                && self.s[self.pos] >= 0x20
            {
                self.pos += 1;
            }
            // The input is a &str, so a run between ASCII delimiters is valid UTF-8.
            out.push_str(
                std::str::from_utf8(&self.s[start..self.pos])
                    .map_err(|_| self.err("invalid UTF-8"))?,
            );
            match self.peek() {
                Some(b'"') => {
                    self.pos += 1;
                    return Ok(out);
                }
                Some(b'\\') => {
                    self.pos += 1;
                    let c = self.peek().ok_or_else(|| self.err("unterminated string"))?;
                    self.pos += 1;
                    match c {
                        b'"' => out.push('"'),
                        b'\\' => out.push('\\'),
                        b'/' => out.push('/'),
                        b'b' => out.push('\u{8}'),
                        b'f' => out.push('\u{c}'),
                        b'n' => out.push('\n'),
                        b'r' => out.push('\r'),
                        b't' => out.push('\t'),
                        b'u' => {
                            let hi = self.hex4()?;
                            let mut code = hi;
                            if (0xD800..0xDC00).contains(&hi)
                                && self.s.get(self.pos..self.pos + 2) == Some(b"\\u")
                            {
                                let save = self.pos;
                                self.pos += 2;
                                let lo = self.hex4()?;
                                if (0xDC00..0xE000).contains(&lo) {
                                    code = 0x10000 + ((hi - 0xD800) << 10) + (lo - 0xDC00);
                                } else {
                                    self.pos = save;
                                }
                            }
                            // A lone surrogate (valid JSON, not a character) reads as U+FFFD:
                            // never a byte of a string parameter, and nothing in the texts the
                            // encoder does not use (docs/conformance.md §5).
                            out.push(char::from_u32(code).unwrap_or('\u{FFFD}'));
                        }
                        _ => return Err(self.err("bad escape")),
                    }
                }
                Some(_) => return Err(self.err("control character in string")),
                None => return Err(self.err("unterminated string")),
            }
        }
    }

    fn number(&mut self) -> Result<Json, JsonError> {
        let start = self.pos;
        let digits = |p: &mut Self| {
            let s = p.pos;
            while p.pos < p.s.len() && p.s[p.pos].is_ascii_digit() {
                p.pos += 1;
            }
            p.pos - s
        };
        if self.peek() == Some(b'-') {
            self.pos += 1;
        }
        let int_start = self.pos;
        let n = digits(self);
        if n == 0 || (n > 1 && self.s[int_start] == b'0') {
            self.pos = start;
            return Err(self.err("bad number"));
        }
        if self.peek() == Some(b'.') {
            self.pos += 1;
            if digits(self) == 0 {
                return Err(self.err("bad number"));
            }
        }
        if matches!(self.peek(), Some(b'e' | b'E')) {
            self.pos += 1;
            if matches!(self.peek(), Some(b'+' | b'-')) {
                self.pos += 1;
            }
            if digits(self) == 0 {
                return Err(self.err("bad number"));
            }
        }
        let text =
            std::str::from_utf8(&self.s[start..self.pos]).map_err(|_| self.err("bad number"))?;
        Ok(Json::Number(text.to_string()))
    }
}

/// A value that can be read back from its canonical JSON form.
pub trait FromJson: Sized {
    fn from_json(v: &Json) -> Result<Self, JsonError>;
}

fn integer(v: &Json, lo: i128, hi: i128) -> Result<i128, JsonError> {
    let expected = || {
        JsonError::new(format!(
            "expected an integer in {lo}..{hi}, got {}",
            describe(v)
        ))
    };
    let Json::Number(text) = v else {
        return Err(expected());
    };
    let n: i128 = text.parse().map_err(|_| expected())?;
    if n < lo || n > hi {
        return Err(expected());
    }
    Ok(n)
}

fn describe(v: &Json) -> String {
    match v {
        Json::Number(t) => t.clone(),
        Json::Bool(b) => b.to_string(),
        other => other.kind().to_string(),
    }
}

macro_rules! from_json_int {
    ($($t:ty),*) => {$(
        impl FromJson for $t {
            fn from_json(v: &Json) -> Result<Self, JsonError> {
                let n = integer(v, i128::from(<$t>::MIN), i128::from(<$t>::MAX))?;
                Ok(n as $t)
            }
        }
    )*};
}

from_json_int!(u8, u16, u32, u64, i8, i16, i32, i64);

impl FromJson for bool {
    fn from_json(v: &Json) -> Result<Self, JsonError> {
        match v {
            Json::Bool(b) => Ok(*b),
            other => Err(JsonError::new(format!(
                "expected true or false, got {}",
                describe(other)
            ))),
        }
    }
}

fn float_special(v: &Json, hex_digits: usize) -> Result<Option<u64>, JsonError> {
    // Ok(Some(bits)) for "nan:0x..", Ok(None) for plain numbers; infinities and "nan" are
    // handled by the callers.
    let Json::String(s) = v else { return Ok(None) };
    let bad = || {
        JsonError::new(format!(
            "expected a number, \"inf\", \"-inf\", \"nan\" or \"nan:0x\" + {hex_digits} hex digits, got \"{s}\""
        ))
    };
    let hex = s.strip_prefix("nan:0x").ok_or_else(bad)?;
    if hex.len() != hex_digits || !hex.bytes().all(|c| c.is_ascii_hexdigit()) {
        return Err(bad());
    }
    u64::from_str_radix(hex, 16).map(Some).map_err(|_| bad())
}

/// The double nearest to a JSON number (ties to even); an infinite result is an error, one that
/// underflows is 0 or a denormal (docs/conformance.md §5).
fn finite_double(t: &str) -> Result<f64, JsonError> {
    let x: f64 = t
        .parse()
        .map_err(|_| JsonError::new(format!("bad number {t}")))?;
    if x.is_infinite() {
        return Err(JsonError::new(format!(
            "number {t} is out of range for a double"
        )));
    }
    Ok(x)
}

impl FromJson for f64 {
    fn from_json(v: &Json) -> Result<Self, JsonError> {
        match v {
            Json::Number(t) => finite_double(t),
            Json::String(s) if s == "inf" => Ok(f64::INFINITY),
            Json::String(s) if s == "-inf" => Ok(f64::NEG_INFINITY),
            Json::String(s) if s == "nan" => Ok(f64::from_bits(crate::json::F64_QUIET_NAN)),
            Json::String(_) => {
                let bits = float_special(v, 16)?.unwrap_or(0);
                let x = f64::from_bits(bits);
                if !x.is_nan() {
                    return Err(JsonError::new(format!("0x{bits:016x} is not a NaN")));
                }
                Ok(x)
            }
            other => Err(JsonError::new(format!(
                "expected a number, got {}",
                describe(other)
            ))),
        }
    }
}

impl FromJson for f32 {
    fn from_json(v: &Json) -> Result<Self, JsonError> {
        match v {
            // The nearest double, then the nearest float (not the decimal straight to a float:
            // the rule is the double's rounding, as in C, C++ and Python).
            Json::Number(t) => {
                let x = finite_double(t)? as f32;
                if x.is_infinite() {
                    return Err(JsonError::new(format!(
                        "number {t} is out of range for a float"
                    )));
                }
                Ok(x)
            }
            Json::String(s) if s == "inf" => Ok(f32::INFINITY),
            Json::String(s) if s == "-inf" => Ok(f32::NEG_INFINITY),
            Json::String(s) if s == "nan" => Ok(f32::from_bits(crate::json::F32_QUIET_NAN)),
            Json::String(_) => {
                let bits = float_special(v, 8)?.unwrap_or(0) as u32;
                let x = f32::from_bits(bits);
                if !x.is_nan() {
                    return Err(JsonError::new(format!("0x{bits:08x} is not a NaN")));
                }
                Ok(x)
            }
            other => Err(JsonError::new(format!(
                "expected a number, got {}",
                describe(other)
            ))),
        }
    }
}

/// The bytes of a JSON string whose characters are all U+0000..U+00FF.
pub fn string_bytes(v: &Json) -> Result<Vec<u8>, JsonError> {
    let Json::String(s) = v else {
        return Err(JsonError::new(format!(
            "expected a string, got {}",
            describe(v)
        )));
    };
    s.chars()
        .map(|c| {
            u8::try_from(u32::from(c)).map_err(|_| {
                JsonError::new(format!(
                    "character U+{:04X} is not a byte (U+0000..U+00FF)",
                    u32::from(c)
                ))
            })
        })
        .collect()
}

impl FromJson for Char {
    fn from_json(v: &Json) -> Result<Self, JsonError> {
        let bytes = string_bytes(v)?;
        match bytes[..] {
            [b] => Ok(Char(b)),
            _ => Err(JsonError::new(format!(
                "expected a string of 1 character, got {}",
                bytes.len()
            ))),
        }
    }
}

impl<const N: usize> FromJson for Str<N> {
    fn from_json(v: &Json) -> Result<Self, JsonError> {
        let bytes = string_bytes(v)?;
        let arr: [u8; N] = bytes[..].try_into().map_err(|_| {
            JsonError::new(format!(
                "expected a string of {N} characters, got {}",
                bytes.len()
            ))
        })?;
        Ok(Str(arr))
    }
}

fn array(v: &Json) -> Result<&[Json], JsonError> {
    match v {
        Json::Array(items) => Ok(items),
        other => Err(JsonError::new(format!(
            "expected an array, got {}",
            describe(other)
        ))),
    }
}

impl<T: Wire + FromJson, const N: usize> FromJson for [T; N] {
    fn from_json(v: &Json) -> Result<Self, JsonError> {
        let items = array(v)?;
        if items.len() != N {
            return Err(JsonError::new(format!(
                "expected {N} elements, got {}",
                items.len()
            )));
        }
        let mut out = [T::ZERO; N];
        for (i, (slot, item)) in out.iter_mut().zip(items).enumerate() {
            *slot = T::from_json(item).map_err(|e| e.index(i))?;
        }
        Ok(out)
    }
}

impl<T: Wire + FromJson, const N: usize> FromJson for BoundedVec<T, N> {
    fn from_json(v: &Json) -> Result<Self, JsonError> {
        let items = array(v)?;
        if items.len() > N {
            return Err(JsonError::new(format!(
                "at most {N} elements, got {}",
                items.len()
            )));
        }
        let mut out = Self::new();
        for (i, item) in items.iter().enumerate() {
            let x = T::from_json(item).map_err(|e| e.index(i))?;
            // Cannot fail: the length was checked.
            let _ = out.push(x);
        }
        Ok(out)
    }
}

/// A JSON object with a known set of keys, for reading struct and layout values.
pub struct Obj<'a> {
    items: &'a [(String, Json)],
}

impl<'a> Obj<'a> {
    /// `v` must be an object whose keys are all in `keys`.
    pub fn new(v: &'a Json, keys: &[&str]) -> Result<Self, JsonError> {
        let Json::Object(items) = v else {
            return Err(JsonError::new(format!(
                "expected an object, got {}",
                describe(v)
            )));
        };
        for (k, _) in items {
            if !keys.contains(&k.as_str()) {
                let expected = if keys.is_empty() {
                    "no keys".to_string()
                } else {
                    keys.join(", ")
                };
                return Err(JsonError::new(format!(
                    "unknown key \"{k}\" (expected {expected})"
                )));
            }
        }
        Ok(Self { items })
    }

    fn get(&self, key: &str) -> Option<&'a Json> {
        self.items.iter().find(|(k, _)| k == key).map(|(_, v)| v)
    }

    /// A required member.
    pub fn req<T>(
        &self,
        key: &str,
        read: impl FnOnce(&'a Json) -> Result<T, JsonError>,
    ) -> Result<T, JsonError> {
        match self.get(key) {
            Some(v) => read(v).map_err(|e| e.at(key)),
            None => Err(JsonError::new(format!("missing \"{key}\""))),
        }
    }

    /// An optional member (absent: `None`).
    pub fn opt<T>(
        &self,
        key: &str,
        read: impl FnOnce(&'a Json) -> Result<T, JsonError>,
    ) -> Result<Option<T>, JsonError> {
        match self.get(key) {
            Some(v) => read(v).map(Some).map_err(|e| e.at(key)),
            None => Ok(None),
        }
    }
}

/// Reads `null` (a union member without data).
pub fn null(v: &Json) -> Result<(), JsonError> {
    match v {
        Json::Null => Ok(()),
        other => Err(JsonError::new(format!(
            "expected null (this member has no data), got {}",
            describe(other)
        ))),
    }
}

/// Decodes lowercase or uppercase hex (an even number of digits).
pub fn hex_bytes(v: &Json) -> Result<Vec<u8>, JsonError> {
    let Json::String(s) = v else {
        return Err(JsonError::new(format!(
            "expected a hex string, got {}",
            describe(v)
        )));
    };
    let bytes = s.as_bytes();
    if bytes.len() % 2 != 0 || !bytes.iter().all(u8::is_ascii_hexdigit) {
        return Err(JsonError::new("expected an even number of hex digits"));
    }
    Ok(bytes
        .chunks(2)
        .map(|pair| {
            let digit = |c: u8| char::from(c).to_digit(16).unwrap_or(0) as u8;
            (digit(pair[0]) << 4) | digit(pair[1])
        })
        .collect())
}
