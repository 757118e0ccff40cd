//! `configure_and_stream ADDRESS [COUNT]`: configures a MS-IMU3020 with the crate's command session and
//! prints COUNT data packets (default 5).
//!
//! ADDRESS is `tcp:HOST:PORT` or a serial port path (with the crate's `serial` feature). The
//! program pings the device, reads its get device model, writes then reads one setting
//! (IMU sample rate configure), sets the data message (Select sensors (Rev A)), enables the stream
//! (Data on/off) and prints the fields of IMU Data Message (0xA2) through one
//! handler per data descriptor. A NACK, a timeout or a refused command ends it with a message and
//! exit status 1. Run it with `cargo run --example configure_and_stream -- tcp:192.168.1.100:5000`.
//! The documentation quotes the parts between the `[...]` and `[end]` comments. Generated: do not
//! edit.

use std::cell::Cell;
use std::error::Error;
use std::process::ExitCode;
use std::rc::Rc;

use mscipcodec::device::{connect, Device, DEFAULT_BAUD};
use mscipcodec::{Device as Model, FieldValue};

const PROG: &str = "configure_and_stream";
const WAIT_MS: u64 = 5000; // how long to wait for the data packets

fn run(address: &str, count: usize) -> Result<(), Box<dyn Error>> {
    // [connect]
    // The device model selects per-device layouts and refuses what the model does not support.
    let mut device = connect(address, Some(Model::MsImu3020), DEFAULT_BAUD)?;
    device.base().ping()?;
    let info = device.base().get_device_model()?;
    println!("device {info:?}");
    // [end]
    configure(&mut device)?;
    stream(&mut device, count)
}

fn configure(device: &mut Device) -> Result<(), Box<dyn Error>> {
    // [configure]
    device.imu_config().sample_rate().write(10)?;
    let setting = device.imu_config().sample_rate().read()?;
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
        if packet.set() == 0xA2 {
            counter.set(counter.get() + 1);
        }
    });
    let seen = Rc::clone(&packets);
    device.on_field(0xA2, 0x81, move |value, _packet| {
        if let FieldValue::ImuData(mscipcodec::imu_data::SetField::ScaledAccel(v)) = value {
            if seen.get() <= count {
                println!("scaled_accel {v:?}"); // on_packet has counted this packet
            }
        }
    });
    let seen = Rc::clone(&packets);
    device.on_field(0xA2, 0x82, move |value, _packet| {
        if let FieldValue::ImuData(mscipcodec::imu_data::SetField::ScaledGyro(v)) = value {
            if seen.get() <= count {
                println!("scaled_gyro {v:?}"); // on_packet has counted this packet
            }
        }
    });
    let sensors = mscipcodec::bounded::BoundedVec::from_slice(&[
        mscipcodec::types::SensorCode::SCALED_ACCEL,
        mscipcodec::types::SensorCode::SCALED_GYRO,
    ])
    .ok_or("too many sensors")?;
    device.imu_config().select_sensors().write(0, sensors)?;
    device
        .imu_config()
        .data_on_off()
        .write(mscipcodec::types::OnOff::ON)?;
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
