//! `democodec-encode`: reads JSON lines (as printed by `democodec-decode`) on stdin and
//! writes the bytes on stdout: packets rebuilt from their fields with payload length and
//! checksum recomputed, skip runs as their bytes. Blank lines are ignored.
//! Exit status: 0; 1 for bad input (a bad line writes nothing and is reported as `line N: ...`
//! on stderr; the other lines are still encoded, as in the C, C++ and Python encoders); 2 for
//! usage and I/O errors.

use std::io::{self, BufRead, Write};
use std::process::ExitCode;

use democodec::text::encode_line;

const PROG: &str = "democodec-encode";

fn main() -> ExitCode {
    if let Some(arg) = std::env::args().nth(1) {
        if arg == "-h" || arg == "--help" {
            println!("usage: {PROG} < lines.jsonl > stream.bin");
            return ExitCode::SUCCESS;
        }
        eprintln!("{PROG}: unexpected argument '{arg}' (usage: {PROG} < lines.jsonl > stream.bin)");
        return ExitCode::from(2);
    }
    let stdin = io::stdin();
    let mut input = stdin.lock();
    let stdout = io::stdout();
    let mut out = io::BufWriter::new(stdout.lock());
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
                let _ = out.flush();
                eprintln!("{PROG}: cannot read stdin: {e}");
                return ExitCode::from(2);
            }
        }
        number += 1;
        let result = match std::str::from_utf8(&raw) {
            Ok(line) if line.trim().is_empty() => continue,
            Ok(line) => encode_line(line).map_err(|e| e.to_string()),
            Err(_) => Err("the line is not valid UTF-8".to_string()),
        };
        match result {
            Ok(bytes) => {
                if let Err(e) = out.write_all(&bytes) {
                    eprintln!("{PROG}: cannot write: {e}");
                    return ExitCode::from(2);
                }
            }
            Err(message) => {
                eprintln!("{PROG}: line {number}: {message}");
                bad_lines = true;
            }
        }
    }
    if let Err(e) = out.flush() {
        eprintln!("{PROG}: cannot write: {e}");
        return ExitCode::from(2);
    }
    if bad_lines {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}
