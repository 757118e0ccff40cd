//! Getting through (src/device.rs: to idle, the baud search, reconnection, the settings
//! re-applied, the link lines; docs/conformance.md section 8) on the test protocol rendered from
//! tests/runtime_specs/: the link corpus tests/link/cases.txt (the format and the fake device's
//! rules in tests/link/README.md), as the C, C++ and Python runtimes run it, on a fake clock
//! ([`DeviceClock`]); then the cases of this API only. The test protocol has no idle command: a
//! case gives the ping its place ([`Link::with_idle_command`]) unless it says `set idle none`.

use std::cell::RefCell;
use std::io;
use std::rc::Rc;
use std::time::Duration;

use protocodec::builder::PacketBuilder;
use protocodec::commands::ACK_DESCRIPTOR as ACK;
use protocodec::device::{Device as Link, DeviceClock, SessionError, Transport};
use protocodec::fields::{FieldItem, Packet};
use protocodec::parser::{Event, Parser};
use protocodec::session::{Session, SessionEvent, StartOptions, Status};
use protocodec::types::Function;
use protocodec::wire::{Layout, Wire};
use protocodec::{control, Device, FieldValue};

const EIO: i32 = 5;
const PING: u8 = <control::Ping as Layout>::DESCRIPTOR;

fn packet(set: u8, descriptor: u8, data: &[u8]) -> Vec<u8> {
    let mut b = PacketBuilder::new(set);
    b.add_raw_field(descriptor, data).unwrap();
    b.finish().to_vec()
}

/// A data packet of the sensor set (reading: count, offset, valid).
fn data_packet() -> Vec<u8> {
    packet(0x80, 0x01, &[0x01, 0x00, 0x00, 0x01])
}

fn ack_packet(descriptor: u8) -> Vec<u8> {
    packet(control::SET, ACK, &[descriptor, 0x00])
}

/// The scripted device of tests/link/README.md: a fake clock in ms, a port that can be lost.
#[derive(Default)]
struct Fake {
    now: u64,
    to_host: Vec<u8>,
    sent: Vec<Vec<u8>>,
    streaming: bool,
    unanswered: u32,
    answers_at: u32, // the only rate the device answers at (0: any)
    rate: Option<u32>,
    lost: bool,
    reopen_failures: u32,
    flushes: u32,
    sleeps: Vec<u64>,
}

type Shared = Rc<RefCell<Fake>>;

struct Port(Shared);

impl Transport for Port {
    fn send(&mut self, bytes: &[u8]) -> io::Result<()> {
        let mut d = self.0.borrow_mut();
        if d.lost {
            return Err(io::Error::from_raw_os_error(EIO));
        }
        d.sent.push(bytes.to_vec());
        if (d.answers_at != 0 && d.rate != Some(d.answers_at)) || d.unanswered > 0 {
            d.unanswered = d.unanswered.saturating_sub(1);
            return Ok(());
        }
        let mut descriptor = None;
        Parser::new().feed(bytes, |e| {
            if let Event::Packet { bytes, .. } = e {
                if let Some(FieldItem::Field { descriptor: f, .. }) =
                    Packet::new(bytes).unwrap().fields().next()
                {
                    descriptor = Some(f);
                }
            }
        });
        let descriptor = descriptor.expect("one command field");
        if descriptor == PING {
            d.streaming = false; // the idle command of these cases
        }
        d.to_host.extend(ack_packet(descriptor));
        Ok(())
    }

    fn receive(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
        let mut d = self.0.borrow_mut();
        if d.lost {
            return Err(io::Error::from_raw_os_error(EIO));
        }
        if d.to_host.is_empty() && d.streaming {
            d.to_host = data_packet();
            d.now += 10;
        }
        if d.to_host.is_empty() {
            d.now += u64::try_from(timeout.as_millis()).unwrap();
            return Ok(0);
        }
        let n = buf.len().min(d.to_host.len());
        buf[..n].copy_from_slice(&d.to_host[..n]);
        d.to_host.drain(..n);
        Ok(n)
    }

    fn clear_input(&mut self) -> io::Result<()> {
        let mut d = self.0.borrow_mut();
        d.flushes += 1;
        d.to_host.clear();
        Ok(())
    }

    fn baud(&self) -> Option<u32> {
        self.0.borrow().rate
    }

    fn set_baud(&mut self, baud: u32) -> io::Result<()> {
        self.0.borrow_mut().rate = Some(baud);
        Ok(())
    }
}

struct Clock(Shared);

impl DeviceClock for Clock {
    fn elapsed(&self) -> Duration {
        Duration::from_millis(self.0.borrow().now)
    }
    fn sleep(&mut self, duration: Duration) {
        let ms = u64::try_from(duration.as_millis()).unwrap();
        let mut d = self.0.borrow_mut();
        d.sleeps.push(ms);
        d.now += ms;
    }
}

/// A device on the fake (reconnecting within `reconnect_ms`; the ping as the idle command unless
/// `idle` is false) with its link lines and the count of packets its handlers saw.
struct Fixture {
    fake: Shared,
    dev: Link<Port>,
    lines: Rc<RefCell<Vec<String>>>,
    packets: Rc<RefCell<usize>>,
}

fn fixture(fake: Fake, model: Option<Device>, reconnect_ms: Option<u64>, idle: bool) -> Fixture {
    let fake = Rc::new(RefCell::new(fake));
    let again = Rc::clone(&fake);
    let mut dev = Link::new(Port(Rc::clone(&fake)), model)
        .with_clock(Clock(Rc::clone(&fake)))
        .with_idle_command(if idle {
            Some((control::SET, PING))
        } else {
            None
        })
        .with_opener("/tmp/x/dev", move |_baud| {
            let mut d = again.borrow_mut();
            if d.reopen_failures > 0 {
                d.reopen_failures -= 1;
                return Err(SessionError::Connect("cannot open /tmp/x/dev".into()));
            }
            d.lost = false;
            Ok(Port(Rc::clone(&again)))
        });
    if let Some(ms) = reconnect_ms {
        dev = dev.with_reconnect_ms(ms);
    }
    let lines = Rc::new(RefCell::new(Vec::new()));
    let sink = Rc::clone(&lines);
    dev.on_link(move |text| sink.borrow_mut().push(text.to_string()));
    let packets = Rc::new(RefCell::new(0));
    let count = Rc::clone(&packets);
    dev.on_packet(move |_, _| *count.borrow_mut() += 1);
    Fixture {
        fake,
        dev,
        lines,
        packets,
    }
}

#[derive(Default)]
struct Case {
    name: String,
    set: Vec<(String, String)>,
    steps: Vec<Vec<String>>,
    log: Vec<String>,
    expect: Vec<(String, String)>,
}

fn cases() -> Vec<Case> {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../../../tests/link/cases.txt"
    );
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let mut out = Vec::new();
    let mut c = Case::default();
    for line in text.lines() {
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let (what, rest) = line.split_once(' ').unwrap_or((line, ""));
        let rest = rest.to_string();
        match what {
            "case" => c.name = rest,
            "set" => {
                let (k, v) = rest.split_once(' ').unwrap_or((&rest, ""));
                c.set.push((k.to_string(), v.to_string()));
            }
            "step" => c
                .steps
                .push(rest.split_whitespace().map(String::from).collect()),
            "log" => c.log.push(rest),
            "end" => out.push(std::mem::take(&mut c)),
            "sent" | "flushes" | "packets" | "sleeps" | "rate" => {
                c.expect.push((what.to_string(), rest));
            }
            _ => panic!("{path}: unknown line {line:?}"),
        }
    }
    out
}

/// `{data N}` and `{ack N}`: N data or ACK packets' bytes.
fn expanded(line: &str) -> String {
    let mut out = line.to_string();
    for (what, size) in [
        ("{data ", data_packet().len()),
        ("{ack ", ack_packet(PING).len()),
    ] {
        while let Some(at) = out.find(what) {
            let close = at + out[at..].find('}').unwrap();
            let n: usize = out[at + what.len()..close].parse().unwrap();
            out.replace_range(at..=close, &(n * size).to_string());
        }
    }
    out
}

fn ping() -> FieldValue {
    FieldValue::Control(control::SetField::Ping(control::Ping::ZERO))
}

fn gain(function: Function, value: Option<u16>) -> FieldValue {
    FieldValue::Control(control::SetField::Gain(control::Gain {
        function,
        gain: value,
    }))
}

/// The command of a `sent` token or a step (`ping`, `read`, `write:N`).
fn command(token: &str) -> FieldValue {
    match token {
        "ping" => ping(),
        "read" => gain(Function::READ, None),
        _ => gain(
            Function::WRITE,
            Some(token.strip_prefix("write:").unwrap().parse().unwrap()),
        ),
    }
}

fn token_packet(token: &str) -> Vec<u8> {
    let mut b = PacketBuilder::new(control::SET);
    match command(token) {
        FieldValue::Control(control::SetField::Ping(p)) => b.add(&p).unwrap(),
        FieldValue::Control(control::SetField::Gain(g)) => b.add(&g).unwrap(),
        other => panic!("{other:?}"),
    }
    b.finish().to_vec()
}

/// The result of a step as the corpus names it.
fn outcome(r: Result<Option<Status>, SessionError>) -> String {
    match r {
        Ok(Some(status)) => status.as_str().to_string(),
        Ok(None) => "none".to_string(),
        Err(SessionError::LinkLost { .. }) => "lost".to_string(),
        Err(SessionError::Io(_)) => "error".to_string(),
        Err(e) => format!("{e}"),
    }
}

fn run_step(f: &mut Fixture, step: &[String]) -> Option<String> {
    let got = match step[0].as_str() {
        "lose" => {
            let mut d = f.fake.borrow_mut();
            d.lost = true;
            d.reopen_failures = step[1].parse().unwrap();
            return None;
        }
        "stream" => {
            f.fake.borrow_mut().streaming = true;
            return None;
        }
        "to_idle" => match f.dev.to_idle() {
            Err(SessionError::Link(m)) if m == "idle: the protocol has no idle command" => {
                "refused".to_string()
            }
            r => outcome(r.map(|d| Some(d.status))),
        },
        "find_baud" => match f.dev.find_baud() {
            Ok(Some(_)) => "ack".to_string(),
            Err(SessionError::Link(m)) if m == "baud: no answer at any rate" => "fail".to_string(),
            r => outcome(r.map(|_| None)),
        },
        "listen" => match f.dev.listen(step[1].parse().unwrap()) {
            Ok(()) => "ok".to_string(),
            r => outcome(r.map(|_| None)),
        },
        "write" => outcome(
            f.dev
                .run(
                    &command(&format!("write:{}", step[1])),
                    StartOptions::default(),
                )
                .map(|d| Some(d.status)),
        ),
        token => outcome(
            f.dev
                .run(&command(token), StartOptions::default())
                .map(|d| Some(d.status)),
        ),
    };
    Some(got)
}

fn run_case(c: &Case) {
    let mut fake = Fake {
        rate: Some(115_200),
        ..Fake::default()
    };
    let (mut model, mut reconnect, mut idle) = (Some(Device::Alpha), Some(10_000), true);
    for (k, v) in &c.set {
        match k.as_str() {
            "streaming" => fake.streaming = true,
            "unanswered" => fake.unanswered = v.parse().unwrap(),
            "answers_at" => fake.answers_at = v.parse().unwrap(),
            "baud" => fake.rate = v.parse().ok(),
            "model" => model = Device::from_id(v),
            "reconnect" => reconnect = v.parse().ok(),
            "idle" => idle = v != "none",
            _ => panic!("{}: unknown setting {k}", c.name),
        }
    }
    let mut f = fixture(fake, model, reconnect, idle);
    for step in &c.steps {
        if let Some(got) = run_step(&mut f, step) {
            let want = step.last().unwrap();
            if want != "any" {
                assert_eq!(&got, want, "{}: {step:?}", c.name);
            }
        }
    }
    let log: Vec<String> = c.log.iter().map(|l| expanded(l)).collect();
    assert_eq!(*f.lines.borrow(), log, "{}", c.name);
    let d = f.fake.borrow();
    for (what, rest) in &c.expect {
        let words: Vec<&str> = rest.split_whitespace().collect();
        match what.as_str() {
            "sent" => {
                let sent: Vec<Vec<u8>> = words.iter().map(|t| token_packet(t)).collect();
                assert_eq!(d.sent, sent, "{}: sent", c.name);
            }
            "flushes" => assert_eq!(d.flushes.to_string(), *rest, "{}: flushes", c.name),
            "packets" => assert_eq!(f.packets.borrow().to_string(), *rest, "{}", c.name),
            "sleeps" => {
                let sleeps: Vec<u64> = words.iter().map(|w| w.parse().unwrap()).collect();
                assert_eq!(d.sleeps, sleeps, "{}: sleeps", c.name);
            }
            "rate" => {
                let rate = d.rate.map_or("none".to_string(), |r| r.to_string());
                assert_eq!(rate, *rest, "{}: rate", c.name);
            }
            _ => unreachable!(),
        }
    }
}

#[test]
fn the_link_corpus() {
    let cases = cases();
    assert!(cases.len() >= 16, "{}", cases.len());
    for c in &cases {
        run_case(c);
    }
}

// The cases of this API only.

#[test]
fn the_errors_of_a_lost_port() {
    let mut f = fixture(Fake::default(), Some(Device::Alpha), Some(1000), true);
    f.fake.borrow_mut().lost = true;
    match f.dev.call(&ping()) {
        Err(e @ SessionError::LinkLost { gave_up: None, .. }) => {
            assert_eq!(e.to_string(), "ping: link lost: Input/output error");
        }
        other => panic!("expected link lost, got {other:?}"),
    }
    let mut f = fixture(Fake::default(), Some(Device::Alpha), Some(1200), true);
    f.fake.borrow_mut().lost = true;
    f.fake.borrow_mut().reopen_failures = 100;
    let err = f.dev.call(&ping()).unwrap_err();
    assert!(matches!(err, SessionError::LinkLost { name: "ping", .. }));
    assert_eq!(
        err.to_string(),
        "link: gave up reopening /tmp/x/dev after 1200 ms"
    );
    let mut f = fixture(Fake::default(), Some(Device::Alpha), None, true);
    f.fake.borrow_mut().lost = true;
    match f.dev.call(&ping()) {
        Err(SessionError::Io(e)) => assert_eq!(e.raw_os_error(), Some(EIO)),
        other => panic!("expected an I/O error, got {other:?}"),
    }
}

#[test]
fn the_settings_are_the_latest_write_per_key() {
    let mut f = fixture(Fake::default(), Some(Device::Alpha), None, true);
    for value in [5, 7] {
        f.dev.call(&gain(Function::WRITE, Some(value))).unwrap();
    }
    f.dev.call(&gain(Function::READ, None)).unwrap_err(); // no gain_value reply: not a setting
    f.dev.call(&ping()).unwrap();
    assert_eq!(
        f.dev.settings().copied().collect::<Vec<_>>(),
        [gain(Function::WRITE, Some(7))]
    );
}

#[test]
fn listening_rides_through_a_lost_port() {
    let mut f = fixture(Fake::default(), Some(Device::Alpha), Some(2000), false);
    f.dev.call(&gain(Function::WRITE, Some(3))).unwrap();
    f.fake.borrow_mut().lost = true;
    f.fake.borrow_mut().sent.clear();
    f.dev.listen(100).unwrap();
    assert_eq!(f.fake.borrow().sent, [token_packet("write:3")]);
    assert_eq!(f.lines.borrow().len(), 2);
}

#[test]
fn abandon_forgets_the_pending_commands_and_their_late_replies_are_packets() {
    let mut s: Session<2> = Session::new(None);
    let id = s.start(&ping(), 0, StartOptions::default()).unwrap().id;
    assert_eq!(s.abandon(), 1);
    assert!(!s.is_pending(id) && s.pending() == 0 && s.next_deadline().is_none());
    let mut b = PacketBuilder::new(control::SET);
    b.add_raw_field(ACK, &[<control::Ping as Layout>::DESCRIPTOR, 0])
        .unwrap();
    let mut events = Vec::new();
    s.feed(b.finish(), 5000, |e| {
        events.push(matches!(e, SessionEvent::Packet { .. }))
    });
    assert_eq!(events, [true]); // no timeout result, the ack routed as a packet
}
