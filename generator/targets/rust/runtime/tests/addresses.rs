//! Unit tests of the address parser of the blocking API (src/device.rs `parse_address`), without
//! opening anything: serial port paths of every platform the `serialport` crate serves (`COM3`,
//! `\\.\COM10`, `/dev/ttyUSB0`), `tcp:HOST:PORT`, and HOST:PORT without `tcp:`, which is refused
//! with "did you mean tcp:HOST:PORT?" unless it is an existing path (the rule the four languages
//! share).

use protocodec::device::{parse_address, Address, SessionError};

fn serial(address: &str) -> Address {
    Address::Serial(address.to_string())
}

fn refusal(address: &str) -> String {
    match parse_address(address) {
        Err(SessionError::Address(text)) => text,
        other => panic!("{address}: expected an address error, got {other:?}"),
    }
}

#[test]
fn serial_ports_of_every_platform_are_serial_ports() {
    for path in [
        "COM3",
        "\\\\.\\COM10",
        "/dev/ttyUSB0",
        "/dev/serial/by-id/usb-x:1.0-port0",
    ] {
        assert_eq!(parse_address(path).unwrap(), serial(path), "{path}");
    }
}

#[test]
fn tcp_addresses() {
    let tcp = |host: &str, port| Address::Tcp {
        host: host.to_string(),
        port,
    };
    assert_eq!(
        parse_address("tcp:127.0.0.1:5000").unwrap(),
        tcp("127.0.0.1", 5000)
    );
    assert_eq!(parse_address("tcp:[::1]:5000").unwrap(), tcp("::1", 5000));
    assert_eq!(
        parse_address("tcp:localhost:65535").unwrap(),
        tcp("localhost", 65535)
    );
    for bad in [
        "tcp:127.0.0.1",
        "tcp::5000",
        "tcp:host:0",
        "tcp:host:65536",
        "tcp:host:x",
    ] {
        assert_eq!(
            refusal(bad),
            format!("bad TCP address '{bad}' (expected tcp:HOST:PORT)")
        );
    }
    assert!(refusal("").starts_with("empty address"));
}

#[test]
fn host_and_port_without_tcp_is_a_mistake_unless_the_path_exists() {
    for address in ["127.0.0.1:5000", "localhost:5000", "[::1]:5000"] {
        assert_eq!(
            refusal(address),
            format!("'{address}' is not a serial port: did you mean tcp:{address}?")
        );
    }
    // Not HOST:PORT: a port that is not a number, an IPv6 host without brackets, a path.
    for path in ["COM3:", "dev:tty", "fe80::1:5000", "./127.0.0.1:5000"] {
        assert_eq!(parse_address(path).unwrap(), serial(path), "{path}");
    }
    // An existing file named like HOST:PORT is a path (a relative one, in the current directory).
    let dir = std::env::temp_dir().join(format!("addresses-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("port:5000"), b"").unwrap();
    std::env::set_current_dir(&dir).unwrap();
    let found = parse_address("port:5000");
    std::fs::remove_dir_all(&dir).unwrap();
    assert_eq!(found.unwrap(), serial("port:5000"));
}
