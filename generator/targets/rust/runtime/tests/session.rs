//! Unit tests of the session core (src/session.rs) against the test protocol rendered by the back
//! end from tests/runtime_specs/ (../Cargo.toml: `ping` on every device, `set_mode` on alpha only,
//! answered by the reserved ack field 0xF1): matching, nack, timeouts, routing of
//! data while a command waits, the look-ahead rule and its wake-up, skip runs in pieces of
//! SKIP_PIECE bytes, the bounded queue, several acks in
//! one packet, invalid replies, chunking independence and hostile input. The spec-driven cases
//! (tests/sessions/) run in every generated crate (templates/rust/test_sessions.rs.j2).

use protocodec::builder::PacketBuilder;
use protocodec::commands::ACK_DESCRIPTOR as ACK;
use protocodec::framing::{
    FOREIGN_NMEA, FOREIGN_RTCM3, HEADER_SIZE, LENGTH_OFFSET, SET_OFFSET, SYNC,
};
use protocodec::session::{Session, SessionEvent, StartOptions, Status, SKIP_PIECE};
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
        SessionEvent::Nmea { offset, bytes } => format!("nmea {offset} {}", bytes.len()),
        SessionEvent::Rtcm { offset, bytes } => format!("rtcm {offset} {}", bytes.len()),
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

/// The example GGA sentence NMEA references quote (checksum 47, 67 bytes) and the RTCM 10403
/// example frame of message 1005 (25 bytes, CRC-24Q 36 0B 98) between a data packet and a reply:
/// framing a carries them (`FOREIGN_NMEA`, `FOREIGN_RTCM3`; docs/conformance.md §1) and the
/// session hands them on as `SessionEvent::Nmea` and `SessionEvent::Rtcm` in stream order,
/// whatever the split; framing b has none, and the same bytes are skip runs.
#[test]
fn foreign_frames_go_to_the_handler_whatever_the_split() {
    let gga: &[u8] = b"$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47\r\n";
    let rtcm: [u8; 25] = [
        0xD3, 0x00, 0x13, 0x3E, 0xD7, 0xD3, 0x02, 0x02, 0x98, 0x0E, 0xDE, 0xEF, 0x34, 0xB4, 0xBD,
        0x62, 0xAC, 0x09, 0x41, 0x98, 0x6F, 0x33, 0x36, 0x0B, 0x98,
    ];
    let d = data(7);
    let mut stream = gga.to_vec();
    stream.extend(&d);
    stream.extend(rtcm);
    stream.extend(ack(0));
    let (g, r) = (gga.len(), gga.len() + d.len());
    let want = if FOREIGN_NMEA && FOREIGN_RTCM3 {
        vec![
            format!("nmea 0 {g}"),
            format!("packet {g} set 128"),
            format!("rtcm {r} 25"),
        ]
    } else {
        vec![
            format!("skip 0 {g}"),
            format!("packet {g} set 128"),
            format!("skip {r} 25"),
        ]
    };
    let mut want = want;
    want.push(r#"{"line":1,"result":"ack","code":0,"reply":[]}"#.to_string());
    for cut in 0..=stream.len() {
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

/// A sync and a header of the command set claiming `length` payload bytes that never come.
fn false_sync(length: u8) -> Vec<u8> {
    let mut garbage = vec![0u8; HEADER_SIZE];
    garbage[..SYNC.len()].copy_from_slice(&SYNC);
    garbage[SET_OFFSET] = COMMAND_SET;
    garbage[LENGTH_OFFSET] = length;
    garbage
}

fn poll<const N: usize>(s: &mut Session<N>, now: u64) -> Vec<String> {
    let mut out = Vec::new();
    s.poll(now, |e| out.push(text(e)));
    out
}

const ACK_LINE: &str = r#"{"line":1,"result":"ack","code":0,"reply":[]}"#;

#[test]
fn look_ahead_skips_a_false_sync_for_the_complete_packet_after_it() {
    let mut s: Session = Session::new(None);
    start(&mut s, 0);
    // The ack behind a false sync, in the same chunk: the parser waits for the false packet.
    let mut bytes = false_sync(80);
    bytes.extend(ack(0));
    assert!(feed(&mut s, &bytes, 10).is_empty());
    // The wait expires after the inter-packet timeout (100 ms): 10 + 100 + 1.
    assert_eq!(s.next_deadline(), Some(111));
    assert!(poll(&mut s, 110).is_empty(), "not expired at 110");
    assert_eq!(
        poll(&mut s, 111),
        [&format!("skip 0 {HEADER_SIZE}"), ACK_LINE]
    );
    assert_eq!(s.next_deadline(), None);
}

#[test]
fn look_ahead_takes_the_first_valid_packet_and_parsing_continues_after_it() {
    let mut s: Session = Session::new(None);
    start(&mut s, 0);
    // False sync, then a packet with a broken checksum, then the ack and a data packet.
    let mut broken = ack(0);
    let last = broken.len() - 1;
    broken[last] ^= 0xFF;
    let mut bytes = false_sync(200);
    bytes.extend(&broken);
    let ack_at = bytes.len();
    bytes.extend(ack(0));
    let data_at = bytes.len();
    bytes.extend(data(7));
    assert!(feed(&mut s, &bytes, 0).is_empty());
    assert_eq!(
        poll(&mut s, 101),
        [
            format!("skip 0 {ack_at}"),
            ACK_LINE.to_string(),
            format!("packet {data_at} set {DATA_SET}")
        ]
    );
}

#[test]
fn a_slow_packet_is_never_dropped() {
    let mut s: Session = Session::new(None);
    start(&mut s, 0);
    let reply = ack(0);
    let half = reply.len() / 2;
    assert!(feed(&mut s, &reply[..half], 10).is_empty());
    assert_eq!(s.next_deadline(), Some(111));
    // Expired with nothing complete after it: nothing dropped, and no wake-up for the rule any
    // more (a poll without new bytes could change nothing); the command's deadline remains.
    assert!(poll(&mut s, 111).is_empty());
    assert_eq!(s.next_deadline(), Some(1000));
    assert!(poll(&mut s, 500).is_empty());
    assert_eq!(feed(&mut s, &reply[half..], 600), [ACK_LINE]);
    assert_eq!(s.next_deadline(), None);
}

#[test]
fn wake_up_is_none_after_an_expired_check() {
    let mut s: Session = Session::new(None);
    assert!(feed(&mut s, &false_sync(80), 5).is_empty());
    assert_eq!(s.next_deadline(), Some(106));
    assert!(poll(&mut s, 106).is_empty());
    assert_eq!(s.next_deadline(), None, "nothing pending, the wait expired");
    // A later feed still checks by itself: the ack added behind the false sync is found.
    let mut out = feed(&mut s, &data(1), 300);
    assert_eq!(
        out,
        [
            format!("skip 0 {HEADER_SIZE}"),
            format!("packet {HEADER_SIZE} set {DATA_SET}")
        ]
    );
    // A new wait (a partial packet at 400) gets its own wake-up.
    out = feed(&mut s, &SYNC, 400);
    assert!(out.is_empty());
    assert_eq!(s.next_deadline(), Some(501));
}

#[test]
fn false_sync_with_nothing_after_it_waits_until_close() {
    let mut s: Session = Session::new(None).with_timeout_ms(300);
    start(&mut s, 0);
    assert!(feed(&mut s, &false_sync(0xF0), 5).is_empty());
    assert!(poll(&mut s, 106).is_empty());
    assert_eq!(
        poll(&mut s, 300),
        [r#"{"line":1,"result":"timeout","code":null,"reply":[]}"#]
    );
    let mut out = Vec::new();
    s.close(301, |e| out.push(text(e)));
    assert_eq!(out, [format!("skip 0 {HEADER_SIZE}")]);
}

#[test]
fn skip_runs_come_in_pieces_of_65536_bytes_as_they_arrive() {
    assert_eq!(SKIP_PIECE, 65536);
    // One feed of 200000 zeros: three pieces at once, the rest pending until close.
    let mut s: Session = Session::new(None);
    assert_eq!(
        feed(&mut s, &vec![0u8; 200_000], 0),
        ["skip 0 65536", "skip 65536 65536", "skip 131072 65536"]
    );
    assert_eq!(s.retain_from(), 196_608);
    let mut out = Vec::new();
    s.close(1, |e| out.push(text(e)));
    assert_eq!(out, ["skip 196608 3392"]);

    // Fed 1000 bytes at a time: the piece comes with the feed that makes it 65536 bytes long.
    let mut s: Session = Session::new(None);
    let mut fed = 0u64;
    let mut pieces = Vec::new();
    for _ in 0..140 {
        let out = feed(&mut s, &[0u8; 1000], 0);
        fed += 1000;
        if !out.is_empty() {
            pieces.push((fed, out));
        }
    }
    assert_eq!(
        pieces,
        [
            (66_000, vec!["skip 0 65536".to_string()]),
            (132_000, vec!["skip 65536 65536".to_string()])
        ]
    );

    // A run that a packet ends: pieces, then the rest, then the packet.
    let mut s: Session = Session::new(None);
    let mut bytes = vec![0u8; 70_000];
    bytes.extend(data(3));
    assert_eq!(
        feed(&mut s, &bytes, 0),
        [
            "skip 0 65536".to_string(),
            "skip 65536 4464".to_string(),
            format!("packet 70000 set {DATA_SET}")
        ]
    );
    // Exactly one piece before a packet, and a false sync's bytes continue the run.
    let mut s: Session = Session::new(None);
    let mut bytes = vec![0u8; 65_535];
    bytes.extend(&SYNC[..1]);
    bytes.push(0);
    bytes.extend(data(4));
    assert_eq!(
        feed(&mut s, &bytes, 0),
        [
            "skip 0 65536".to_string(),
            "skip 65536 1".to_string(),
            format!("packet 65537 set {DATA_SET}")
        ]
    );
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
