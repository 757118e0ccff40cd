//! The session corpus (tests/sessions/mip/, `docs/conformance.md` §8) through the
//! sans-I/O session core, by the runner rule: before each step, `poll` at every wake-up the
//! session reports up to the step's time; then `start` the command or `feed` the bytes; at the
//! end, poll while commands are pending, then `close`. Each `receive` is also fed split at every
//! position (two feeds at the same time), with the same lines.

use std::fmt::Write;

use mipcodec::device::command_from_line;
use mipcodec::dispatch::{write_foreign_json, write_packet_json, write_skip_json};
use mipcodec::session::{Session, SessionEvent, StartOptions};
use mipcodec::Device;

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
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}", bytes: Some("756501020201e0c6") },
            Step::Receive { at: 5, hex: "7565010404f10100d56a" },
        ],
        &[
            "{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[]}",
        ],
    );
}

/// `read_with_reply_field`
#[test]
fn session_read_with_reply_field() {
    check(
        Some("cv7_ins"),
        1000,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":49,\"name\":\"sensor_to_vehicle_euler\",\"values\":{\"function\":2}}]}", bytes: Some("75650c030331021f46") },
            Step::Receive { at: 7, hex: "75650c1204f131000eb1000000003fc90ff93fc90ff9fdd3" },
        ],
        &[
            "{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[{\"descriptor\":177,\"name\":\"sensor_to_vehicle_euler_response\",\"values\":{\"roll\":0.0,\"pitch\":1.5707999467849731,\"yaw\":1.5707999467849731}}]}",
        ],
    );
}

/// `write_then_read`
#[test]
fn session_write_then_read() {
    check(
        Some("cv7_ins"),
        1000,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":49,\"name\":\"sensor_to_vehicle_euler\",\"values\":{\"function\":1,\"roll\":0.0,\"pitch\":1.5707999467849731,\"yaw\":1.5707999467849731}}]}", bytes: Some("75650c0f0f3101000000003fc90ff93fc90ff9563d") },
            Step::Receive { at: 4, hex: "75650c0404f13100100c" },
            Step::Send { at: 4, line: "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":49,\"name\":\"sensor_to_vehicle_euler\",\"values\":{\"function\":2}}]}", bytes: None },
            Step::Receive { at: 9, hex: "75650c1204f131000eb1000000003fc90ff93fc90ff9fdd3" },
        ],
        &[
            "{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[]}",
            "{\"line\":2,\"result\":\"ack\",\"code\":0,\"reply\":[{\"descriptor\":177,\"name\":\"sensor_to_vehicle_euler_response\",\"values\":{\"roll\":0.0,\"pitch\":1.5707999467849731,\"yaw\":1.5707999467849731}}]}",
        ],
    );
}

/// `garbage_and_data_around_the_reply`
#[test]
fn session_garbage_and_data_around_the_reply() {
    check(
        None,
        1000,
        100,
        &[
            Step::Receive { at: 0, hex: "00117522" },
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 2, hex: "7565800e0e040000000000000000bf800000b935aa" },
            Step::Receive { at: 4, hex: "7565010404f10100d56a" },
        ],
        &[
            "{\"offset\":0,\"skipped\":\"00117522\"}",
            "{\"offset\":4,\"set\":128,\"fields\":[{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[0.0,0.0,-1.0]}}]}",
            "{\"offset\":24,\"skipped\":\"aa\"}",
            "{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[]}",
        ],
    );
}

/// `reply_for_another_command`
#[test]
fn session_reply_for_another_command() {
    check(
        None,
        1000,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 3, hex: "7565010404f10200d66c" },
            Step::Receive { at: 4, hex: "75650c0404f10100e0ac" },
            Step::Receive { at: 5, hex: "7565010404f10100d56a" },
        ],
        &[
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":2,\"ack_code\":0}}]}",
            "{\"offset\":10,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":1,\"ack_code\":0}}]}",
            "{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[]}",
        ],
    );
}

/// `late_reply_after_a_timeout`
#[test]
fn session_late_reply_after_a_timeout() {
    check(
        None,
        200,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Send { at: 200, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"set_to_idle\",\"values\":{}}]}", bytes: Some("756501020202e1c7") },
            Step::Receive { at: 250, hex: "7565010404f10100d56a" },
            Step::Receive { at: 260, hex: "7565010404f10200d66c" },
        ],
        &[
            "{\"line\":1,\"result\":\"timeout\",\"code\":null,\"reply\":[]}",
            "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":1,\"ack_code\":0}}]}",
            "{\"line\":2,\"result\":\"ack\",\"code\":0,\"reply\":[]}",
        ],
    );
}

/// `nack_with_every_code`
#[test]
fn session_nack_with_every_code() {
    check(
        None,
        1000,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 1, hex: "7565010404f10101d66b" },
            Step::Send { at: 1, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 2, hex: "7565010404f10102d76c" },
            Step::Send { at: 2, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 3, hex: "7565010404f10103d86d" },
            Step::Send { at: 3, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 4, hex: "7565010404f10104d96e" },
            Step::Send { at: 4, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 5, hex: "7565010404f10105da6f" },
            Step::Send { at: 5, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 6, hex: "7565010404f10106db70" },
            Step::Send { at: 6, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 7, hex: "7565010404f1017f54e9" },
        ],
        &[
            "{\"line\":1,\"result\":\"nack\",\"code\":1,\"reply\":[]}",
            "{\"line\":2,\"result\":\"nack\",\"code\":2,\"reply\":[]}",
            "{\"line\":3,\"result\":\"nack\",\"code\":3,\"reply\":[]}",
            "{\"line\":4,\"result\":\"nack\",\"code\":4,\"reply\":[]}",
            "{\"line\":5,\"result\":\"nack\",\"code\":5,\"reply\":[]}",
            "{\"line\":6,\"result\":\"nack\",\"code\":6,\"reply\":[]}",
            "{\"line\":7,\"result\":\"nack\",\"code\":127,\"reply\":[]}",
        ],
    );
}

/// `nack_of_a_read`
#[test]
fn session_nack_of_a_read() {
    check(
        Some("cv7_ins"),
        1000,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":49,\"name\":\"sensor_to_vehicle_euler\",\"values\":{\"function\":2}}]}", bytes: None },
            Step::Receive { at: 3, hex: "75650c0404f13103130f" },
        ],
        &[
            "{\"line\":1,\"result\":\"nack\",\"code\":3,\"reply\":[]}",
        ],
    );
}

/// `ack_suppressed_by_function`
#[test]
fn session_ack_suppressed_by_function() {
    check(
        Some("gx5_45"),
        1000,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":55,\"name\":\"accel_bias\",\"device\":\"gx5_45\",\"values\":{\"function\":6,\"bias\":[1.0,2.0,3.0]}}]}", bytes: Some("75650c0f0f37063f8000004000000040400000c0ea") },
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 5, hex: "7565010404f10100d56a" },
        ],
        &[
            "{\"line\":1,\"result\":\"sent\",\"code\":null,\"reply\":[]}",
            "{\"line\":2,\"result\":\"ack\",\"code\":0,\"reply\":[]}",
        ],
    );
}

/// `ack_suppressed_by_parameter`
#[test]
fn session_ack_suppressed_by_parameter() {
    check(
        Some("gx5_45"),
        1000,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":1,\"name\":\"poll_imu_data\",\"values\":{\"option\":1,\"num_descriptors\":0,\"descriptors\":[]}}]}", bytes: Some("75650c0404010100f0dc") },
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 3, hex: "7565800e0e040000000000000000bf800000b935" },
            Step::Receive { at: 5, hex: "7565010404f10100d56a" },
        ],
        &[
            "{\"line\":1,\"result\":\"sent\",\"code\":null,\"reply\":[]}",
            "{\"offset\":0,\"set\":128,\"fields\":[{\"descriptor\":4,\"name\":\"scaled_accel\",\"values\":{\"scaled_accel\":[0.0,0.0,-1.0]}}]}",
            "{\"line\":2,\"result\":\"ack\",\"code\":0,\"reply\":[]}",
        ],
    );
}

/// `refused_command_for_the_device`
#[test]
fn session_refused_command_for_the_device() {
    check(
        Some("gx5_45"),
        1000,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":49,\"name\":\"sensor_to_vehicle_euler\",\"values\":{\"function\":2}}]}", bytes: None },
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 5, hex: "7565010404f10100d56a" },
        ],
        &[
            "{\"line\":1,\"result\":\"refused\",\"code\":null,\"reply\":[],\"error\":\"sensor_to_vehicle_euler is not supported by 3DM-GX5-45 (3dm-gx5-45-dcp.txt)\"}",
            "{\"line\":2,\"result\":\"ack\",\"code\":0,\"reply\":[]}",
        ],
    );
}

/// `refused_function_for_the_device`
#[test]
fn session_refused_function_for_the_device() {
    check(
        Some("cv7_ins"),
        1000,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":48,\"name\":\"device_startup_settings\",\"device\":\"cv7_ins\",\"values\":{\"function\":2}}]}", bytes: None },
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":48,\"name\":\"device_startup_settings\",\"device\":\"cv7_ins\",\"values\":{\"function\":3}}]}", bytes: Some("75650c030330031f45") },
            Step::Receive { at: 20, hex: "75650c0404f130000f0a" },
        ],
        &[
            "{\"line\":1,\"result\":\"refused\",\"code\":null,\"reply\":[],\"error\":\"function read of device_startup_settings is not supported by 3DM-CV7-GNSS/INS (3dm-cv7-ins-docs.txt)\"}",
            "{\"line\":2,\"result\":\"ack\",\"code\":0,\"reply\":[]}",
        ],
    );
}

/// `reply_field_that_does_not_decode`
#[test]
fn session_reply_field_that_does_not_decode() {
    check(
        Some("cv7_ins"),
        1000,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":49,\"name\":\"sensor_to_vehicle_euler\",\"values\":{\"function\":2}}]}", bytes: None },
            Step::Receive { at: 3, hex: "75650c0e04f131000ab1000000003fc90ff9e54d" },
        ],
        &[
            "{\"line\":1,\"result\":\"invalid\",\"code\":0,\"reply\":[{\"descriptor\":177,\"data\":\"000000003fc90ff9\",\"error\":\"yaw: needs 4 bytes at offset 8, 0 left\"}],\"error\":\"yaw: needs 4 bytes at offset 8, 0 left\"}",
        ],
    );
}

/// `bad_field_header_after_the_ack`
#[test]
fn session_bad_field_header_after_the_ack() {
    check(
        Some("cv7_ins"),
        1000,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":49,\"name\":\"sensor_to_vehicle_euler\",\"values\":{\"function\":2}}]}", bytes: None },
            Step::Receive { at: 3, hex: "75650c0604f1310001b1c4ed" },
        ],
        &[
            "{\"line\":1,\"result\":\"invalid\",\"code\":0,\"reply\":[{\"trailing\":\"01b1\",\"error\":\"field length 1 at payload offset 4 is shorter than the field header\"}],\"error\":\"field length 1 at payload offset 4 is shorter than the field header\"}",
        ],
    );
}

/// `reply_field_missing`
#[test]
fn session_reply_field_missing() {
    check(
        Some("cv7_ins"),
        1000,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":49,\"name\":\"sensor_to_vehicle_euler\",\"values\":{\"function\":2}}]}", bytes: None },
            Step::Receive { at: 3, hex: "75650c0404f13100100c" },
        ],
        &[
            "{\"line\":1,\"result\":\"invalid\",\"code\":0,\"reply\":[],\"error\":\"missing reply field 177\"}",
        ],
    );
}

/// `long_command_allowance`
#[test]
fn session_long_command_allowance() {
    check(
        Some("cv7_ins"),
        300,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":57,\"name\":\"capture_gyro_bias\",\"values\":{\"averaging_time_ms\":1000}}]}", bytes: Some("75650c04043903e81270") },
            Step::Receive { at: 1100, hex: "75650c1204f139000e9b3a83126f00000000ba83126fcb11" },
            Step::Send { at: 1100, line: "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":48,\"name\":\"device_startup_settings\",\"device\":\"cv7_ins\",\"values\":{\"function\":3}}]}", bytes: None },
            Step::Receive { at: 2000, hex: "75650c0404f130000f0a" },
        ],
        &[
            "{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[{\"descriptor\":155,\"name\":\"gyro_bias_response\",\"values\":{\"bias\":[0.0010000000474974513,0.0,-0.0010000000474974513]}}]}",
            "{\"line\":2,\"result\":\"ack\",\"code\":0,\"reply\":[]}",
        ],
    );
}

/// `timeout_without_allowance`
#[test]
fn session_timeout_without_allowance() {
    check(
        Some("cv7_ins"),
        300,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":57,\"name\":\"capture_gyro_bias\",\"values\":{\"averaging_time_ms\":1000}}]}", bytes: None },
            Step::Receive { at: 1500, hex: "75650c1204f139000e9b3a83126f00000000ba83126fcb11" },
        ],
        &[
            "{\"line\":1,\"result\":\"timeout\",\"code\":null,\"reply\":[]}",
            "{\"offset\":0,\"set\":12,\"fields\":[{\"descriptor\":241,\"name\":\"ack_nack\",\"values\":{\"command_descriptor\":57,\"ack_code\":0}},{\"descriptor\":155,\"name\":\"gyro_bias_response\",\"values\":{\"bias\":[0.0010000000474974513,0.0,-0.0010000000474974513]}}]}",
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
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 5, hex: "756501f07565010404f10100d56a" },
        ],
        &[
            "{\"offset\":0,\"skipped\":\"756501f0\"}",
            "{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[]}",
        ],
    );
}

/// `false_sync_then_the_reply_later`
#[test]
fn session_false_sync_then_the_reply_later() {
    check(
        None,
        1000,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 5, hex: "756501f0" },
            Step::Receive { at: 60, hex: "7565010404f10100d56a" },
        ],
        &[
            "{\"offset\":0,\"skipped\":\"756501f0\"}",
            "{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[]}",
        ],
    );
}

/// `slow_reply_kept_waiting`
#[test]
fn session_slow_reply_kept_waiting() {
    check(
        None,
        500,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 5, hex: "7565010404" },
            Step::Receive { at: 300, hex: "f10100d56a" },
        ],
        &[
            "{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[]}",
        ],
    );
}

/// `false_sync_then_the_reply_after_the_inter_packet_timeout`
#[test]
fn session_false_sync_then_the_reply_after_the_inter_packet_timeout() {
    check(
        None,
        500,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 5, hex: "756501f0" },
            Step::Receive { at: 300, hex: "7565010404f10100d56a" },
        ],
        &[
            "{\"offset\":0,\"skipped\":\"756501f0\"}",
            "{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[]}",
        ],
    );
}

/// `false_sync_with_nothing_after_it_waits_for_close`
#[test]
fn session_false_sync_with_nothing_after_it_waits_for_close() {
    check(
        None,
        300,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 5, hex: "756501f0" },
        ],
        &[
            "{\"line\":1,\"result\":\"timeout\",\"code\":null,\"reply\":[]}",
            "{\"offset\":0,\"skipped\":\"756501f0\"}",
        ],
    );
}

/// `reply_byte_by_byte_within_the_timeout`
#[test]
fn session_reply_byte_by_byte_within_the_timeout() {
    check(
        None,
        1000,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 5, hex: "75" },
            Step::Receive { at: 10, hex: "65" },
            Step::Receive { at: 15, hex: "01" },
            Step::Receive { at: 20, hex: "04" },
            Step::Receive { at: 25, hex: "04" },
            Step::Receive { at: 30, hex: "f1" },
            Step::Receive { at: 35, hex: "01" },
            Step::Receive { at: 40, hex: "00" },
            Step::Receive { at: 45, hex: "d5" },
            Step::Receive { at: 50, hex: "6a" },
        ],
        &[
            "{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[]}",
        ],
    );
}

/// `two_pending_answered_out_of_order`
#[test]
fn session_two_pending_answered_out_of_order() {
    check(
        None,
        1000,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"set_to_idle\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 3, hex: "7565010404f10200d66c" },
            Step::Receive { at: 4, hex: "7565010404f10100d56a" },
        ],
        &[
            "{\"line\":2,\"result\":\"ack\",\"code\":0,\"reply\":[]}",
            "{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[]}",
        ],
    );
}

/// `one_packet_answers_two_commands`
#[test]
fn session_one_packet_answers_two_commands() {
    check(
        None,
        1000,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":2,\"name\":\"set_to_idle\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 3, hex: "7565010804f1010004f10200d0c9" },
        ],
        &[
            "{\"line\":1,\"result\":\"ack\",\"code\":0,\"reply\":[]}",
            "{\"line\":2,\"result\":\"ack\",\"code\":0,\"reply\":[]}",
        ],
    );
}

/// `same_command_twice_first_in_first_out`
#[test]
fn session_same_command_twice_first_in_first_out() {
    check(
        None,
        50,
        100,
        &[
            Step::Send { at: 0, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Send { at: 10, line: "{\"offset\":0,\"set\":1,\"fields\":[{\"descriptor\":1,\"name\":\"ping\",\"values\":{}}]}", bytes: None },
            Step::Receive { at: 20, hex: "7565010404f10101d66b" },
        ],
        &[
            "{\"line\":1,\"result\":\"nack\",\"code\":1,\"reply\":[]}",
            "{\"line\":2,\"result\":\"timeout\",\"code\":null,\"reply\":[]}",
        ],
    );
}
