//! `mipcodec-decode [--device ID] [--samples] [--decoder general|straight|cached] [FILE|-]`: reads a
//! binary stream (FILE, or stdin when FILE is absent or `-`) and prints the canonical JSON lines of
//! `docs/conformance.md` §4. `--decoder straight` or `cached` decodes the data packets with
//! `packets::decode_packet` or a `packets::LayoutCache` (issue 38) and writes their typed members
//! with the same writer (the same lines: the conformance corpus checks those decoders with it); a
//! packet whose decoded fields and passed-on entries do not make up its entries ends it with
//! exit status 1.
//! Exit status: 0, or 2 for usage and I/O errors (one line on stderr; a closed pipe on stdout
//! ends it by SIGPIPE). The input is read in blocks as it arrives and decoded in bounded memory;
//! when stdout is not a regular file, the lines of every block are flushed at once, so a live
//! stream shows each packet when it arrives.

use std::io::{self, Read, Write};
use std::process::ExitCode;

use std::fmt::Write as _;

use mipcodec::dispatch::{write_field_json, write_foreign_json, write_skip_json};
use mipcodec::fields::{FieldItem, Packet};
use mipcodec::packets::{decode_packet, AnyPacket, LayoutCache};
use mipcodec::parser::{Event, Parser};
use mipcodec::samples::SampleTracker;
use mipcodec::text::StreamDecoder;
use mipcodec::{json, Device};

const PROG: &str = "mipcodec-decode";

fn usage_error(message: &str) -> ExitCode {
    eprintln!(
        "{PROG}: {message} (usage: {PROG} [--device ID] [--samples] [--decoder general|straight|cached] [FILE|-])"
    );
    ExitCode::from(2)
}

/// The lines of `StreamDecoder` with the data packets decoded by `decode_packet` (straight) or a
/// `LayoutCache` (cached): each decoded field written from its member (`AnyPacket::field`, the
/// value `decode_field` gives) by `FieldValue::write_json`, every entry the decoder passed on as
/// `write_packet_json` writes it.
struct TypedLines {
    parser: Parser,
    device: Option<Device>,
    samples: Option<SampleTracker>,
    cache: Option<LayoutCache>,
    any: Box<AnyPacket>,
    hist: Vec<u8>,
    hist_base: u64,
    /// Stream offset of the first packet the decoder did not cover.
    mismatch: Option<u64>,
}

/// An entry a decoder passed on, as it can be kept past the call (its bytes are a slice of the
/// packet): where its bytes start in the packet and their length, and its descriptor or, for
/// trailing bytes, its error's text.
#[derive(PartialEq)]
enum Kept {
    Field(usize, usize, u8),
    Trailing(usize, usize, String),
}

fn kept(packet: &[u8], item: &FieldItem<'_>) -> Kept {
    let at = |s: &[u8]| (s.as_ptr() as usize).wrapping_sub(packet.as_ptr() as usize);
    match item {
        FieldItem::Field { descriptor, data } => Kept::Field(at(data), data.len(), *descriptor),
        FieldItem::Trailing { bytes, error } => {
            Kept::Trailing(at(bytes), bytes.len(), error.to_string())
        }
    }
}

/// An entry as `write_packet_json` writes it.
fn write_item(out: &mut String, set: u8, item: &FieldItem<'_>, device: Option<Device>) {
    // Writing to a String cannot fail.
    let _ = match *item {
        FieldItem::Field { descriptor, data } => {
            write_field_json(out, set, descriptor, data, device)
        }
        FieldItem::Trailing { bytes, ref error } => (|| {
            out.write_str("{\"trailing\":\"")?;
            json::write_hex(out, bytes)?;
            out.write_str("\",\"error\":")?;
            json::write_display(out, error)?;
            out.write_char('}')
        })(),
    };
}

impl TypedLines {
    fn new(device: Option<Device>, samples: bool, cached: bool) -> Self {
        Self {
            parser: Parser::new(),
            device,
            samples: samples.then(SampleTracker::new),
            cache: cached.then(LayoutCache::new),
            any: Box::default(),
            hist: Vec::new(),
            hist_base: 0,
            mismatch: None,
        }
    }

    /// The packet's line from the decoder's result; false when the decoded fields and the
    /// entries passed on do not make up the packet's entries in order.
    fn write_packet(&mut self, out: &mut String, offset: u64, bytes: &[u8]) -> bool {
        let Some(packet) = Packet::new(bytes) else {
            return true;
        };
        let mut others: Vec<Kept> = Vec::new();
        let keep = |item: FieldItem<'_>| others.push(kept(bytes, &item));
        match self.cache.as_mut() {
            Some(cache) => cache.decode(bytes, &mut self.any, keep),
            None => decode_packet(bytes, &mut self.any, keep),
        };
        let decoded: &[u8] = self.any.index().map_or(&[], |i| i.descriptors());
        let set = packet.set();
        out.push('{');
        let _ = write!(out, "\"offset\":{offset},\"set\":{set}");
        let sample_at = out.len();
        out.push_str(",\"fields\":[");
        // The entries in packet order (the walk only places them): each is the next entry passed
        // on when it is that one, else the next decoded field, of its descriptor.
        let (mut passed, mut next) = (0, 0);
        for (i, item) in packet.fields().enumerate() {
            if i > 0 {
                out.push(',');
            }
            if passed < others.len() && others[passed] == kept(bytes, &item) {
                // the entry the decoder passed on (the same kind, bytes, descriptor or error)
                write_item(out, set, &item, self.device);
                passed += 1;
            } else if let FieldItem::Field { descriptor, .. } = item {
                match self.any.field(descriptor) {
                    Some(value) if decoded.get(next) == Some(&descriptor) => {
                        let _ = value.write_json(out);
                        next += 1;
                    }
                    _ => return false,
                }
            } else {
                return false;
            }
        }
        out.push_str("]}");
        if passed != others.len() || next != decoded.len() {
            return false;
        }
        if let Some(place) = self.samples.as_mut().and_then(|t| t.feed(&packet)) {
            out.insert_str(sample_at, &format!(",\"sample\":{}", place.number));
        }
        true
    }

    fn on_event(&mut self, out: &mut String, event: Event<'_>) {
        if self.mismatch.is_some() {
            return;
        }
        let start = out.len();
        match event {
            Event::Skip { offset, count } => {
                let at = (offset - self.hist_base) as usize;
                let _ = write_skip_json(out, offset, &self.hist[at..at + count as usize]);
            }
            Event::Nmea { offset, bytes } | Event::Rtcm { offset, bytes } => {
                let _ = write_foreign_json(out, offset, bytes);
            }
            Event::Packet { offset, bytes } => {
                if !self.write_packet(out, offset, bytes) {
                    out.truncate(start);
                    self.mismatch = Some(offset);
                    return;
                }
            }
        }
        out.push('\n');
    }

    fn feed(&mut self, chunk: &[u8], out: &mut String) {
        self.hist.extend_from_slice(chunk);
        let mut parser = std::mem::take(&mut self.parser);
        parser.feed(chunk, |event| self.on_event(out, event));
        self.parser = parser;
        self.trim();
    }

    fn finish(&mut self, out: &mut String) {
        let mut parser = std::mem::take(&mut self.parser);
        parser.flush(|event| self.on_event(out, event));
        self.parser = parser;
        self.trim();
    }

    fn trim(&mut self) {
        let keep = self.parser.retain_from();
        let drop = (keep - self.hist_base) as usize;
        if drop > 0 {
            self.hist.drain(..drop);
            self.hist_base = keep;
        }
    }
}

/// The general decoder or a typed one.
enum Lines {
    General(Box<StreamDecoder>),
    Typed(Box<TypedLines>, &'static str),
}

impl Lines {
    fn feed(&mut self, chunk: &[u8], out: &mut String) {
        match self {
            Lines::General(d) => d.feed(chunk, out),
            Lines::Typed(d, _) => d.feed(chunk, out),
        }
    }
    fn finish(&mut self, out: &mut String) {
        match self {
            Lines::General(d) => d.finish(out),
            Lines::Typed(d, _) => {
                if d.mismatch.is_none() {
                    d.finish(out)
                }
            }
        }
    }
    /// The decoder's name and the offset of the packet it did not cover.
    fn mismatch(&self) -> Option<(&'static str, u64)> {
        match self {
            Lines::General(_) => None,
            Lines::Typed(d, name) => d.mismatch.map(|at| (*name, at)),
        }
    }
}

fn mismatch_error(name: &str, at: u64) -> ExitCode {
    eprintln!(
        "{PROG}: the {name} decoder's fields and passed-on entries of the packet at offset {at} do not make up its entries"
    );
    ExitCode::from(1)
}

/// The one rule for I/O faults of the tools (docs/conformance.md §5): a closed pipe on stdout
/// ends the tool by SIGPIPE, quietly (the Unix convention, as C programs and `cat` do; Rust
/// ignores the signal, so it is restored and raised here); any other read or write error is one
/// line on stderr and exit status 2.
fn write_error(e: &io::Error) -> ExitCode {
    #[cfg(unix)]
    if e.kind() == io::ErrorKind::BrokenPipe {
        extern "C" {
            fn signal(signum: i32, handler: usize) -> usize;
            fn raise(signum: i32) -> i32;
        }
        const SIGPIPE: i32 = 13;
        const SIG_DFL: usize = 0;
        // SAFETY: restores the default action of SIGPIPE and raises it; nothing else runs.
        unsafe {
            signal(SIGPIPE, SIG_DFL);
            raise(SIGPIPE);
        }
    }
    eprintln!("{PROG}: cannot write standard output: {}", io_message(e));
    ExitCode::from(2)
}

/// The OS error text without Rust's " (os error N)" suffix, as the other languages print it.
fn io_message(e: &io::Error) -> String {
    let text = e.to_string();
    match text.find(" (os error ") {
        Some(at) => text[..at].to_string(),
        None => text,
    }
}

/// Standard output as a file of its own (Rust's `Stdout` treats a closed descriptor as a sink
/// and adds line buffering), and whether it is a regular file: otherwise (a pipe, a terminal)
/// what every block of input gave is flushed at once.
#[cfg(unix)]
fn output() -> io::Result<(Box<dyn Write>, bool)> {
    use std::os::unix::io::AsFd;
    let file = std::fs::File::from(io::stdout().as_fd().try_clone_to_owned()?);
    let is_file = file.metadata().map(|m| m.is_file()).unwrap_or(false);
    Ok((Box::new(file), is_file))
}

#[cfg(not(unix))]
fn output() -> io::Result<(Box<dyn Write>, bool)> {
    Ok((Box::new(io::stdout()), false))
}

/// Standard input as a file of its own: reads return what has arrived, and a closed
/// descriptor is an error, as in the other languages. Rust's runtime reopens a closed standard
/// descriptor on /dev/null, read-write, before `main`: that is what is recognised here (an
/// input redirected from /dev/null is opened read-only).
#[cfg(unix)]
fn input() -> io::Result<Box<dyn Read>> {
    use std::os::unix::fs::{FileTypeExt, MetadataExt};
    use std::os::unix::io::AsFd;
    extern "C" {
        fn fcntl(fd: i32, cmd: i32, ...) -> i32;
    }
    const F_GETFL: i32 = 3;
    const O_ACCMODE: i32 = 3;
    const O_RDWR: i32 = 2;
    let file = std::fs::File::from(io::stdin().as_fd().try_clone_to_owned()?);
    // SAFETY: F_GETFL only reads the flags of descriptor 0, which is open (it was just cloned).
    let flags = unsafe { fcntl(0, F_GETFL) };
    if flags >= 0 && flags & O_ACCMODE == O_RDWR {
        if let (Ok(ours), Ok(null)) = (file.metadata(), std::fs::metadata("/dev/null")) {
            if ours.rdev() == null.rdev() && ours.file_type().is_char_device() {
                return Err(io::Error::from_raw_os_error(9)); // EBADF: stdin was closed
            }
        }
    }
    Ok(Box::new(file))
}

#[cfg(not(unix))]
fn input() -> io::Result<Box<dyn Read>> {
    Ok(Box::new(io::stdin()))
}

fn device_ids() -> String {
    Device::ALL
        .iter()
        .map(|d| d.id())
        .collect::<Vec<_>>()
        .join(", ")
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut device: Option<Device> = None;
    let mut file: Option<String> = None;
    let mut samples = false;
    let mut decoder_name = "general";
    let mut i = 0;
    while i < args.len() {
        let arg = args[i].as_str();
        let id = if arg == "--device" {
            i += 1;
            match args.get(i) {
                Some(id) => Some(id.as_str()),
                None => return usage_error("--device needs a device ID"),
            }
        } else {
            arg.strip_prefix("--device=")
        };
        if let Some(id) = id {
            match Device::from_id(id) {
                Some(d) => device = Some(d),
                None => {
                    return usage_error(&format!(
                        "unknown device '{id}' (devices: {})",
                        device_ids()
                    ))
                }
            }
        } else if arg == "--decoder" || arg.starts_with("--decoder=") {
            let name = match arg.strip_prefix("--decoder=") {
                Some(name) => name,
                None => {
                    i += 1;
                    match args.get(i) {
                        Some(name) => name.as_str(),
                        None => return usage_error("--decoder needs general, straight or cached"),
                    }
                }
            };
            decoder_name = match name {
                "general" => "general",
                "straight" => "straight",
                "cached" => "cached",
                _ => {
                    return usage_error(&format!(
                        "unknown decoder '{name}' (expected general, straight or cached)"
                    ))
                }
            };
        } else if arg == "--samples" {
            samples = true;
        } else if arg == "-h" || arg == "--help" {
            println!(
                "usage: {PROG} [--device ID] [--samples] [FILE|-]    (devices: {})",
                device_ids()
            );
            return ExitCode::SUCCESS;
        } else if arg.starts_with('-') && arg != "-" {
            return usage_error(&format!("unknown option '{arg}'"));
        } else if file.is_some() {
            return usage_error("more than one FILE");
        } else {
            file = Some(arg.to_string());
        }
        i += 1;
    }
    let (name, mut input): (String, Box<dyn Read>) = match file.as_deref() {
        None | Some("-") => match input() {
            Ok(r) => ("standard input".to_string(), r),
            Err(e) => {
                eprintln!("{PROG}: cannot read standard input: {}", io_message(&e));
                return ExitCode::from(2);
            }
        },
        Some(path) => match std::fs::File::open(path) {
            Ok(f) => (format!("'{path}'"), Box::new(f)),
            Err(e) => {
                eprintln!("{PROG}: cannot open '{path}': {}", io_message(&e));
                return ExitCode::from(2);
            }
        },
    };
    let (stdout, is_file) = match output() {
        Ok(o) => o,
        Err(e) => return write_error(&e),
    };
    let mut out = io::BufWriter::with_capacity(1 << 16, stdout);
    let mut decoder = if decoder_name == "general" {
        let mut d = StreamDecoder::new(device);
        if samples {
            d = d.with_samples();
        }
        Lines::General(Box::new(d))
    } else {
        Lines::Typed(
            Box::new(TypedLines::new(device, samples, decoder_name == "cached")),
            decoder_name,
        )
    };
    let mut buf = vec![0u8; 1 << 16];
    let mut text = String::new();
    loop {
        let n = match input.read(&mut buf) {
            Ok(0) => break,
            Ok(n) => n,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
            Err(e) => {
                if let Err(w) = out.flush() {
                    return write_error(&w);
                }
                eprintln!("{PROG}: cannot read {name}: {}", io_message(&e));
                return ExitCode::from(2);
            }
        };
        text.clear();
        decoder.feed(&buf[..n], &mut text);
        let written = out.write_all(text.as_bytes());
        if let Some((name, at)) = decoder.mismatch() {
            if let Err(e) = written.and_then(|()| out.flush()) {
                return write_error(&e);
            }
            return mismatch_error(name, at);
        }
        if let Err(e) = written.and_then(|()| if is_file { Ok(()) } else { out.flush() }) {
            return write_error(&e);
        }
    }
    text.clear();
    decoder.finish(&mut text);
    if let Err(e) = out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        return write_error(&e);
    }
    if let Some((name, at)) = decoder.mismatch() {
        return mismatch_error(name, at);
    }
    ExitCode::SUCCESS
}
