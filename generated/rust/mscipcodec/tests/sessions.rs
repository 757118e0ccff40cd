//! The session corpus (tests/sessions/mscip/, `docs/conformance.md` §8) through the
//! sans-I/O session core, by the runner rule: before each step, `poll` at every wake-up the
//! session reports up to the step's time; then `start` the command or `feed` the bytes; at the
//! end, poll while commands are pending, then `close`. Each `receive` is also fed split at every
//! position (two feeds at the same time), with the same lines.

use std::fmt::Write;

use mscipcodec::device::command_from_line;
use mscipcodec::dispatch::{write_foreign_json, write_packet_json, write_skip_json};
use mscipcodec::session::{Session, SessionEvent, StartOptions};
use mscipcodec::Device;

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

/// `ping_ack`
#[test]
fn session_ping_ack() {
    check(
        None,
        1000,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}", bytes: Some("a5a5010202004f25") },
            Step::Receive { at: 5, hex: "a5a5010480020200d3cf" },
        ],
        &[
            "{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[]}",
        ],
    );
}

/// `reply_with_data_field`
#[test]
fn session_reply_with_data_field() {
    check(
        None,
        1000,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":5,\"name\":\"get_device_model\",\"values\":{}}]}", bytes: Some("a5a501020500522b") },
            Step::Receive { at: 5, hex: "a5a501168002050085102020202020204d535f494d5533303230ec54" },
        ],
        &[
            "{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[{\"descriptor\":133,\"name\":\"device_model\",\"values\":{\"model\":\"      MS_IMU3020\"}}]}",
        ],
    );
}

/// `nack_with_every_error_code`
#[test]
fn session_nack_with_every_error_code() {
    check(
        None,
        1000,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 1, hex: "a5a5010480020201d4d0" },
            Step::Send { at: 1, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 2, hex: "a5a5010480020202d5d1" },
            Step::Send { at: 2, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 3, hex: "a5a5010480020203d6d2" },
            Step::Send { at: 3, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 4, hex: "a5a5010480020204d7d3" },
        ],
        &[
            "{\"line\":1,\"result\":\"nack\",\"code\":1,\"reply\":[]}",
            "{\"line\":2,\"result\":\"nack\",\"code\":2,\"reply\":[]}",
            "{\"line\":3,\"result\":\"nack\",\"code\":3,\"reply\":[]}",
            "{\"line\":4,\"result\":\"nack\",\"code\":4,\"reply\":[]}",
        ],
    );
}

/// `data_garbage_and_another_reply_before_the_answer`
#[test]
fn session_data_garbage_and_another_reply_before_the_answer() {
    check(
        None,
        1000,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 2, hex: "00a501a5a5a20e810c37a7c5ac377ba8823f800065d61a" },
            Step::Receive { at: 3, hex: "a5a5020480020200d4d5" },
            Step::Receive { at: 4, hex: "a5a5010480020200d3cf" },
        ],
        &[
            "{\"offset\":0,\"skipped\":\"00a501\"}",
            "{\"offset\":3,\"set\":162,\"fields\":[{\"descriptor\":129,\"name\":\"scaled_accel\",\"values\":{\"accel\":[1.9999999494757503e-05,1.4999999621068127e-05,1.0000120401382446]}}]}",
            "{\"offset\":23,\"set\":2,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":2,\"error_code\":0}}]}",
            "{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[]}",
        ],
    );
}

/// `reply_field_that_does_not_decode`
#[test]
fn session_reply_field_that_does_not_decode() {
    check(
        None,
        1000,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":5,\"name\":\"get_device_model\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 5, hex: "a5a5010a80020500850420202020e58d" },
        ],
        &[
            "{\"line\":1,\"result\":\"invalid\",\"code\":0,\"reply\":[{\"descriptor\":133,\"data\":\"20202020\",\"error\":\"model: needs 16 bytes at offset 0, 4 left\"}],\"error\":\"model: needs 16 bytes at offset 0, 4 left\"}",
        ],
    );
}

/// `late_reply_after_a_timeout`
#[test]
fn session_late_reply_after_a_timeout() {
    check(
        None,
        150,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Send { at: 150, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":5,\"name\":\"get_device_model\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 200, hex: "a5a5010480020200d3cf" },
            Step::Receive { at: 210, hex: "a5a501168002050085102020202020204d535f494d5533303230ec54" },
        ],
        &[
            "{\"line\":1,\"result\":\"timeout\",\"code\":null,\"reply\":[]}",
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":128,\"name\":\"ack\",\"values\":{\"command_code\":2,\"error_code\":0}}]}",
            "{\"line\":2,\"result\":\"ack\",\"code\":0,\"reply\":[{\"descriptor\":133,\"name\":\"device_model\",\"values\":{\"model\":\"      MS_IMU3020\"}}]}",
        ],
    );
}

/// `false_sync_dropped_by_the_timed_rule`
#[test]
fn session_false_sync_dropped_by_the_timed_rule() {
    check(
        None,
        1000,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 5, hex: "a5a501f0a5a5010480020200d3cf" },
        ],
        &[
            "{\"offset\":0,\"skipped\":\"a5a501f0\"}",
            "{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[]}",
        ],
    );
}
