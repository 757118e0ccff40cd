//! Unit tests of the session core (src/session.rs) against the test protocol rendered by the back
//! end from tests/runtime_specs/ (../Cargo.toml: `ping` on every device, `set_mode` on alpha only,
//! answered by the reserved ack field 0xF1): matching, nack, timeouts, routing of
//! data while a command waits, the timed inter-packet rule, the bounded queue, several acks in
//! one packet, invalid replies, chunking independence and hostile input. The spec-driven cases
//! (tests/sessions/) run in every generated crate (templates/rust/test_sessions.rs.j2).

use protocodec::builder::PacketBuilder;
use protocodec::commands::ACK_DESCRIPTOR as ACK;
use protocodec::framing::{HEADER_SIZE, LENGTH_OFFSET, SET_OFFSET, SYNC};
use protocodec::session::{Session, SessionEvent, StartOptions, Status};
use protocodec::wire::{Layout, Wire};
use protocodec::{control, sensor, Device, FieldValue};

const COMMAND_SET: u8 = control::SET;
const PING: u8 = <control::Ping as Layout>::DESCRIPTOR;
const DATA_SET: u8 = sensor::SET;
const READING: u8 = <sensor::Reading as Layout>::DESCRIPTOR;

fn ping() -> FieldValue {
    FieldValue::Control(control::SetField::Ping(control::Ping::ZERO))
}

fn packet(set: u8, fields: &[(u8, &[u8])]) -> Vec<u8> {
    let mut b = PacketBuilder::new(set);
    for (d, data) in fields {
        b.add_raw_field(*d, data).unwrap();
    }
    b.finish().to_vec()
}

fn ack(code: u8) -> Vec<u8> {
    packet(COMMAND_SET, &[(ACK, &[PING, code])])
}

fn data(count: u16) -> Vec<u8> {
    packet(
        DATA_SET,
        &[(READING, &[count as u8, (count >> 8) as u8, 0, 1])],
    )
}

/// Events as text: results as the tool's lines (line = command id), packets and skips.
fn text(e: SessionEvent<'_>) -> String {
    match e {
        SessionEvent::Result(r) => {
            let mut t = String::new();
            r.write_line(&mut t, u64::from(r.id)).unwrap();
            t
        }
        SessionEvent::Packet { offset, packet } => format!("packet {offset} set {}", packet.set()),
        SessionEvent::Skip { offset, count } => format!("skip {offset} {count}"),
    }
}

fn start<const N: usize>(s: &mut Session<N>, now: u64) -> (u32, Vec<u8>, Option<String>) {
    let st = s.start(&ping(), now, StartOptions::default()).unwrap();
    let line = st.result.map(|r| text(SessionEvent::Result(r)));
    (st.id, st.packet.to_vec(), line)
}

fn feed<const N: usize>(s: &mut Session<N>, bytes: &[u8], now: u64) -> Vec<String> {
    let mut out = Vec::new();
    s.feed(bytes, now, |e| out.push(text(e)));
    out
}

#[test]
fn ack_answers_the_command_and_data_is_routed_meanwhile() {
    let mut s: Session = Session::new(None);
    let (id, sent, done) = start(&mut s, 0);
    assert_eq!(sent, packet(COMMAND_SET, &[(PING, &[])]));
    assert_eq!((id, done), (1, None));
    assert_eq!(s.next_deadline(), Some(1000));
    let mut stream = data(7);
    stream.extend(ack(0));
    let want = vec![
        "packet 0 set 128".to_string(),
        r#"{"line":1,"result":"ack","code":0,"reply":[]}"#.to_string(),
    ];
    assert_eq!(feed(&mut s, &stream, 5), want);
    assert_eq!(s.pending(), 0);
    // Every split gives the same events.
    for cut in 1..stream.len() {
        let mut s: Session = Session::new(None);
        start(&mut s, 0);
        let mut got = feed(&mut s, &stream[..cut], 5);
        got.extend(feed(&mut s, &stream[cut..], 5));
        assert_eq!(got, want, "split at {cut}");
    }
}

#[test]
fn nack_timeout_and_late_reply() {
    let mut s: Session = Session::new(None).with_timeout_ms(50);
    start(&mut s, 0);
    assert_eq!(
        feed(&mut s, &ack(3), 10),
        [r#"{"line":1,"result":"nack","code":3,"reply":[]}"#]
    );
    start(&mut s, 100);
    let mut out = Vec::new();
    s.poll(149, |e| out.push(text(e)));
    assert!(out.is_empty());
    s.poll(150, |e| out.push(text(e)));
    assert_eq!(
        out,
        [r#"{"line":2,"result":"timeout","code":null,"reply":[]}"#]
    );
    // The reply after the timeout answers nothing: a packet.
    assert_eq!(
        feed(&mut s, &ack(0), 160),
        [format!("packet {} set {COMMAND_SET}", ack(0).len())]
    );
}

#[test]
fn several_acks_in_one_packet_answer_the_oldest_first() {
    let mut s: Session<2> = Session::new(None);
    start(&mut s, 0);
    start(&mut s, 0);
    let (_, sent, refused) = start(&mut s, 0);
    assert!(sent.is_empty());
    assert_eq!(
        refused.as_deref(),
        Some(
            r#"{"line":3,"result":"refused","code":null,"reply":[],"error":"2 commands already pending"}"#
        )
    );
    let two = packet(
        COMMAND_SET,
        &[(ACK, &[PING, 0]), (PING, &[1]), (ACK, &[PING, 4])],
    );
    assert_eq!(
        feed(&mut s, &two, 1),
        [
            r#"{"line":1,"result":"invalid","code":0,"reply":[{"descriptor":1,"data":"01","error":"1 unexpected bytes at offset 0"}],"error":"1 unexpected bytes at offset 0"}"#,
            r#"{"line":2,"result":"nack","code":4,"reply":[]}"#,
        ]
    );
}

#[test]
fn timed_rule_drops_a_false_sync_and_resumes_at_the_next_byte() {
    let mut s: Session = Session::new(None);
    start(&mut s, 0);
    // A sync and a header claiming 80 payload bytes that never come, with the ack behind it.
    let mut garbage = vec![0u8; HEADER_SIZE];
    garbage[..SYNC.len()].copy_from_slice(&SYNC);
    garbage[SET_OFFSET] = COMMAND_SET;
    garbage[LENGTH_OFFSET] = 80;
    garbage.extend(ack(0));
    assert!(feed(&mut s, &garbage, 10).is_empty());
    assert_eq!(s.next_deadline(), Some(111));
    let mut out = Vec::new();
    s.poll(110, |e| out.push(text(e)));
    assert!(out.is_empty(), "not yet: {out:?}");
    s.poll(111, |e| out.push(text(e)));
    assert_eq!(
        out,
        [
            &format!("skip 0 {HEADER_SIZE}"),
            r#"{"line":1,"result":"ack","code":0,"reply":[]}"#
        ]
    );
    assert_eq!(s.next_deadline(), None);
}

#[test]
fn refusal_by_device_and_close_flushes() {
    let mut s: Session = Session::new(Some(Device::Beta));
    let (_, _, done) = start(&mut s, 0);
    assert!(done.is_none(), "beta supports ping");
    let set_mode = FieldValue::Control(control::SetField::SetMode(control::SetMode::ZERO));
    let refused = s.start(&set_mode, 0, StartOptions::default()).unwrap();
    assert!(
        refused.packet.is_empty(),
        "set_mode is alpha's only: not sent"
    );
    assert_eq!(
        refused
            .result
            .map(|r| text(SessionEvent::Result(r)))
            .as_deref(),
        Some(
            r#"{"line":2,"result":"refused","code":null,"reply":[],"error":"set_mode is not supported by Beta (beta.txt)"}"#
        )
    );
    let reading = FieldValue::Sensor(sensor::SetField::Reading(sensor::Reading::ZERO));
    assert!(s.start(&reading, 0, StartOptions::default()).is_err());
    let mut out = Vec::new();
    s.feed(&SYNC, 1, |e| out.push(text(e)));
    s.close(2, |e| out.push(text(e)));
    assert_eq!(out, [format!("skip 0 {}", SYNC.len())]);
    assert_eq!(s.pending(), 1, "close leaves commands pending");
}

#[test]
fn hostile_bytes_never_panic_and_memory_stays_bounded() {
    let mut s: Session<4> = Session::new(None).with_inter_packet_timeout_ms(0);
    let mut x: u32 = 1;
    let mut now = 0;
    for round in 0..2000 {
        if round % 7 == 0 {
            let _ = s.start(&ping(), now, StartOptions::default());
        }
        let mut chunk = Vec::new();
        for _ in 0..(x % 40) {
            x ^= x << 13;
            x ^= x >> 17;
            x ^= x << 5;
            chunk.push(match x % 5 {
                0 => SYNC[0],
                1 => SYNC[1],
                2 => COMMAND_SET,
                3 => ACK,
                _ => x as u8,
            });
        }
        if round % 11 == 0 {
            chunk.extend(ack((x % 3) as u8));
        }
        now += u64::from(x % 3);
        s.feed(&chunk, now, |e| {
            if let SessionEvent::Result(r) = e {
                assert!(matches!(
                    r.status,
                    Status::Ack | Status::Nack | Status::Timeout | Status::Invalid
                ));
            }
        });
        assert!(s.pending() <= 4);
    }
}
