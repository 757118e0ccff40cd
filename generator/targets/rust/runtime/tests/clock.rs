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
