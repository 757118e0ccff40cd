//! `protocodec-decode [--device ID] [--samples] [FILE|-]`: reads a binary stream (FILE, or stdin when
//! FILE is absent or `-`) and prints the canonical JSON lines of `docs/conformance.md` §4.
//! Exit status: 0, or 2 for usage and I/O errors (one line on stderr; a closed pipe on stdout
//! ends it by SIGPIPE). The input is read in blocks as it arrives and decoded in bounded memory;
//! when stdout is not a regular file, the lines of every block are flushed at once, so a live
//! stream shows each packet when it arrives.

use std::io::{self, Read, Write};
use std::process::ExitCode;

use protocodec::text::StreamDecoder;
use protocodec::Device;

const PROG: &str = "protocodec-decode";

fn usage_error(message: &str) -> ExitCode {
    eprintln!("{PROG}: {message} (usage: {PROG} [--device ID] [--samples] [FILE|-])");
    ExitCode::from(2)
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
        if let Err(e) = written.and_then(|()| if is_file { Ok(()) } else { out.flush() }) {
            return write_error(&e);
        }
    }
    text.clear();
    decoder.finish(&mut text);
    if let Err(e) = out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        return write_error(&e);
    }
    ExitCode::SUCCESS
}
