//! The host clock model (src/clock.rs) runs the corpus tests/clock/cases.txt (docs/time.md), as
//! the C, C++ and Python runtimes do.

use protocodec::clock::ClockModel;

struct Case {
    name: String,
    packets: Vec<(i64, i64)>,
    expects: Vec<Vec<String>>,
}

fn cases() -> Vec<Case> {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../../../tests/clock/cases.txt"
    );
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let mut out = Vec::new();
    let mut c = Case {
        name: String::new(),
        packets: Vec::new(),
        expects: Vec::new(),
    };
    for line in text.lines() {
        let words: Vec<&str> = line.split_whitespace().collect();
        match words.first() {
            None => {}
            Some(w) if w.starts_with('#') => {}
            Some(&"case") => {
                c = Case {
                    name: words[1].to_string(),
                    packets: Vec::new(),
                    expects: Vec::new(),
                }
            }
            Some(&"p") => c
                .packets
                .push((words[1].parse().unwrap(), words[2].parse().unwrap())),
            Some(&"expect") => c
                .expects
                .push(words[1..].iter().map(|w| w.to_string()).collect()),
            Some(&"end") => out.push(std::mem::replace(
                &mut c,
                Case {
                    name: String::new(),
                    packets: Vec::new(),
                    expects: Vec::new(),
                },
            )),
            Some(w) => panic!("unknown line {w}"),
        }
    }
    out
}

#[test]
fn clock_corpus() {
    let cases = cases();
    assert_eq!(cases.len(), 7);
    for c in &cases {
        let mut model = ClockModel::new();
        for &(d, a) in &c.packets {
            assert_eq!(model.add(d, a).is_some(), model.estimated(), "{}", c.name);
        }
        assert!(!c.expects.is_empty(), "{}", c.name);
        let last = c.packets.last().unwrap().0;
        for e in &c.expects {
            let num = |i: usize| e[i].parse::<i64>().unwrap();
            match e[0].as_str() {
                "estimated" => {
                    assert_eq!(model.estimated(), e[1] == "1", "{}", c.name);
                    assert_eq!(model.drift_ppm().is_some(), model.estimated(), "{}", c.name);
                    assert_eq!(model.offset_ns().is_some(), model.estimated(), "{}", c.name);
                }
                "restarts" => assert_eq!(i64::from(model.restarts()), num(1), "{}", c.name),
                "drift_ppm" => {
                    let drift = model.drift_ppm().unwrap();
                    let (want, tol) = (e[1].parse::<f64>().unwrap(), e[2].parse::<f64>().unwrap());
                    assert!((drift - want).abs() <= tol, "{}: drift {drift}", c.name);
                }
                "host_ns" => {
                    let host = model.host_time(num(1)).unwrap();
                    assert!(
                        (host - num(2)).abs() <= num(3),
                        "{}: host off by {}",
                        c.name,
                        host - num(2)
                    );
                    assert_eq!(
                        model.offset_ns().unwrap(),
                        model.host_time(last).unwrap() - last
                    );
                }
                "bound_max_ns" => {
                    assert!(
                        model.bound_ns() >= 0 && model.bound_ns() <= num(1),
                        "{}: bound {}",
                        c.name,
                        model.bound_ns()
                    )
                }
                other => panic!("unknown expectation {other}"),
            }
        }
    }
}

#[test]
fn clock_restarts_when_device_time_goes_back() {
    let mut model = ClockModel::new();
    for k in 0..300i64 {
        model.add(
            1_000_000_000 + k * 10_000_000,
            5_000_000_000_000 + k * 10_000_000,
        );
    }
    assert!(model.estimated());
    assert_eq!(model.restarts(), 0);
    assert_eq!(
        model.add(1_000_000, 5_000_000_000_000 + 301 * 10_000_000),
        None
    );
    assert_eq!(model.restarts(), 1);
}

/// A data packet of the test protocol's sensor set (0x80) carrying alpha's reference time
/// (shared 0xD5, ns, in the protocol's byte order).
fn stamped(ns: u64) -> Vec<u8> {
    let data = if protocodec::framing::BIG_ENDIAN {
        ns.to_be_bytes()
    } else {
        ns.to_le_bytes()
    };
    let mut b = protocodec::builder::PacketBuilder::new(0x80);
    b.add_raw_field(0xD5, &data).unwrap();
    b.finish().to_vec()
}

/// The session feeds the model the reference time of every data packet at the host time of its
/// bytes (feed_at) and gives the packet's host time with the packet's event.
#[test]
fn session_feeds_the_model() {
    use protocodec::session::{Session, SessionEvent};
    use protocodec::Device;
    for device in [Device::Alpha, Device::Beta] {
        let mut s: Session = Session::new(Some(device));
        s.use_clock(Some(ClockModel::new()));
        let mut hosts: Vec<Option<i64>> = Vec::new();
        let host0: i64 = 9_000_000_000_000;
        let mut a = 0;
        // 10 s at 50 Hz, the device's clock 100 ppm fast, no delay
        for k in 0..500i64 {
            let d = 3_000_000_000 + k * 20_000_000;
            a = host0 + ((d - 3_000_000_000) as f64 / (1.0 + 100e-6)).round() as i64;
            s.feed_at(&stamped(d as u64), (a / 1_000_000) as u64, a, |e, host| {
                if let SessionEvent::Packet { .. } = e {
                    hosts.push(host);
                }
            });
        }
        assert_eq!(hosts.len(), 500);
        let model = s.clock().unwrap();
        if device == Device::Beta {
            // beta has no reference time in the spec: nothing fed
            assert!(!model.estimated());
            assert!(hosts.last().unwrap().is_none());
            continue;
        }
        assert!(hosts[0].is_none(), "nothing before two buckets closed");
        // No delay or jitter: the fit is the true line, to the whole-ns rounding of arrival times.
        assert!((model.drift_ppm().unwrap() - 100.0).abs() < 0.01);
        let last = hosts.last().unwrap().expect("the last packet's host time");
        assert!((last - a).abs() <= 1, "{last} vs {a}");
        // feed() feeds the model at now (ms) x 1000000; a packet without the reference time has
        // no host time and feeds nothing.
        let mut b = protocodec::builder::PacketBuilder::new(0x80);
        b.add_raw_field(0x04, &[1, 2]).unwrap();
        let other = b.finish().to_vec();
        let mut seen = Vec::new();
        s.feed_at(
            &other,
            (a / 1_000_000) as u64 + 20,
            a + 20_000_000,
            |e, host| {
                if let SessionEvent::Packet { .. } = e {
                    seen.push(host);
                }
            },
        );
        assert_eq!(seen, vec![None]);
        let mut packets = 0;
        let next: i64 = 3_000_000_000 + 500 * 20_000_000;
        s.feed(&stamped(next as u64), (a / 1_000_000) as u64 + 20, |e| {
            if let SessionEvent::Packet { .. } = e {
                packets += 1;
            }
        });
        assert_eq!(packets, 1);
        assert_eq!(s.clock().unwrap().restarts(), 0);
    }
}
