//! `democodec-decode [--device ID] [--samples] [FILE|-]`: reads a binary stream (FILE, or stdin when
//! FILE is absent or `-`) and prints the canonical JSON lines of `docs/conformance.md` §4.
//! Exit status: 0, or 2 for usage and I/O errors (one line on stderr).

use std::io::{self, Read, Write};
use std::process::ExitCode;

use democodec::text::StreamDecoder;
use democodec::Device;

const PROG: &str = "democodec-decode";

fn usage_error(message: &str) -> ExitCode {
    eprintln!("{PROG}: {message} (usage: {PROG} [--device ID] [--samples] [FILE|-])");
    ExitCode::from(2)
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
        None | Some("-") => ("stdin".to_string(), Box::new(io::stdin().lock())),
        Some(path) => match std::fs::File::open(path) {
            Ok(f) => (path.to_string(), Box::new(f)),
            Err(e) => {
                eprintln!("{PROG}: cannot open {path}: {e}");
                return ExitCode::from(2);
            }
        },
    };
    let stdout = io::stdout();
    let mut out = io::BufWriter::new(stdout.lock());
    let mut decoder = StreamDecoder::new(device);
    if samples {
        decoder = decoder.with_samples();
    }
    let mut buf = vec![0u8; 1 << 16];
    let mut text = String::new();
    loop {
        let n = match input.read(&mut buf) {
            Ok(0) => break,
            Ok(n) => n,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
            Err(e) => {
                let _ = out.flush();
                eprintln!("{PROG}: cannot read {name}: {e}");
                return ExitCode::from(2);
            }
        };
        text.clear();
        decoder.feed(&buf[..n], &mut text);
        if let Err(e) = out.write_all(text.as_bytes()) {
            eprintln!("{PROG}: cannot write: {e}");
            return ExitCode::from(2);
        }
    }
    text.clear();
    decoder.finish(&mut text);
    if let Err(e) = out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        eprintln!("{PROG}: cannot write: {e}");
        return ExitCode::from(2);
    }
    ExitCode::SUCCESS
}
