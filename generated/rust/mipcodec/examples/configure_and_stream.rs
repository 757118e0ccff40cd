//! `configure_and_stream ADDRESS [COUNT]`: configures a 3DM-CV7-GNSS/INS with the crate's command session and
//! prints COUNT data packets (default 5).
//!
//! ADDRESS is `tcp:HOST:PORT` or a serial port path (with the crate's `serial` feature). The
//! program pings the device, reads its get device information, writes then reads one setting
//! (Sensor-to-vehicle frame transformation (Euler)), sets the data message (Message format), enables the stream
//! (Data stream control) and prints the fields of Sensor (IMU) Data Set (0x80) through one
//! handler per data descriptor. A NACK, a timeout or a refused command ends it with a message and
//! exit status 1. Run it with `cargo run --example configure_and_stream -- tcp:192.168.1.100:5000`.
//! The documentation quotes the parts between the `[...]` and `[end]` comments. Generated: do not
//! edit.

use std::cell::Cell;
use std::error::Error;
use std::process::ExitCode;
use std::rc::Rc;

use mipcodec::device::{connect, Device, DEFAULT_BAUD};
use mipcodec::{Device as Model, FieldValue};

const PROG: &str = "configure_and_stream";
const WAIT_MS: u64 = 5000; // how long to wait for the data packets

fn run(address: &str, count: usize) -> Result<(), Box<dyn Error>> {
    // [connect]
    // The device model selects per-device layouts and refuses what the model does not support.
    let mut device = connect(address, Some(Model::Cv7Ins), DEFAULT_BAUD)?;
    device.base().ping()?;
    let info = device.base().get_device_info()?;
    println!("device {info:?}");
    // [end]
    configure(&mut device)?;
    stream(&mut device, count)
}

fn configure(device: &mut Device) -> Result<(), Box<dyn Error>> {
    // [configure]
    device
        .threedm()
        .sensor_to_vehicle_euler()
        .write(0.0, 0.0, 1.5)?;
    let setting = device.threedm().sensor_to_vehicle_euler().read()?;
    println!("setting {setting:?}");
    // [end]
    Ok(())
}

fn stream(device: &mut Device, count: usize) -> Result<(), Box<dyn Error>> {
    // [stream]
    // Every packet that is not a reply goes to the handlers, also while a command waits; the
    // packet handler runs before the field handlers of the same packet.
    let packets = Rc::new(Cell::new(0usize));
    let counter = Rc::clone(&packets);
    device.on_packet(move |_offset, packet| {
        if packet.set() == 0x80 {
            counter.set(counter.get() + 1);
        }
    });
    let seen = Rc::clone(&packets);
    device.on_field(0x80, 0x04, move |value, _packet| {
        if let FieldValue::Sensor(mipcodec::sensor::SetField::ScaledAccel(v)) = value {
            if seen.get() <= count {
                println!("scaled_accel {v:?}"); // on_packet has counted this packet
            }
        }
    });
    let seen = Rc::clone(&packets);
    device.on_field(0x80, 0x05, move |value, _packet| {
        if let FieldValue::Sensor(mipcodec::sensor::SetField::ScaledGyro(v)) = value {
            if seen.get() <= count {
                println!("scaled_gyro {v:?}"); // on_packet has counted this packet
            }
        }
    });
    let descriptors = mipcodec::bounded::BoundedVec::from_slice(&[
        mipcodec::types::DescriptorRate {
            descriptor: 4,
            decimation: 100,
        },
        mipcodec::types::DescriptorRate {
            descriptor: 5,
            decimation: 100,
        },
    ])
    .ok_or("too many descriptors")?;
    device.threedm().message_format().write(0x80, descriptors)?;
    device
        .threedm()
        .data_stream_control()
        .write_cv7_ins(0x80, true)?;
    let deadline = device.now_ms() + WAIT_MS;
    while packets.get() < count && device.now_ms() < deadline {
        device.listen(deadline.saturating_sub(device.now_ms()).min(100))?; // data packets reach the handlers
    }
    // [end]
    if packets.get() < count {
        return Err(format!("{} of {count} data packets in {WAIT_MS} ms", packets.get()).into());
    }
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
        eprintln!("usage: {PROG} ADDRESS [COUNT]");
        return ExitCode::from(2);
    };
    match run(address, count) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            // a NACK, a timeout, a refused command, a connection that failed
            eprintln!("{PROG}: {e}");
            ExitCode::FAILURE
        }
    }
}
