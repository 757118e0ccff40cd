//! `configure_and_stream tcp:HOST:PORT [N]`: connects to a 3DM-CV7-GNSS/INS, pings
//! it, reads its device info, writes and reads back one setting
//! (`sensor_to_vehicle_euler`), enables a data stream and prints the first N data packets
//! (default 5) as canonical JSON lines. Run it with
//! `cargo run --example configure_and_stream -- tcp:192.168.1.100:5000`. A serial port path
//! works too with the crate's `serial` feature. The documentation quotes the parts between the
//! `[...]` and `[end]` comments. Generated: do not edit.

use std::cell::Cell;
use std::error::Error;
use std::f32::consts::FRAC_PI_2;
use std::process::ExitCode;
use std::rc::Rc;

use mipcodec::device::{connect, DEFAULT_BAUD};
use mipcodec::dispatch::write_packet_json;
use mipcodec::Device as Model;

const PROG: &str = "configure_and_stream";

fn run(address: &str, count: usize) -> Result<(), Box<dyn Error>> {
    // [connect]
    // The device model selects per-device layouts and refuses what the model does not support.
    let mut device = connect(address, Some(Model::Cv7Ins), DEFAULT_BAUD)?;
    device.base().ping()?;
    println!("ping: ack");
    let info = device.base().get_device_info()?;
    println!("device info: {info:?}");
    // [end]

    // [configure]
    device
        .threedm()
        .sensor_to_vehicle_euler()
        .write(0.0, FRAC_PI_2, FRAC_PI_2)?;
    let setting = device.threedm().sensor_to_vehicle_euler().read()?;
    println!("sensor_to_vehicle_euler: {setting:?}");
    // [end]

    // [stream]
    // Every packet that is not a reply goes to the handlers, also while a command waits.
    let seen = Rc::new(Cell::new(0usize));
    let counter = Rc::clone(&seen);
    device.on_packet(move |offset, packet| {
        if counter.get() < count {
            let mut line = String::new();
            let _ = write_packet_json(&mut line, offset, packet, Some(Model::Cv7Ins));
            println!("data {line}");
        }
        counter.set(counter.get() + 1);
    });
    device
        .threedm()
        .data_stream_control()
        .write_cv7_ins(0x80, true)?;
    // Listen in slices of 100 ms until N packets came (or 10 s passed).
    for _ in 0..100 {
        if seen.get() >= count {
            break;
        }
        device.listen(100)?;
    }
    if seen.get() < count {
        return Err(format!("{} of {count} data packets received", seen.get()).into());
    }
    // [end]
    Ok(())
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let count = match args.get(1).map(|n| n.parse::<usize>()) {
        None => Ok(5),
        Some(Ok(n)) if n > 0 => Ok(n),
        Some(_) => Err(()),
    };
    let (Some(address), Ok(count), true) = (args.first(), count, args.len() <= 2) else {
        eprintln!("usage: {PROG} tcp:HOST:PORT|SERIAL_PORT [N]");
        return ExitCode::from(2);
    };
    match run(address, count) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("{PROG}: {e}");
            ExitCode::FAILURE
        }
    }
}
