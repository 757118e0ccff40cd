//! Stream parser (`docs/conformance.md` §1): finds packets in a byte stream fed in chunks of
//! any size and reports the bytes between them as skip runs. The events do not depend on the
//! chunking. State: one maximum packet or foreign frame ([`PARSER_CAPACITY`] bytes) and a few
//! counters.

use crate::framing::{
    checksum_bytes, CHECKSUM_SIZE, FOREIGN_NMEA, FOREIGN_RTCM3, HEADER_SIZE, LENGTH_OFFSET,
    MAX_PAYLOAD, NMEA_MAX, PARSER_CAPACITY, SYNC,
};

/// What the parser found.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Event<'a> {
    /// A maximal run of `count` skipped bytes starting at stream offset `offset`.
    Skip { offset: u64, count: u64 },
    /// A packet with a valid checksum at stream offset `offset`: sync to checksum.
    Packet { offset: u64, bytes: &'a [u8] },
    /// An NMEA-0183 sentence between packets ([`FOREIGN_NMEA`]): `$` or `!` to CR LF.
    Nmea { offset: u64, bytes: &'a [u8] },
    /// An RTCM3 frame between packets ([`FOREIGN_RTCM3`]): 0xD3 to its CRC-24Q.
    Rtcm { offset: u64, bytes: &'a [u8] },
}

/// The message number of an RTCM3 frame (the first 12 bits of its payload).
pub fn rtcm_type(frame: &[u8]) -> u16 {
    u16::from(frame[3]) << 4 | u16::from(frame[4]) >> 4
}

// Foreign frames (`docs/conformance.md` §1): where the parser would skip bytes, a whole
// NMEA-0183 sentence or RTCM3 frame is reported instead; a candidate that fails stays skipped
// bytes, one byte at a time. Never on the packet path.
enum Foreign {
    // A whole valid frame of this many bytes.
    Frame(usize),
    // Not a frame: its first byte is skipped.
    Not,
    // More bytes decide.
    Wait,
}

fn foreign_start(b: u8) -> bool {
    (FOREIGN_NMEA && (b == b'$' || b == b'!')) || (FOREIGN_RTCM3 && b == 0xD3)
}

/// CRC-24Q of RTCM3: polynomial 0x1864CFB, initial value 0, not reflected.
fn crc24q(data: &[u8]) -> u32 {
    let mut crc = 0u32;
    for &b in data {
        crc ^= u32::from(b) << 16;
        for _ in 0..8 {
            crc <<= 1;
            if crc & 0x100_0000 != 0 {
                crc ^= 0x186_4CFB;
            }
        }
    }
    crc
}

fn hex_digit(c: u8) -> Option<u32> {
    char::from(c).to_digit(16)
}

/// The foreign frame at `p[0]` (a start byte), with the bytes `p` holds.
fn foreign_frame(p: &[u8]) -> Foreign {
    let n = p.len();
    if p[0] == 0xD3 {
        if n < 3 {
            return Foreign::Wait;
        }
        if p[1] & 0xFC != 0 {
            return Foreign::Not;
        }
        let length = usize::from(p[1] & 3) << 8 | usize::from(p[2]);
        let total = 3 + length + 3;
        if length < 2 {
            return Foreign::Not; // no message number
        }
        if n < total {
            return Foreign::Wait;
        }
        let crc =
            u32::from(p[total - 3]) << 16 | u32::from(p[total - 2]) << 8 | u32::from(p[total - 1]);
        return if crc24q(&p[..total - 3]) == crc {
            Foreign::Frame(total)
        } else {
            Foreign::Not
        };
    }
    let lim = NMEA_MAX.saturating_sub(4).max(1); // the '*' stands before lim
    let mut j = 1;
    let mut x = 0u32;
    while j < n && j < lim && (0x20..=0x7E).contains(&p[j]) && !matches!(p[j], b'$' | b'!' | b'*') {
        x ^= u32::from(p[j]);
        j += 1;
    }
    if j == lim {
        return Foreign::Not; // overlong
    }
    if j == n {
        return Foreign::Wait;
    }
    if p[j] != b'*' {
        return Foreign::Not;
    }
    if n < j + 5 {
        return Foreign::Wait;
    }
    match (hex_digit(p[j + 1]), hex_digit(p[j + 2])) {
        (Some(hi), Some(lo)) if p[j + 3] == b'\r' && p[j + 4] == b'\n' && (hi << 4 | lo) == x => {
            Foreign::Frame(j + 5)
        }
        _ => Foreign::Not,
    }
}

fn foreign_event(offset: u64, bytes: &[u8]) -> Event<'_> {
    if bytes[0] == 0xD3 {
        Event::Rtcm { offset, bytes }
    } else {
        Event::Nmea { offset, bytes }
    }
}

/// The stream parser.
#[derive(Clone)]
pub struct Parser {
    buf: [u8; PARSER_CAPACITY],
    len: usize,
    // Stream offset of buf[0].
    base: u64,
    skip_start: u64,
    skip_count: u64,
}

impl Default for Parser {
    fn default() -> Self {
        Self::new()
    }
}

/// Whether `sent` is the checksum of `body` (byte by byte: no call to a slice comparison).
#[inline(always)]
fn checksum_matches(body: &[u8], sent: &[u8]) -> bool {
    let sum = checksum_bytes(body);
    sent.len() == CHECKSUM_SIZE && (0..CHECKSUM_SIZE).all(|i| sum[i] == sent[i])
}

/// Index of the first `byte` in `hay`, eight bytes at a time (one branch per eight bytes of
/// garbage instead of one per byte).
#[inline(always)]
fn find_byte(hay: &[u8], byte: u8) -> Option<usize> {
    const LOW: u64 = 0x0101_0101_0101_0101;
    const HIGH: u64 = 0x8080_8080_8080_8080;
    let pattern = LOW * u64::from(byte);
    let mut words = hay.chunks_exact(8);
    let mut base = 0;
    for word in &mut words {
        let mut bytes = [0u8; 8];
        bytes.copy_from_slice(word);
        // Bytes equal to `byte` become zero; the lowest flagged byte is the first zero byte
        // (a flag can be wrong only above a zero byte).
        let x = u64::from_le_bytes(bytes) ^ pattern;
        let zero = x.wrapping_sub(LOW) & !x & HIGH;
        if zero != 0 {
            return Some(base + (zero.trailing_zeros() / 8) as usize);
        }
        base += 8;
    }
    words
        .remainder()
        .iter()
        .position(|&b| b == byte)
        .map(|i| base + i)
}

/// Index of the first full sync in `data` at or after `from`, or of a sync prefix at its very
/// end; `None` if there is neither.
#[inline(always)]
fn find_sync_from(data: &[u8], from: usize) -> Option<usize> {
    let end = data.len();
    let mut at = from;
    // Sixteen candidate positions at a time while the full sync fits after all of them: byte k
    // of the sync compared in one 128-bit word loaded at `at + k`, a position matches where
    // every comparison gave a zero byte. One branch per sixteen bytes of garbage, none per
    // false first byte.
    const LOW: u128 = u128::from_le_bytes([1; 16]);
    const HIGH: u128 = LOW << 7;
    while at + 16 + SYNC.len() - 1 <= end {
        let mut diff = 0u128;
        for (k, &byte) in SYNC.iter().enumerate() {
            let mut bytes = [0u8; 16];
            bytes.copy_from_slice(&data[at + k..at + k + 16]);
            diff |= u128::from_le_bytes(bytes) ^ (LOW * u128::from(byte));
        }
        // Zero bytes of `diff` are the matches; the lowest flagged byte is the first match (a
        // flag can be wrong only above a zero byte).
        let zero = diff.wrapping_sub(LOW) & !diff & HIGH;
        if zero != 0 {
            return Some(at + (zero.trailing_zeros() / 8) as usize);
        }
        at += 16;
    }
    loop {
        at += find_byte(&data[at..], SYNC[0])?;
        // The rest of the sync, or as much of it as `data` holds (byte by byte: no call to a
        // slice comparison).
        let n = (end - at).min(SYNC.len());
        if (1..n).all(|k| data[at + k] == SYNC[k]) {
            return Some(at);
        }
        at += 1;
    }
}

enum Sync {
    // A full sync sequence at this index.
    Full(usize),
    // No full sync; bytes from this index may start one (wait for more input).
    Partial(usize),
}

impl Parser {
    /// A parser at stream offset 0.
    pub const fn new() -> Self {
        Self {
            buf: [0; PARSER_CAPACITY],
            len: 0,
            base: 0,
            skip_start: 0,
            skip_count: 0,
        }
    }

    /// Stream offset of the next byte to be fed.
    pub fn offset(&self) -> u64 {
        self.base + self.len as u64
    }

    /// The earliest stream offset whose byte may still be reported (in a skip run or a packet).
    /// A caller that keeps the input to print skipped bytes can drop everything before it.
    pub fn retain_from(&self) -> u64 {
        if self.skip_count > 0 {
            self.skip_start
        } else {
            self.base
        }
    }

    /// Bytes buffered for a candidate packet that waits for more input (0: none).
    pub fn waiting(&self) -> usize {
        self.len
    }

    /// Stream offset of the first buffered byte: the position the parser waits at when
    /// [`Parser::waiting`] is not 0.
    pub fn waiting_at(&self) -> u64 {
        self.base
    }

    /// The look-ahead rule of the sessions (`docs/conformance.md` §8): finds the first position
    /// after the first buffered byte where a full sync starts a complete packet with a valid
    /// checksum, all of its bytes buffered (the §1 check). If there is one, the bytes before it
    /// are skipped (added to the pending skip run) and the search resumes there, with no new
    /// input (the packet is reported); returns whether it found one. Nothing is dropped when
    /// there is none: a slow packet is never thrown away.
    pub fn skip_to_complete_packet<F: FnMut(Event<'_>)>(&mut self, mut on: F) -> bool {
        let Some(j) = (1..self.len).find(|&j| self.complete_packet_at(j)) else {
            return false;
        };
        self.skip(j);
        self.process(&mut on, false);
        true
    }

    /// Whether the buffered bytes from index `at` start a complete packet with a valid checksum.
    fn complete_packet_at(&self, at: usize) -> bool {
        let rest = &self.buf[at..self.len];
        if rest.len() < HEADER_SIZE || (0..SYNC.len()).any(|k| rest[k] != SYNC[k]) {
            return false;
        }
        let payload = usize::from(rest[LENGTH_OFFSET]);
        let body = HEADER_SIZE + payload;
        payload <= MAX_PAYLOAD
            && rest.len() >= body + CHECKSUM_SIZE
            && checksum_matches(&rest[..body], &rest[body..body + CHECKSUM_SIZE])
    }

    /// Length of the skip run not reported yet (it ends at the first buffered byte).
    pub fn pending_skip(&self) -> u64 {
        self.skip_count
    }

    /// Reports the pending skip run in pieces of `piece` bytes while it holds at least that
    /// many (each piece is a skip run of its own; the rest stays pending, starting after the
    /// last piece). The sessions bound their memory with it (`docs/conformance.md` §8).
    pub fn report_skip_pieces<F: FnMut(Event<'_>)>(&mut self, piece: u64, mut on: F) {
        if piece == 0 {
            return;
        }
        while self.skip_count >= piece {
            on(Event::Skip {
                offset: self.skip_start,
                count: piece,
            });
            self.skip_start += piece;
            self.skip_count -= piece;
        }
    }

    /// Feeds `data`; calls `on` for every event it completes.
    ///
    /// Packets that lie wholly inside `data` are checked and reported in place (their bytes
    /// borrow `data`); only a packet split across `feed` calls is copied into the parser's
    /// buffer, and only the bytes it still needs.
    pub fn feed<F: FnMut(Event<'_>)>(&mut self, mut data: &[u8], mut on: F) {
        // Finish the candidate buffered by the previous call.
        while self.len > 0 && !data.is_empty() {
            let n = data.len().min(self.wanted() - self.len);
            self.buf[self.len..self.len + n].copy_from_slice(&data[..n]);
            self.len += n;
            data = &data[n..];
            self.process(&mut on, false);
        }
        if data.is_empty() {
            return;
        }
        // Nothing buffered: search `data` itself, then keep the undecided tail.
        let used = self.scan(data, &mut on);
        let rest = &data[used..];
        self.buf[..rest.len()].copy_from_slice(rest);
        self.len = rest.len();
    }

    /// Bytes the buffered candidate needs before it can be decided (more than `self.len`
    /// whenever `process` left bytes waiting).
    fn wanted(&self) -> usize {
        if (FOREIGN_NMEA || FOREIGN_RTCM3) && foreign_start(self.buf[0]) {
            return if self.buf[0] != 0xD3 {
                NMEA_MAX
            } else if self.len < 3 {
                3
            } else {
                3 + (usize::from(self.buf[1] & 3) << 8 | usize::from(self.buf[2])) + 3
            };
        }
        if self.len < HEADER_SIZE {
            HEADER_SIZE
        } else {
            HEADER_SIZE + usize::from(self.buf[LENGTH_OFFSET]) + CHECKSUM_SIZE
        }
    }

    /// The search of `process` over `data` in place, with nothing buffered (`self.base` is the
    /// stream offset of `data[0]`). Returns how many bytes it consumed; the rest (a candidate
    /// that needs more input, shorter than a maximum packet) is for the caller to buffer.
    fn scan<F: FnMut(Event<'_>)>(&mut self, data: &[u8], on: &mut F) -> usize {
        let end = data.len();
        let mut pos = 0;
        loop {
            // The next sync (or a sync prefix at the very end): usually right here, after a
            // packet; else searched for. (Reads through slices whose length was checked, so
            // that they need no further bounds checks.)
            let here = &data[pos..];
            let at = if here.len() >= SYNC.len() && (0..SYNC.len()).all(|k| here[k] == SYNC[k]) {
                pos
            } else {
                match find_sync_from(data, pos) {
                    Some(at) => at,
                    None => {
                        return match self.gap_in_place(data, pos, end, on) {
                            Ok(_) => end,
                            Err(wait) => wait,
                        };
                    }
                }
            };
            if at > pos {
                match self.gap_in_place(data, pos, at, on) {
                    Ok(next) if next > at => {
                        pos = next; // a frame ran over the sync: go on after it
                        continue;
                    }
                    Ok(_) => {}
                    Err(wait) => return wait,
                }
            }
            pos = at;
            let candidate = &data[pos..];
            if candidate.len() < HEADER_SIZE {
                return pos;
            }
            let payload = usize::from(candidate[LENGTH_OFFSET]);
            if payload > MAX_PAYLOAD {
                self.skip_in_place(1);
                pos += 1;
                continue;
            }
            let body = HEADER_SIZE + payload;
            let total = body + CHECKSUM_SIZE;
            let Some(packet) = candidate.get(..total) else {
                return pos;
            };
            if checksum_matches(&packet[..body], &packet[body..]) {
                self.emit_skip(on);
                on(Event::Packet {
                    offset: self.base,
                    bytes: packet,
                });
                self.base += total as u64;
                pos += total;
            } else {
                // The sync was false: resynchronise at the next byte.
                self.skip_in_place(1);
                pos += 1;
            }
        }
    }

    /// The bytes `data[pos..to]` hold no sync: skipped, but for the foreign frames among them.
    /// Returns where scanning goes on (`to`, or past it after a frame that runs over it), or
    /// `Err(s)` to wait at `s` (nothing buffered). Out of line: the packet loop calls `on` in
    /// one place only, where the compiler can inline it.
    #[inline(never)]
    fn gap_in_place<F: FnMut(Event<'_>)>(
        &mut self,
        data: &[u8],
        mut pos: usize,
        to: usize,
        on: &mut F,
    ) -> Result<usize, usize> {
        if FOREIGN_NMEA || FOREIGN_RTCM3 {
            while let Some(k) = data[pos..to].iter().position(|&b| foreign_start(b)) {
                let s = pos + k;
                self.skip_in_place(k);
                match foreign_frame(&data[s..]) {
                    Foreign::Wait => return Err(s),
                    Foreign::Frame(n) => {
                        self.emit_skip(on);
                        on(foreign_event(self.base, &data[s..s + n]));
                        self.base += n as u64;
                        pos = s + n;
                        if pos >= to {
                            return Ok(pos);
                        }
                    }
                    Foreign::Not => {
                        self.skip_in_place(1);
                        pos = s + 1;
                    }
                }
            }
        }
        self.skip_in_place(to - pos);
        Ok(to)
    }

    /// Adds `n` bytes at the parser's offset to the skip run (nothing buffered).
    fn skip_in_place(&mut self, n: usize) {
        if n == 0 {
            return;
        }
        if self.skip_count == 0 {
            self.skip_start = self.base;
        }
        self.skip_count += n as u64;
        self.base += n as u64;
    }

    /// End of input: the same search, but a candidate packet that would wait for more input is
    /// a false sync (one byte skipped, search continues), so a packet behind a false sync whose
    /// length runs past the end is still found. Reports the remaining events, including the
    /// last skip run.
    pub fn flush<F: FnMut(Event<'_>)>(&mut self, mut on: F) {
        self.process(&mut on, true);
        self.emit_skip(&mut on);
    }

    fn find_sync(&self) -> Sync {
        let mut i = 0;
        while i < self.len {
            let n = (self.len - i).min(SYNC.len());
            if self.buf[i..i + n] == SYNC[..n] {
                if n == SYNC.len() {
                    return Sync::Full(i);
                }
                return Sync::Partial(i);
            }
            i += 1;
        }
        Sync::Partial(self.len)
    }

    /// Runs the search of `docs/conformance.md` §1 over the buffered bytes. Where it would wait
    /// for more input it returns, unless `at_end`: then the candidate's first byte is skipped.
    fn process<F: FnMut(Event<'_>)>(&mut self, on: &mut F, at_end: bool) {
        loop {
            if FOREIGN_NMEA || FOREIGN_RTCM3 {
                let gap = match self.find_sync() {
                    Sync::Full(i) | Sync::Partial(i) => i,
                };
                if let Some(s) = self.buf[..gap].iter().position(|&b| foreign_start(b)) {
                    self.skip(s);
                    match foreign_frame(&self.buf[..self.len]) {
                        Foreign::Wait if !at_end => return,
                        Foreign::Frame(n) => {
                            self.emit_skip(on);
                            on(foreign_event(self.base, &self.buf[..n]));
                            self.consume(n);
                        }
                        _ => self.skip(1),
                    }
                    continue;
                }
            }
            let start = match self.find_sync() {
                Sync::Full(i) => i,
                Sync::Partial(i) => {
                    self.skip(i);
                    if at_end && self.len > 0 {
                        self.skip(1);
                        continue;
                    }
                    return;
                }
            };
            self.skip(start);
            if self.len < HEADER_SIZE {
                if at_end {
                    self.skip(1);
                    continue;
                }
                return;
            }
            let payload = usize::from(self.buf[LENGTH_OFFSET]);
            if payload > MAX_PAYLOAD {
                self.skip(1);
                continue;
            }
            let total = HEADER_SIZE + payload + CHECKSUM_SIZE;
            if self.len < total {
                if at_end {
                    self.skip(1);
                    continue;
                }
                return;
            }
            let body = HEADER_SIZE + payload;
            if checksum_matches(&self.buf[..body], &self.buf[body..total]) {
                self.emit_skip(on);
                on(Event::Packet {
                    offset: self.base,
                    bytes: &self.buf[..total],
                });
                self.consume(total);
            } else {
                // The sync was false: resynchronise at the next byte.
                self.skip(1);
            }
        }
    }

    fn skip(&mut self, n: usize) {
        if n == 0 {
            return;
        }
        if self.skip_count == 0 {
            self.skip_start = self.base;
        }
        self.skip_count += n as u64;
        self.consume(n);
    }

    fn consume(&mut self, n: usize) {
        self.buf.copy_within(n..self.len, 0);
        self.len -= n;
        self.base += n as u64;
    }

    #[inline(always)]
    fn emit_skip<F: FnMut(Event<'_>)>(&mut self, on: &mut F) {
        if self.skip_count > 0 {
            self.report_skip(on);
        }
    }

    /// Reports the skip run (out of line: the packet loop then calls `on` in one place only,
    /// where the compiler can inline it).
    #[inline(never)]
    fn report_skip<F: FnMut(Event<'_>)>(&mut self, on: &mut F) {
        on(Event::Skip {
            offset: self.skip_start,
            count: self.skip_count,
        });
        self.skip_count = 0;
    }
}
