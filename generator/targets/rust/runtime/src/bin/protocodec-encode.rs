//! `protocodec-encode`: reads JSON lines (as printed by `protocodec-decode`) on stdin and
//! writes the bytes on stdout: packets rebuilt from their fields with payload length and
//! checksum recomputed, skip runs as their bytes. Blank lines are ignored.
//! Exit status: 0; 1 for bad input (a bad line writes nothing and is reported as `line N: ...`
//! on stderr; the other lines are still encoded, as in the C, C++ and Python encoders); 2 for
//! usage and I/O errors (one line on stderr; a closed pipe on stdout ends it by SIGPIPE).

use std::io::{self, BufRead, Read, Write};
use std::process::ExitCode;

use protocodec::text::encode_line;

const PROG: &str = "protocodec-encode";

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

/// RFC 8259 whitespace only: a line of nothing else is blank.
fn blank(line: &[u8]) -> bool {
    line.iter()
        .all(|b| matches!(b, b' ' | b'\t' | b'\r' | b'\n'))
}

fn main() -> ExitCode {
    if let Some(arg) = std::env::args().nth(1) {
        if arg == "-h" || arg == "--help" {
            println!("usage: {PROG} < lines.jsonl > stream.bin");
            return ExitCode::SUCCESS;
        }
        eprintln!("{PROG}: unexpected argument '{arg}' (usage: {PROG} < lines.jsonl > stream.bin)");
        return ExitCode::from(2);
    }
    let mut input = match input() {
        Ok(r) => io::BufReader::with_capacity(1 << 16, r),
        Err(e) => {
            eprintln!("{PROG}: cannot read standard input: {}", io_message(&e));
            return ExitCode::from(2);
        }
    };
    let (stdout, is_file) = match output() {
        Ok(o) => o,
        Err(e) => return write_error(&e),
    };
    let mut out = io::BufWriter::with_capacity(1 << 16, stdout);
    let mut raw = Vec::new();
    let mut number = 0usize;
    let mut bad_lines = false;
    loop {
        raw.clear();
        match input.read_until(b'\n', &mut raw) {
            Ok(0) => break,
            Ok(_) => {}
            Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
            Err(e) => {
                if let Err(w) = out.flush() {
                    return write_error(&w);
                }
                eprintln!("{PROG}: cannot read standard input: {}", io_message(&e));
                return ExitCode::from(2);
            }
        }
        number += 1;
        if blank(&raw) {
            continue;
        }
        let result = match std::str::from_utf8(&raw) {
            Ok(line) => encode_line(line).map_err(|e| e.to_string()),
            Err(_) => Err("the line is not valid UTF-8".to_string()),
        };
        match result {
            Ok(bytes) => {
                if let Err(e) = out.write_all(&bytes) {
                    return write_error(&e);
                }
            }
            Err(message) => {
                eprintln!("{PROG}: line {number}: {message}");
                bad_lines = true;
            }
        }
        // What has arrived is written at once when stdout is a pipe or a terminal.
        if !is_file && input.buffer().is_empty() {
            if let Err(e) = out.flush() {
                return write_error(&e);
            }
        }
    }
    if let Err(e) = out.flush() {
        return write_error(&e);
    }
    if bad_lines {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}
