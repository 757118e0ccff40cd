//! Unit tests of getting through (src/device.rs: reconnection, the settings re-applied, the link
//! lines; src/session.rs: `Session::abandon`) against the test protocol rendered from
//! tests/runtime_specs/ (`ping`, `gain` with a function selector; no idle command), over a
//! scripted transport whose port can go away and come back. Getting a streaming device to idle
//! and finding its baud rate are tested against the simulator (tests/conformance/test_link.py),
//! with the MIP facts.

use std::cell::RefCell;
use std::collections::VecDeque;
use std::io;
use std::rc::Rc;
use std::time::{Duration, Instant};

use protocodec::builder::PacketBuilder;
use protocodec::commands::ACK_DESCRIPTOR as ACK;
use protocodec::device::{Device as Link, SessionError, Transport};
use protocodec::fields::{FieldItem, Packet};
use protocodec::parser::{Event, Parser};
use protocodec::session::{Session, SessionEvent, StartOptions, Status};
use protocodec::types::Function;
use protocodec::wire::{Layout, Wire};
use protocodec::{control, Device, FieldValue};

const EIO: i32 = 5;

/// The device's end of the line: answers every command with an ack while the port is up.
struct Line {
    up: bool,
    parser: Parser,
    inbox: VecDeque<u8>,
    commands: Vec<(u8, u8, Vec<u8>)>,
    opens: u32,
    // A serial port's rate and the device's: (host, device); commands are answered only when
    // they are the same.
    rates: Option<(u32, u32)>,
}

impl Line {
    fn new() -> Rc<RefCell<Line>> {
        Rc::new(RefCell::new(Line {
            up: true,
            parser: Parser::new(),
            inbox: VecDeque::new(),
            commands: Vec::new(),
            opens: 0,
            rates: None,
        }))
    }
}

struct Port(Rc<RefCell<Line>>);

fn lost() -> io::Error {
    io::Error::from_raw_os_error(EIO)
}

impl Transport for Port {
    fn send(&mut self, bytes: &[u8]) -> io::Result<()> {
        let mut line = self.0.borrow_mut();
        if !line.up {
            return Err(lost());
        }
        let understood = line.rates.map_or(true, |(host, device)| host == device);
        let Line {
            parser,
            inbox,
            commands,
            ..
        } = &mut *line;
        parser.feed(bytes, |e| {
            if let Event::Packet { bytes, .. } = e {
                let packet = Packet::new(bytes).unwrap();
                for item in packet.fields() {
                    if let FieldItem::Field { descriptor, data } = item {
                        commands.push((packet.set(), descriptor, data.to_vec()));
                        if !understood {
                            continue;
                        }
                        let mut b = PacketBuilder::new(packet.set());
                        b.add_raw_field(ACK, &[descriptor, 0]).unwrap();
                        inbox.extend(b.finish());
                    }
                }
            }
        });
        Ok(())
    }

    fn receive(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
        let mut line = self.0.borrow_mut();
        if !line.up {
            return Err(lost());
        }
        if line.inbox.is_empty() {
            drop(line);
            std::thread::sleep(timeout.min(Duration::from_millis(5)));
            return Ok(0);
        }
        let n = buf.len().min(line.inbox.len());
        for (slot, b) in buf.iter_mut().zip(line.inbox.drain(..n)) {
            *slot = b;
        }
        Ok(n)
    }

    fn baud(&self) -> Option<u32> {
        self.0.borrow().rates.map(|(host, _)| host)
    }

    fn set_baud(&mut self, baud: u32) -> io::Result<()> {
        let mut line = self.0.borrow_mut();
        let device = line.rates.map_or(baud, |(_, device)| device);
        line.rates = Some((baud, device));
        Ok(())
    }
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

const GAIN: u8 = <control::Gain as Layout>::DESCRIPTOR;

/// The data of a gain write as the framing's byte order puts it.
fn gain_data(value: u16) -> Vec<u8> {
    let bytes = if protocodec::framing::BIG_ENDIAN {
        value.to_be_bytes()
    } else {
        value.to_le_bytes()
    };
    vec![Function::WRITE.0, bytes[0], bytes[1]]
}

/// A device on `line` that reopens it (the `fails` first reopens fail) and logs its link lines.
fn device(
    line: &Rc<RefCell<Line>>,
    fails: u32,
    reconnect_ms: Option<u64>,
) -> (Link<Port>, Rc<RefCell<Vec<String>>>) {
    let again = Rc::clone(line);
    let mut dev = Link::new(Port(Rc::clone(line)), Some(Device::Alpha))
        .with_timeout_ms(200)
        .with_opener("test-port", move |_baud| {
            let mut l = again.borrow_mut();
            l.opens += 1;
            if l.opens <= fails {
                return Err(SessionError::Connect("cannot open test-port".into()));
            }
            l.up = true;
            l.parser = Parser::new();
            Ok(Port(Rc::clone(&again)))
        });
    if let Some(ms) = reconnect_ms {
        dev = dev.with_reconnect_ms(ms);
    }
    let logs = Rc::new(RefCell::new(Vec::new()));
    let sink = Rc::clone(&logs);
    dev.on_link(move |text| sink.borrow_mut().push(text.to_string()));
    (dev, logs)
}

#[test]
fn a_lost_port_fails_the_command_in_flight_then_the_settings_are_reapplied() {
    let line = Line::new();
    let (mut dev, logs) = device(&line, 1, Some(3000));
    dev.call(&gain(Function::WRITE, Some(5))).unwrap();
    dev.call(&gain(Function::WRITE, Some(7))).unwrap();
    dev.call(&gain(Function::READ, None)).unwrap_err(); // no gain_value reply: not a setting
    dev.call(&ping()).unwrap();
    // The latest write of a one-parameter command wins; reads and pings are not settings.
    assert_eq!(
        dev.settings().copied().collect::<Vec<_>>(),
        [gain(Function::WRITE, Some(7))]
    );

    line.borrow_mut().up = false;
    line.borrow_mut().commands.clear();
    let began = Instant::now();
    match dev.call(&ping()) {
        Err(SessionError::LinkLost {
            name,
            reason,
            gave_up: None,
        }) => {
            assert_eq!((name, reason.as_str()), ("ping", "Input/output error"));
        }
        other => panic!("expected link lost, got {other:?}"),
    }
    // A failed reopen 500 ms after the loss, then one that works 500 ms later.
    let took = began.elapsed();
    assert!(took >= Duration::from_millis(1000), "{took:?}");
    assert!(took < Duration::from_millis(2000), "{took:?}");
    assert_eq!(line.borrow().opens, 2);
    // Re-applied in order, the command in flight not retried (the protocol has no idle command).
    let sent = line.borrow().commands.clone();
    assert_eq!(sent, [(control::SET, GAIN, gain_data(7))]);
    let logs = logs.borrow().clone();
    assert_eq!(logs.len(), 2, "{logs:?}");
    assert_eq!(
        logs[0],
        "link: port lost (Input/output error), reopening test-port every 500 ms"
    );
    assert!(
        logs[1].starts_with("link: reconnected after 1.")
            && logs[1].ends_with(" s, re-applied 1 settings"),
        "{}",
        logs[1]
    );
    // The link works again.
    assert_eq!(
        dev.run(&ping(), StartOptions::default()).unwrap().status,
        Status::Ack
    );
}

#[test]
fn reconnection_gives_up_at_its_deadline_with_one_error() {
    let line = Line::new();
    let (mut dev, logs) = device(&line, u32::MAX, Some(1200));
    line.borrow_mut().up = false;
    let began = Instant::now();
    let err = dev.call(&ping()).unwrap_err();
    let took = began.elapsed();
    assert_eq!(
        err.to_string(),
        "link: gave up reopening test-port after 1200 ms"
    );
    assert!(matches!(err, SessionError::LinkLost { name: "ping", .. }));
    // Reopened at 500, 1000 and (the deadline) 1200 ms.
    assert_eq!(line.borrow().opens, 3);
    assert!(took >= Duration::from_millis(1200) && took < Duration::from_millis(1700));
    assert_eq!(
        *logs.borrow(),
        [
            "link: port lost (Input/output error), reopening test-port every 500 ms",
            "link: gave up reopening test-port after 1200 ms"
        ]
    );
}

#[test]
fn without_reconnection_a_lost_port_is_an_io_error() {
    let line = Line::new();
    let (mut dev, logs) = device(&line, 0, None);
    line.borrow_mut().up = false;
    match dev.call(&ping()) {
        Err(SessionError::Io(e)) => assert_eq!(e.raw_os_error(), Some(EIO)),
        other => panic!("expected an I/O error, got {other:?}"),
    }
    assert_eq!(line.borrow().opens, 0);
    assert!(logs.borrow().is_empty());
}

#[test]
fn listening_rides_through_a_lost_port() {
    let line = Line::new();
    let (mut dev, logs) = device(&line, 0, Some(2000));
    dev.call(&gain(Function::WRITE, Some(3))).unwrap();
    line.borrow_mut().up = false;
    line.borrow_mut().commands.clear();
    dev.listen(100).unwrap();
    assert_eq!(line.borrow().commands, [(control::SET, GAIN, gain_data(3))]);
    assert_eq!(logs.borrow().len(), 2);
}

#[test]
fn without_an_idle_command_to_idle_says_so() {
    let line = Line::new();
    let (mut dev, _) = device(&line, 0, None);
    let err = dev.to_idle().unwrap_err();
    assert_eq!(
        err.to_string(),
        "link: idle: the protocol has no idle command"
    );
    assert!(line.borrow().commands.is_empty());
    // Over a transport without a baud rate there is none to find.
    assert_eq!(dev.find_baud().unwrap(), None);
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

/// The baud-rate search: the configured rate, the model's default, then its rates from the
/// highest down (tests/runtime_specs: alpha 9600, 115200 (default), 921600; beta 115200,
/// 230400), one ping each.
fn search(
    model: Option<Device>,
    host: u32,
    device: u32,
) -> (Result<Option<u32>, String>, Vec<String>, u32) {
    let line = Line::new();
    line.borrow_mut().rates = Some((host, device));
    let logs = Rc::new(RefCell::new(Vec::new()));
    let sink = Rc::clone(&logs);
    let mut dev = Link::new(Port(Rc::clone(&line)), model).with_timeout_ms(100);
    dev.on_link(move |text| sink.borrow_mut().push(text.to_string()));
    let found = dev.find_baud().map_err(|e| e.to_string());
    let logs = logs.borrow().clone();
    let rate = line.borrow().rates.unwrap().0;
    (found, logs, rate)
}

#[test]
fn the_baud_rate_search_tries_the_default_then_the_highest_first() {
    let (found, logs, rate) = search(Some(Device::Alpha), 9600, 921_600);
    assert_eq!(found, Ok(Some(921_600)));
    assert_eq!(
        logs,
        [
            "link: baud: no answer at 9600, trying 115200",
            "link: baud: no answer at 115200, trying 921600",
            "link: baud: device answers at 921600",
        ]
    );
    assert_eq!(rate, 921_600);
    // At the configured rate: one ping, nothing said.
    let (found, logs, _) = search(Some(Device::Alpha), 115_200, 115_200);
    assert_eq!((found, logs.len()), (Ok(Some(115_200)), 0));
    // Without a model: every model's default, then all their rates from the highest down.
    let (found, logs, _) = search(None, 9600, 230_400);
    assert_eq!(found, Ok(Some(230_400)));
    assert_eq!(
        logs[..3],
        [
            "link: baud: no answer at 9600, trying 115200",
            "link: baud: no answer at 115200, trying 921600",
            "link: baud: no answer at 921600, trying 230400",
        ]
    );
}

#[test]
fn no_answer_at_any_rate_fails_and_leaves_the_configured_rate() {
    let (found, logs, rate) = search(Some(Device::Beta), 230_400, 57_600);
    assert_eq!(found, Err("link: baud: no answer at any rate".to_string()));
    assert_eq!(
        logs,
        [
            "link: baud: no answer at 230400, trying 115200",
            "link: baud: no answer at any rate",
        ]
    );
    assert_eq!(rate, 230_400);
}
