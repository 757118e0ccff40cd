//! `protocodec-session --connect ADDRESS [--timeout-ms N] [--device ID] [--baud N] [--auto-baud]
//! [--reconnect-ms N]`: the session conformance tool (`docs/conformance.md` §8). Reads command
//! packets as canonical JSON lines on stdin, runs them in order over the connection
//! (`tcp:HOST:PORT`, an IPv6 host in brackets, or a serial port path with the `serial` feature)
//! and prints one result line per command; every other packet received and every skip run is
//! printed as its canonical line, in arrival order. Getting through (§8): `--auto-baud` finds the
//! baud rate of a serial port at connect, `--reconnect-ms N` reopens a lost port for up to N ms
//! and re-applies the settings written (a command lost with the port: result `lost`), the lines
//! `{"link":"idle"}` (the last attempt's result line) and `{"link":"listen","ms":M}` (receive
//! for M ms, then `{"line":N,"listened":M}`); each step is one `link: ...` line on stderr.
//! Input lines: blank lines (empty or only JSON whitespace: space, tab, CR) are skipped; a line
//! longer than 1048576 bytes or not UTF-8 is bad (read past in bounded memory). Options are
//! checked before anything is opened (`--timeout-ms` 1..600000, `--reconnect-ms` 1..3600000,
//! `--baud` one of the rates the protocol's devices list; the texts of the option table of
//! `docs/conformance.md` §8). Bounded: the bytes kept for the skip lines are fewer than a skip
//! piece and a packet, each read asks for at most 65536 bytes.
//! Exit status: 0 when every line ran, 1 when a line was bad (reported on stderr with its number
//! and skipped), 2 for usage and connection errors and when getting through failed.

use std::cell::RefCell;
use std::io::{self, BufRead, Write};
use std::process::ExitCode;
use std::rc::Rc;

use protocodec::device::{command_from_line, connect, SessionError, DEFAULT_BAUD};
use protocodec::dispatch::{write_foreign_json, write_packet_json, write_skip_json};
use protocodec::framing::MAX_PACKET;
use protocodec::json_read::{parse, Json};
use protocodec::session::{SessionEvent, StartOptions, DEFAULT_TIMEOUT_MS, SKIP_PIECE};
use protocodec::Device;

const PROG: &str = "protocodec-session";
const USAGE: &str = "usage: session --connect ADDRESS [--timeout-ms N] [--device ID] [--baud N] [--auto-baud] [--reconnect-ms N]";

fn usage_error(error: Usage) -> ExitCode {
    match error {
        Usage::Exact(text) => eprintln!("{PROG}: {text}"),
        Usage::WithUsage(text) => eprintln!("{PROG}: {text} ({USAGE})"),
    }
    ExitCode::from(2)
}

fn device_ids() -> String {
    Device::ALL
        .iter()
        .map(|d| d.id())
        .collect::<Vec<_>>()
        .join(", ")
}

/// An option's value: a decimal integer of ASCII digits only (no sign, no spaces; leading
/// zeros allowed) from `low` to `high` (`docs/conformance.md` §8, the option table).
fn int_option(name: &str, text: &str, low: u64, high: u64) -> Result<u64, Usage> {
    let digits = !text.is_empty() && text.bytes().all(|b| b.is_ascii_digit());
    match text.parse::<u64>() {
        Ok(v) if digits && (low..=high).contains(&v) => Ok(v),
        _ => Err(Usage::Exact(format!(
            "{name}: expected an integer from {low} to {high}, got {text}"
        ))),
    }
}

/// Largest `--timeout-ms`.
const MAX_TIMEOUT_MS: u64 = 600_000;
/// Largest `--reconnect-ms` and `"ms"` of a listen line.
const MAX_LINK_MS: u64 = 3_600_000;
/// Longest input line (bytes, without its newline).
const MAX_LINE: usize = 1 << 20;

/// The baud rates the protocol's devices list (the IR's `link.baud_rates` of every model),
/// ascending, each once.
fn baud_rates() -> Vec<u32> {
    let mut rates: Vec<u32> = Device::ALL
        .iter()
        .flat_map(|d| d.baud_rates().iter().copied())
        .collect();
    rates.sort_unstable();
    rates.dedup();
    rates
}

fn baud_option(text: &str) -> Result<u32, Usage> {
    let rates = baud_rates();
    let digits = !text.is_empty() && text.bytes().all(|b| b.is_ascii_digit());
    match text.parse::<u32>() {
        Ok(v) if digits && rates.contains(&v) => Ok(v),
        _ => Err(Usage::Exact(format!(
            "--baud: {text} is not a baud rate of {} devices ({})",
            protocodec::PROTOCOL,
            rates
                .iter()
                .map(u32::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        ))),
    }
}

/// A usage error: the option table's exact text, or a text followed by the usage.
enum Usage {
    Exact(String),
    WithUsage(String),
}

struct Options {
    connect: String,
    timeout_ms: u64,
    device: Option<Device>,
    baud: u32,
    auto_baud: bool,
    reconnect_ms: Option<u64>,
}

fn options(args: &[String]) -> Result<Options, Usage> {
    let mut connect = None;
    let mut timeout_ms = DEFAULT_TIMEOUT_MS;
    let mut device = None;
    let mut baud = DEFAULT_BAUD;
    let mut auto_baud = false;
    let mut reconnect_ms = None;
    let mut i = 0;
    while i < args.len() {
        let a = args[i].as_str();
        if a == "--auto-baud" {
            auto_baud = true;
            i += 1;
            continue;
        }
        let (name, inline) = match a.split_once('=') {
            Some((n, v)) => (n, Some(v.to_string())),
            None => (a, None),
        };
        if !matches!(
            name,
            "--connect" | "--timeout-ms" | "--device" | "--baud" | "--reconnect-ms"
        ) {
            return Err(Usage::WithUsage(format!("unknown argument '{a}'")));
        }
        let value = match inline {
            Some(v) => v,
            None => {
                i += 1;
                args.get(i)
                    .cloned()
                    .ok_or_else(|| Usage::WithUsage(format!("{name} needs a value")))?
            }
        };
        i += 1;
        match name {
            "--connect" => connect = Some(value),
            "--timeout-ms" => timeout_ms = int_option(name, &value, 1, MAX_TIMEOUT_MS)?,
            "--reconnect-ms" => reconnect_ms = Some(int_option(name, &value, 1, MAX_LINK_MS)?),
            "--baud" => baud = baud_option(&value)?,
            _ => {
                device = Some(Device::from_id(&value).ok_or_else(|| {
                    Usage::WithUsage(format!(
                        "unknown device '{value}' (one of: {})",
                        device_ids()
                    ))
                })?)
            }
        }
    }
    let connect = connect.ok_or_else(|| Usage::Exact("--connect ADDRESS is required".into()))?;
    Ok(Options {
        connect,
        timeout_ms,
        device,
        baud,
        auto_baud,
        reconnect_ms,
    })
}

/// Prints the events of the session: received bytes are kept from the end of the last event
/// on, for the skip lines.
struct Printer {
    device: Option<Device>,
    line: u64,
    hist: Vec<u8>,
    hist_base: u64,
    text: String,
}

impl Printer {
    fn event(&mut self, e: SessionEvent<'_>) {
        let t = &mut self.text;
        // Writing to a String cannot fail.
        let _ = match e {
            SessionEvent::Result(r) => r.write_line(t, self.line),
            SessionEvent::Packet { offset, packet } => {
                let r = write_packet_json(t, offset, &packet, self.device);
                self.trim(offset + packet.bytes().len() as u64);
                r
            }
            SessionEvent::Skip { offset, count } => {
                let from = usize::try_from(offset.saturating_sub(self.hist_base)).unwrap_or(0);
                let to = (from + count as usize).min(self.hist.len());
                let r = write_skip_json(t, offset, &self.hist[from.min(to)..to]);
                self.trim(offset + count);
                r
            }
            SessionEvent::Nmea { offset, bytes } | SessionEvent::Rtcm { offset, bytes } => {
                let r = write_foreign_json(t, offset, bytes);
                self.trim(offset + bytes.len() as u64);
                r
            }
        };
        self.text.push('\n');
    }

    fn trim(&mut self, upto: u64) {
        let n = usize::try_from(upto.saturating_sub(self.hist_base))
            .unwrap_or(0)
            .min(self.hist.len());
        self.hist.drain(..n);
        self.hist_base += n as u64;
    }

    fn flush(&mut self) -> io::Result<()> {
        let mut out = io::stdout().lock();
        out.write_all(self.text.as_bytes())?;
        self.text.clear();
        out.flush()
    }
}

/// What a link line asks for.
enum LinkLine {
    Idle,
    Listen(u64),
}

/// The link operation of an input line: `Ok(None)` when the line is not one, an error text when
/// it is a malformed link line.
fn link_line(text: &str) -> Result<Option<LinkLine>, String> {
    let Ok(Json::Object(members)) = parse(text) else {
        return Ok(None);
    };
    let Some((_, op)) = members.iter().find(|(k, _)| k == "link") else {
        return Ok(None);
    };
    let ms = members.iter().find(|(k, _)| k == "ms").map(|(_, v)| v);
    match (op, ms, members.len()) {
        (Json::String(op), None, 1) if op == "idle" => Ok(Some(LinkLine::Idle)),
        (Json::String(op), Some(ms), 2) if op == "listen" => match ms {
            Json::Number(n) => match n.parse::<u64>() {
                Ok(ms) if ms <= MAX_LINK_MS => Ok(Some(LinkLine::Listen(ms))),
                _ => Err(BAD_MS.to_string()),
            },
            _ => Err(BAD_MS.to_string()),
        },
        _ => Err(BAD_LINK.to_string()),
    }
}

const BAD_LINK: &str = "expected {\"link\":\"idle\"} or {\"link\":\"listen\",\"ms\":M}";
const BAD_MS: &str = "\"ms\" must be an integer from 0 to 3600000";

/// One line of standard input, read in bounded memory.
enum Line {
    /// The end of the input.
    End,
    /// A line (in the buffer, without its newline).
    Text,
    /// A line longer than [`MAX_LINE`] bytes (read past, not kept).
    TooLong,
}

/// Reads one line into `raw` (without its newline), never holding more than [`MAX_LINE`] bytes
/// of it: a longer line is read to its end and reported as [`Line::TooLong`].
fn read_line(input: &mut impl BufRead, raw: &mut Vec<u8>) -> io::Result<Line> {
    raw.clear();
    let mut any = false;
    let mut too_long = false;
    loop {
        let chunk = match input.fill_buf() {
            Ok(c) => c,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e),
        };
        if chunk.is_empty() {
            break;
        }
        any = true;
        let newline = chunk.iter().position(|&b| b == b'\n');
        let part = &chunk[..newline.unwrap_or(chunk.len())];
        if !too_long {
            if raw.len() + part.len() > MAX_LINE {
                too_long = true;
                raw.clear();
                raw.shrink_to(MAX_LINE);
            } else {
                raw.extend_from_slice(part);
            }
        }
        let used = newline.map_or(chunk.len(), |i| i + 1);
        input.consume(used);
        if newline.is_some() {
            break;
        }
    }
    Ok(match (any, too_long) {
        (false, _) => Line::End,
        (true, true) => Line::TooLong,
        (true, false) => Line::Text,
    })
}

/// Blank: empty or only JSON whitespace (space, tab, CR, LF; RFC 8259), nothing else.
fn is_blank(raw: &[u8]) -> bool {
    raw.iter()
        .all(|b| matches!(b, b' ' | b'\t' | b'\r' | b'\n'))
}

fn run(o: Options) -> Result<ExitCode, String> {
    let mut dev = connect(&o.connect, o.device, o.baud)
        .map_err(|e| e.to_string())?
        .with_timeout_ms(o.timeout_ms);
    if let Some(ms) = o.reconnect_ms {
        dev = dev.with_reconnect_ms(ms);
    }
    let p = Rc::new(RefCell::new(Printer {
        device: o.device,
        line: 0,
        hist: Vec::new(),
        hist_base: 0,
        text: String::new(),
    }));
    let printer = Rc::clone(&p);
    dev.on_bytes(move |bytes| {
        let mut p = printer.borrow_mut();
        // Bounded: the session reports every byte before its pending skip run (shorter than
        // SKIP_PIECE) and its undecided candidate (shorter than MAX_PACKET), so older bytes are
        // never printed.
        let keep = SKIP_PIECE as usize + MAX_PACKET;
        if p.hist.len() > keep {
            let upto = p.hist_base + (p.hist.len() - keep) as u64;
            p.trim(upto);
        }
        p.hist.extend_from_slice(bytes)
    });
    let printer = Rc::clone(&p);
    dev.on_event(move |e| {
        let mut p = printer.borrow_mut();
        p.event(*e);
        // A closed standard output ends the run at the next line read.
        let _ = p.flush();
    });
    dev.on_link(|line| eprintln!("{line}"));
    if o.auto_baud {
        dev.find_baud().map_err(|e| e.to_string())?;
    }
    let mut status = ExitCode::SUCCESS;
    let stdin = io::stdin();
    let mut input = stdin.lock();
    let mut raw = Vec::new();
    let io_err = |e: io::Error| protocodec::device::io_message(&e);
    let mut number = 0;
    loop {
        let line = read_line(&mut input, &mut raw)
            .map_err(|e| format!("cannot read standard input: {}", io_err(e)))?;
        if matches!(line, Line::End) {
            break;
        }
        number += 1;
        p.borrow_mut().line = number;
        if matches!(line, Line::TooLong) {
            eprintln!("{PROG}: line {number}: longer than {MAX_LINE} bytes");
            status = ExitCode::from(1);
            continue;
        }
        let Ok(text) = std::str::from_utf8(&raw) else {
            eprintln!("{PROG}: line {number}: not UTF-8");
            status = ExitCode::from(1);
            continue;
        };
        if is_blank(raw.as_slice()) {
            continue;
        }
        let text = text.trim_end_matches('\r');
        match link_line(text) {
            Ok(None) => {}
            Ok(Some(LinkLine::Idle)) => {
                let done = dev.to_idle().map_err(|e| e.to_string())?;
                let mut p = p.borrow_mut();
                // What was dropped meanwhile is never printed.
                p.trim(dev.retain_from());
                let _ = done.write_line(&mut p.text, number);
                p.text.push('\n');
                p.flush().map_err(io_err)?;
                continue;
            }
            Ok(Some(LinkLine::Listen(ms))) => {
                dev.listen(ms).map_err(|e| e.to_string())?;
                let mut p = p.borrow_mut();
                let line = format!("\"line\":{number},\"listened\":{ms}");
                p.text.push('{');
                p.text.push_str(&line);
                p.text.push_str("}\n");
                p.flush().map_err(io_err)?;
                continue;
            }
            Err(e) => {
                eprintln!("{PROG}: line {number}: {e}");
                status = ExitCode::from(1);
                continue;
            }
        }
        let command = match command_from_line(text) {
            Ok(c) => c,
            Err(e) => {
                eprintln!("{PROG}: line {number}: {e}");
                status = ExitCode::from(1);
                continue;
            }
        };
        match dev.run(&command, StartOptions::default()) {
            Ok(done) => {
                // the first unknown-command NACK: the connected model is another one
                if let Some(note) = &done.note {
                    eprintln!("{PROG}: {note}");
                }
            }
            Err(SessionError::Start(e)) => return Err(format!("line {number}: {e}")),
            Err(SessionError::LinkLost {
                reason, gave_up, ..
            }) => {
                let mut error = String::new();
                let lost = format!("link lost: {reason}");
                let _ = protocodec::json::write_display(&mut error, &lost);
                let mut pr = p.borrow_mut();
                let line = format!(
                    "\"line\":{number},\"result\":\"lost\",\"code\":null,\"reply\":[],\"error\":{error}"
                );
                pr.text.push('{');
                pr.text.push_str(&line);
                pr.text.push_str("}\n");
                pr.flush().map_err(io_err)?;
                if let Some(m) = gave_up {
                    return Err(format!("link: {m}"));
                }
            }
            Err(e) => return Err(e.to_string()),
        }
        p.borrow_mut().flush().map_err(io_err)?;
    }
    dev.close();
    p.borrow_mut().flush().map_err(io_err)?;
    Ok(status)
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.iter().any(|a| a == "-h" || a == "--help") {
        println!("{USAGE}    (devices: {})", device_ids());
        return ExitCode::SUCCESS;
    }
    let o = match options(&args) {
        Ok(o) => o,
        Err(e) => return usage_error(e),
    };
    match run(o) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("{PROG}: {e}");
            ExitCode::from(2)
        }
    }
}
