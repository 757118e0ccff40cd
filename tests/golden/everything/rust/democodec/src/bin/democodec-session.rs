//! `democodec-session --connect ADDRESS [--timeout-ms N] [--device ID] [--baud N]`: the session
//! conformance tool (`docs/conformance.md` §8). Reads command packets as canonical JSON lines on
//! stdin, runs them in order over the connection (`tcp:HOST:PORT`, an IPv6 host in brackets, or a
//! serial port path with the `serial` feature) and prints one result line per command; every
//! other packet received and every skip run is printed as its canonical line, in arrival order.
//! Exit status: 0 when every line ran, 1 when a line was bad (reported on stderr with its number
//! and skipped), 2 for usage and connection errors.

use std::io::{self, BufRead, Write};
use std::process::ExitCode;
use std::time::{Duration, Instant};

use democodec::device::{command_from_line, open_transport, Transport, DEFAULT_BAUD};
use democodec::dispatch::{write_packet_json, write_skip_json};
use democodec::session::{Session, SessionEvent, StartOptions, DEFAULT_TIMEOUT_MS};
use democodec::Device;

const PROG: &str = "democodec-session";
const USAGE: &str = "usage: session --connect ADDRESS [--timeout-ms N] [--device ID] [--baud N]";

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
}

fn options(args: &[String]) -> Result<Options, String> {
    let mut connect = None;
    let mut timeout_ms = DEFAULT_TIMEOUT_MS;
    let mut device = None;
    let mut baud = DEFAULT_BAUD;
    let mut i = 0;
    while i < args.len() {
        let a = args[i].as_str();
        let (name, inline) = match a.split_once('=') {
            Some((n, v)) => (n, Some(v.to_string())),
            None => (a, None),
        };
        if !matches!(name, "--connect" | "--timeout-ms" | "--device" | "--baud") {
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

fn run(o: Options) -> Result<ExitCode, String> {
    let mut transport = open_transport(&o.connect, o.baud).map_err(|e| e.to_string())?;
    let mut session: Session<1> = Session::new(o.device).with_timeout_ms(o.timeout_ms);
    let t0 = Instant::now();
    let now = || u64::try_from(t0.elapsed().as_millis()).unwrap_or(u64::MAX);
    let mut p = Printer {
        device: o.device,
        line: 0,
        hist: Vec::new(),
        hist_base: 0,
        text: String::new(),
    };
    let mut buf = vec![0u8; 4096];
    let mut status = ExitCode::SUCCESS;
    let stdin = io::stdin();
    let mut input = stdin.lock();
    let mut raw = Vec::new();
    let io_err = |e: io::Error| democodec::device::io_message(&e);
    loop {
        raw.clear();
        match input.read_until(b'\n', &mut raw) {
            Ok(0) => break,
            Ok(_) => {}
            Err(e) => return Err(format!("cannot read standard input: {}", io_err(e))),
        }
        p.line += 1;
        let Ok(text) = std::str::from_utf8(&raw) else {
            eprintln!("{PROG}: line {}: not UTF-8", p.line);
            status = ExitCode::from(1);
            continue;
        };
        if text.trim().is_empty() {
            continue;
        }
        let command = match command_from_line(text.trim_end_matches(['\n', '\r'])) {
            Ok(c) => c,
            Err(e) => {
                eprintln!("{PROG}: line {}: {e}", p.line);
                status = ExitCode::from(1);
                continue;
            }
        };
        let started = session
            .start(&command, now(), StartOptions::default())
            .map_err(|e| format!("line {}: {e}", p.line))?;
        if !started.packet.is_empty() {
            transport.send(started.packet).map_err(io_err)?;
        }
        if let Some(r) = started.result {
            p.event(SessionEvent::Result(r));
            p.flush().map_err(io_err)?;
            continue;
        }
        let (id, deadline) = (started.id, started.deadline);
        while session.is_pending(id) {
            let wake = session.next_deadline().unwrap_or(deadline);
            let n = transport
                .receive(&mut buf, Duration::from_millis(wake.saturating_sub(now())))
                .map_err(io_err)?;
            p.hist.extend_from_slice(&buf[..n]);
            session.feed(&buf[..n], now(), |e| p.event(e));
            p.flush().map_err(io_err)?;
        }
    }
    session.close(now(), |e| p.event(e));
    p.flush().map_err(io_err)?;
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
