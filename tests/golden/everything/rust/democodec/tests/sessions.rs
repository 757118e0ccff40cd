//! The session corpus (tests/sessions/demo/, `docs/conformance.md` §8) through the
//! sans-I/O session core, by the runner rule: before each step, `poll` at every wake-up the
//! session reports up to the step's time; then `start` the command or `feed` the bytes; at the
//! end, poll while commands are pending, then `close`. Each `receive` is also fed split at every
//! position (two feeds at the same time), with the same lines.
#![allow(dead_code)]

use std::fmt::Write;

use democodec::device::command_from_line;
use democodec::dispatch::{write_foreign_json, write_packet_json, write_skip_json};
use democodec::session::{Session, SessionEvent, StartOptions};
use democodec::Device;

enum Step {
    Send {
        at: u64,
        line: &'static str,
        bytes: Option<&'static str>,
    },
    Receive {
        at: u64,
        hex: &'static str,
    },
}

fn from_hex(hex: &str) -> Vec<u8> {
    (0..hex.len())
        .step_by(2)
        .map(|i| u8::from_str_radix(&hex[i..i + 2], 16).unwrap())
        .collect()
}

fn to_hex(bytes: &[u8]) -> String {
    bytes.iter().map(|b| format!("{b:02x}")).collect()
}

fn line(e: SessionEvent<'_>, hist: &[u8], lines: &[(u32, u64)], device: Option<Device>) -> String {
    let mut t = String::new();
    match e {
        SessionEvent::Result(r) => {
            let number = lines
                .iter()
                .find(|(id, _)| *id == r.id)
                .map(|(_, n)| *n)
                .expect("a started command");
            r.write_line(&mut t, number).unwrap();
        }
        SessionEvent::Packet { offset, packet } => {
            write_packet_json(&mut t, offset, &packet, device).unwrap()
        }
        SessionEvent::Skip { offset, count } => write_skip_json(
            &mut t,
            offset,
            &hist[offset as usize..(offset + count) as usize],
        )
        .unwrap(),
        SessionEvent::Nmea { offset, bytes } | SessionEvent::Rtcm { offset, bytes } => {
            write_foreign_json(&mut t, offset, bytes).unwrap()
        }
    }
    t
}

/// The lines the core reports for a case; `split` = (receive step index, position) feeds that
/// step in two parts at the same time.
fn run(
    device: Option<&str>,
    timeout_ms: u64,
    inter_ms: u64,
    steps: &[Step],
    split: Option<(usize, usize)>,
) -> Vec<String> {
    let device = device.map(|id| Device::from_id(id).expect("device of the case"));
    let mut s: Session = Session::new(device)
        .with_timeout_ms(timeout_ms)
        .with_inter_packet_timeout_ms(inter_ms);
    let mut out: Vec<String> = Vec::new();
    let mut hist: Vec<u8> = Vec::new();
    let mut lines: Vec<(u32, u64)> = Vec::new();
    let mut number = 0;
    let mut now = 0;
    for (k, step) in steps.iter().enumerate() {
        now = match step {
            Step::Send { at, .. } | Step::Receive { at, .. } => *at,
        };
        while let Some(d) = s.next_deadline().filter(|d| *d <= now) {
            s.poll(d, |e| out.push(line(e, &hist, &lines, device)));
        }
        match step {
            Step::Send {
                line: text, bytes, ..
            } => {
                number += 1;
                let command =
                    command_from_line(text).unwrap_or_else(|e| panic!("send {number}: {e}"));
                let started = s
                    .start(&command, now, StartOptions::default())
                    .expect("a command");
                lines.push((started.id, number));
                if let (Some(want), None) = (bytes, &started.result) {
                    assert_eq!(to_hex(started.packet), *want, "command {number} sent");
                }
                if let Some(r) = started.result {
                    out.push(line(SessionEvent::Result(r), &hist, &lines, device));
                }
            }
            Step::Receive { hex, .. } => {
                let data = from_hex(hex);
                hist.extend_from_slice(&data);
                let cut = match split {
                    Some((at, cut)) if at == k => cut,
                    _ => data.len(),
                };
                s.feed(&data[..cut], now, |e| {
                    out.push(line(e, &hist, &lines, device))
                });
                if cut < data.len() {
                    s.feed(&data[cut..], now, |e| {
                        out.push(line(e, &hist, &lines, device))
                    });
                }
            }
        }
    }
    while s.pending() > 0 {
        now = now.max(
            s.next_deadline()
                .expect("a deadline while commands are pending"),
        );
        s.poll(now, |e| out.push(line(e, &hist, &lines, device)));
    }
    s.close(now, |e| out.push(line(e, &hist, &lines, device)));
    out
}

fn check(device: Option<&str>, timeout_ms: u64, inter_ms: u64, steps: &[Step], expect: &[&str]) {
    let mut want = String::new();
    for l in expect {
        writeln!(want, "{l}").unwrap();
    }
    let text = |lines: Vec<String>| lines.iter().map(|l| format!("{l}\n")).collect::<String>();
    assert_eq!(
        text(run(device, timeout_ms, inter_ms, steps, None)),
        want,
        "whole"
    );
    for (k, step) in steps.iter().enumerate() {
        if let Step::Receive { hex, .. } = step {
            for cut in 1..hex.len() / 2 {
                assert_eq!(
                    text(run(device, timeout_ms, inter_ms, steps, Some((k, cut)))),
                    want,
                    "receive step {k} split at {cut}"
                );
            }
        }
    }
}
