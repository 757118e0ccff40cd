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
//! Exit status: 0 when every line ran, 1 when a line was bad (reported on stderr with its number
//! and skipped), 2 for usage and connection errors and when getting through failed.

use std::cell::RefCell;
use std::io::{self, BufRead, Write};
use std::process::ExitCode;
use std::rc::Rc;

use protocodec::device::{command_from_line, connect, SessionError, DEFAULT_BAUD};
use protocodec::dispatch::{write_packet_json, write_skip_json};
use protocodec::json_read::{parse, Json};
use protocodec::session::{SessionEvent, StartOptions, DEFAULT_TIMEOUT_MS};
use protocodec::Device;

const PROG: &str = "protocodec-session";
const USAGE: &str = "usage: session --connect ADDRESS [--timeout-ms N] [--device ID] [--baud N] [--auto-baud] [--reconnect-ms N]";

fn usage_error(message: &str) -> ExitCode {
    eprintln!("{PROG}: {message} ({USAGE})");
    ExitCode::from(2)
}

fn device_ids() -> String {
    Device::ALL
        .iter()
        .map(|d| d.id())
        .collect::<Vec<_>>()
        .join(", ")
}

fn int_option(name: &str, text: &str, low: u64) -> Result<u64, String> {
    match text.parse::<u64>() {
        Ok(v) if v >= low && text.bytes().all(|b| b.is_ascii_digit()) => Ok(v),
        _ => Err(format!("{name} needs an integer >= {low}, not '{text}'")),
    }
}

struct Options {
    connect: String,
    timeout_ms: u64,
    device: Option<Device>,
    baud: u32,
    auto_baud: bool,
    reconnect_ms: Option<u64>,
}

fn options(args: &[String]) -> Result<Options, String> {
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
            return Err(format!("unknown argument '{a}'"));
        }
        let value = match inline {
            Some(v) => v,
            None => {
                i += 1;
                args.get(i)
                    .cloned()
                    .ok_or_else(|| format!("{name} needs a value"))?
            }
        };
        i += 1;
        match name {
            "--connect" => connect = Some(value),
            "--timeout-ms" => timeout_ms = int_option(name, &value, 0)?,
            "--reconnect-ms" => reconnect_ms = Some(int_option(name, &value, 0)?),
            "--baud" => {
                baud = u32::try_from(int_option(name, &value, 1)?)
                    .map_err(|_| format!("{name} needs an integer >= 1, not '{value}'"))?
            }
            _ => {
                device = Some(Device::from_id(&value).ok_or_else(|| {
                    format!("unknown device '{value}' (one of: {})", device_ids())
                })?)
            }
        }
    }
    let connect = connect.ok_or_else(|| "--connect ADDRESS is required".to_string())?;
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
        (Json::String(op), Some(Json::Number(n)), 2) if op == "listen" => match n.parse::<u64>() {
            Ok(ms) => Ok(Some(LinkLine::Listen(ms))),
            Err(_) => Err(BAD_LINK.to_string()),
        },
        _ => Err(BAD_LINK.to_string()),
    }
}

const BAD_LINK: &str = "expected {\"link\":\"idle\"} or {\"link\":\"listen\",\"ms\":M}";

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
    dev.on_bytes(move |bytes| printer.borrow_mut().hist.extend_from_slice(bytes));
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
        raw.clear();
        match input.read_until(b'\n', &mut raw) {
            Ok(0) => break,
            Ok(_) => {}
            Err(e) => return Err(format!("cannot read standard input: {}", io_err(e))),
        }
        number += 1;
        p.borrow_mut().line = number;
        let Ok(text) = std::str::from_utf8(&raw) else {
            eprintln!("{PROG}: line {number}: not UTF-8");
            status = ExitCode::from(1);
            continue;
        };
        let text = text.trim_end_matches(['\n', '\r']);
        if text.trim().is_empty() {
            continue;
        }
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
            Ok(_) => {}
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
        Err(e) => return usage_error(&e),
    };
    match run(o) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("{PROG}: {e}");
            ExitCode::from(2)
        }
    }
}
