//! `gx5_polling ADDRESS [--samples N] [--deadline-s N]`: a 3DM-GX5-45 application polling for
//! data as the manual's polling example does (3dm-gx5-45-dcp.txt section 2.4.2; contract:
//! tests/apps/README.md).
//!
//! It configures the device through the crate's typed command API (idle, device information, the
//! IMU and estimation filter message formats) and leaves it idle: no resume, no stream; it
//! initializes the filter as the manual's step 7 does (poll the complementary filter's Euler
//! angles, Set Initial Attitude with them). Then every 100 ms it sends Poll IMU Data (0x0C,0x01)
//! and Poll Estimation Filter Data (0x0C,0x03), the ACK/NACK not suppressed, each answered by its
//! ACK and one data packet. It prints `imu ok` once the IMU data has accelerometer and gyro, `state
//! N` whenever the filter state changes and, once the solution is valid, one JSON line per polled
//! filter packet until `--samples` were printed (exit 0). Wrong arguments: exit 2; a command that
//! is not acknowledged, a connection that fails or the deadline passing: exit 1.

use std::cell::RefCell;
use std::error::Error;
use std::fmt;
use std::io::{self, Write};
use std::process::ExitCode;
use std::rc::Rc;
use std::time::{Duration, Instant};

use mipcodec::bounded::BoundedVec;
use mipcodec::device::{connect, io_message, Device, DEFAULT_BAUD};
use mipcodec::fields::Packet;
use mipcodec::filter_data::{FilterStatus, SetField as FilterData};
use mipcodec::sensor::SetField as ImuData;
use mipcodec::session::for_each_field;
use mipcodec::types::{DescriptorRate, FilterStateGx5, Gx5PollDescriptor, Gx5PollOption};
use mipcodec::{Device as Model, FieldValue};

const USAGE: &str = "usage: gx5_polling ADDRESS [--samples N] [--deadline-s N]";

/// The IMU (0x80) and estimation filter (0x82) data sets and the fields configured in them.
const IMU_SET: u8 = 0x80;
const FILTER_SET: u8 = 0x82;
const SCALED_ACCEL: u8 = 0x04;
const SCALED_GYRO: u8 = 0x05;
const CF_EULER: u8 = 0x0C;
const GPS_TIMESTAMP: u8 = 0x11;
const FILTER_STATUS: u8 = 0x10;
const LLH_POSITION: u8 = 0x01;
const EULER_ANGLES: u8 = 0x05;
/// Data rates (Hz): the decimation is the base rate divided by them.
const IMU_RATE_HZ: u16 = 100;
const FILTER_RATE_HZ: u16 = 10;
/// The fields of the two messages (and of the polls).
const IMU_FIELDS: [u8; 2] = [SCALED_ACCEL, SCALED_GYRO];
const FILTER_FIELDS: [u8; 4] = [GPS_TIMESTAMP, FILTER_STATUS, LLH_POSITION, EULER_ANGLES];
/// How often the data is polled.
const POLL_PERIOD: Duration = Duration::from_millis(100);
/// How long one read waits at most, so that a finished run ends promptly.
const READ_SLICE: Duration = Duration::from_millis(20);

/// The command line.
struct Options {
    address: String,
    samples: usize,
    deadline_s: u64,
}

/// The options, or `None` for wrong arguments.
fn parse_args(args: &[String]) -> Option<Options> {
    let (mut samples, mut deadline_s) = (20u64, 60u64);
    let mut positional = Vec::new();
    let mut it = args.iter();
    while let Some(arg) = it.next() {
        let slot = match arg.as_str() {
            "--samples" => &mut samples,
            "--deadline-s" => &mut deadline_s,
            other if other.starts_with('-') && other.len() > 1 => return None,
            _ => {
                positional.push(arg.clone());
                continue;
            }
        };
        *slot = it.next()?.parse::<u64>().ok().filter(|&n| n > 0)?;
    }
    let [address]: [String; 1] = positional.try_into().ok()?;
    Some(Options {
        address,
        samples: usize::try_from(samples).ok()?,
        deadline_s,
    })
}

// ------------------------------------------------------------------------------ the data

/// What the data handler keeps between packets.
struct Reader {
    /// `imu ok` was printed.
    imu_seen: bool,
    /// The complementary filter's Euler angles (0x80,0x0C), once polled.
    cf_euler: Option<[f32; 3]>,
    /// The filter state last printed.
    state: Option<u16>,
    /// Valid-solution samples printed, and how many to print.
    printed: usize,
    wanted: usize,
    /// Writing to stdout failed.
    output: Option<io::Error>,
}

/// The fields of one estimation filter data packet.
#[derive(Default)]
struct Sample {
    tow: Option<f64>,
    state: Option<u16>,
    llh: Option<([f64; 3], u16)>,
    euler: Option<([f32; 3], u16)>,
}

impl Reader {
    /// Handles one IMU data packet (0x80).
    fn on_imu_packet(&mut self, packet: &Packet<'_>) {
        let (mut accel, mut gyro) = (false, false);
        for_each_field(packet, Some(Model::Gx5_45), |_, value| match value {
            FieldValue::Sensor(ImuData::ScaledAccel(_)) => accel = true,
            FieldValue::Sensor(ImuData::ScaledGyro(_)) => gyro = true,
            FieldValue::Sensor(ImuData::CfEulerAngles(v)) => {
                self.cf_euler = Some([v.roll, v.pitch, v.yaw]);
            }
            _ => {}
        });
        if accel && gyro && !self.imu_seen {
            self.imu_seen = true;
            self.emit("imu ok");
        }
    }

    /// Handles one estimation filter data packet (0x82).
    fn on_filter_packet(&mut self, packet: &Packet<'_>) {
        let mut s = Sample::default();
        for_each_field(packet, Some(Model::Gx5_45), |_, value| {
            let FieldValue::FilterData(field) = value else {
                return;
            };
            match field {
                FilterData::GpsTimestamp(v) => s.tow = Some(v.tow),
                FilterData::FilterStatus(FilterStatus::Gx5_45(v)) => {
                    s.state = Some(v.filter_state.0)
                }
                FilterData::LlhPosition(v) => {
                    s.llh = Some((
                        [v.latitude, v.longitude, v.ellipsoid_height],
                        v.valid_flags.0,
                    ));
                }
                FilterData::EulerAngles(v) => {
                    s.euler = Some(([v.roll, v.pitch, v.yaw], v.valid_flags.0));
                }
                _ => {}
            }
        });
        let Some(state) = s.state else {
            return;
        };
        if self.state != Some(state) {
            self.state = Some(state);
            self.emit(&format!("state {state}"));
        }
        if state != FilterStateGx5::RUN_SOLUTION_VALID.0 || self.printed >= self.wanted {
            return;
        }
        if let (Some(tow), Some((llh, llh_valid)), Some((euler, euler_valid))) =
            (s.tow, s.llh, s.euler)
        {
            self.printed += 1;
            self.emit(&format!(
                "{{\"tow\":{},\"lat\":{},\"lon\":{},\"height\":{},\
                 \"euler\":[{},{},{}],\"llh_valid\":{llh_valid},\"euler_valid\":{euler_valid}}}",
                Num(tow),
                Num(llh[0]),
                Num(llh[1]),
                Num(llh[2]),
                Num(euler[0].into()),
                Num(euler[1].into()),
                Num(euler[2].into()),
            ));
        }
    }

    /// Prints one line now; the first failure is kept.
    fn emit(&mut self, line: &str) {
        if self.output.is_none() {
            let mut out = io::stdout().lock();
            if let Err(e) = writeln!(out, "{line}").and_then(|()| out.flush()) {
                self.output = Some(e);
            }
        }
    }
}

/// A JSON number that reads back as the same value (`null` for NaN and infinities).
struct Num(f64);

impl fmt::Display for Num {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.0.is_finite() {
            write!(f, "{:?}", self.0)
        } else {
            f.write_str("null")
        }
    }
}

// ------------------------------------------------------------------------------ the application

fn run(options: &Options) -> Result<(), Box<dyn Error>> {
    let started = Instant::now();
    let mut device = connect(&options.address, Some(Model::Gx5_45), DEFAULT_BAUD)?;
    // Every data packet goes to one handler, also while a command waits for its reply.
    let reader = Rc::new(RefCell::new(Reader {
        imu_seen: false,
        cf_euler: None,
        state: None,
        printed: 0,
        wanted: options.samples,
        output: None,
    }));
    let handler = Rc::clone(&reader);
    device.on_packet(move |_offset, packet| match packet.set() {
        IMU_SET => handler.borrow_mut().on_imu_packet(packet),
        FILTER_SET => handler.borrow_mut().on_filter_packet(packet),
        _ => {}
    });
    configure(&mut device, &reader)?;
    poll_data(&mut device, &reader, options, started)
}

/// The setup sequence of the manual, each step acknowledged; no stream enable.
fn configure(device: &mut Device, reader: &RefCell<Reader>) -> Result<(), Box<dyn Error>> {
    device.base().ping()?;
    device.base().set_to_idle()?;
    let info = device.base().get_device_info()?.info;
    {
        let mut r = reader.borrow_mut();
        r.emit(&format!(
            "model {}",
            String::from_utf8_lossy(info.model_name.trimmed())
        ));
        r.emit(&format!(
            "serial {}",
            String::from_utf8_lossy(info.serial_number.trimmed())
        ));
        r.emit(&format!("firmware {}", info.firmware_version));
    }
    let imu_base = device.threedm().get_imu_base_rate()?.rate;
    let filter_base = device.threedm().get_filter_base_rate()?.rate;
    if imu_base < IMU_RATE_HZ || filter_base < FILTER_RATE_HZ {
        return Err(format!(
            "base rates {imu_base} Hz (IMU) and {filter_base} Hz (filter) are too low"
        )
        .into());
    }
    let imu = IMU_FIELDS.map(|descriptor| DescriptorRate {
        descriptor,
        decimation: imu_base / IMU_RATE_HZ,
    });
    device
        .threedm()
        .imu_message_format()
        .write(BoundedVec::from_slice(&imu).ok_or("too many descriptors")?)?;
    let filter = FILTER_FIELDS.map(|descriptor| DescriptorRate {
        descriptor,
        decimation: filter_base / FILTER_RATE_HZ,
    });
    device
        .threedm()
        .filter_message_format()
        .write(BoundedVec::from_slice(&filter).ok_or("too many descriptors")?)?;
    // No resume: the device stays idle and answers polls only.
    initialize_filter(device, reader)
}

/// The manual's step 7, Initialize the Filter (3dm-gx5-45-dcp.txt line 431): poll the
/// complementary filter's Euler angles (0x80,0x0C), then Set Initial Attitude (0x0D,0x02) with
/// them. (A device with auto-initialization enabled does not need it; its factory setting is not
/// documented, so the program does not rely on it.)
fn initialize_filter(device: &mut Device, reader: &RefCell<Reader>) -> Result<(), Box<dyn Error>> {
    let entry = Gx5PollDescriptor {
        descriptor: CF_EULER,
        reserved: 0,
    };
    device.threedm().poll_imu_data(
        Gx5PollOption::NORMAL,
        BoundedVec::from_slice(&[entry]).ok_or("too many descriptors")?,
    )?;
    // The data packet follows the ACK.
    let end = Instant::now() + Duration::from_secs(1);
    loop {
        let angles = reader.borrow().cf_euler;
        if let Some([roll, pitch, yaw]) = angles {
            device.filter().set_initial_attitude(roll, pitch, yaw)?;
            return Ok(());
        }
        if Instant::now() >= end {
            return Err("no complementary filter Euler angles (0x80,0x0C) after the poll".into());
        }
        device.listen(10)?;
    }
}

/// One Poll IMU Data and one Poll Estimation Filter Data, each acknowledged (its data packet
/// follows the ACK and reaches the handler).
fn poll(device: &mut Device) -> Result<(), Box<dyn Error>> {
    let entries = |fields: &[u8]| {
        let list: Vec<Gx5PollDescriptor> = fields
            .iter()
            .map(|&descriptor| Gx5PollDescriptor {
                descriptor,
                reserved: 0,
            })
            .collect();
        BoundedVec::from_slice(&list).ok_or("too many descriptors")
    };
    device
        .threedm()
        .poll_imu_data(Gx5PollOption::NORMAL, entries(&IMU_FIELDS)?)?;
    device
        .threedm()
        .poll_filter_data(Gx5PollOption::NORMAL, entries(&FILTER_FIELDS)?)?;
    Ok(())
}

/// Polls every period until the samples were printed or the deadline (counted from the start)
/// passes.
fn poll_data(
    device: &mut Device,
    reader: &RefCell<Reader>,
    options: &Options,
    started: Instant,
) -> Result<(), Box<dyn Error>> {
    let deadline = started + Duration::from_secs(options.deadline_s);
    let mut next_poll = Instant::now();
    loop {
        {
            let mut r = reader.borrow_mut();
            if let Some(e) = r.output.take() {
                return Err(format!("cannot write the output: {}", io_message(&e)).into());
            }
            if r.printed >= r.wanted {
                return Ok(());
            }
        }
        let now = Instant::now();
        if now >= deadline {
            let r = reader.borrow();
            return Err(match r.state {
                Some(s) => format!(
                    "{} of {} valid-solution samples within {} s (filter state {s})",
                    r.printed, r.wanted, options.deadline_s
                ),
                None => format!("no filter status within {} s", options.deadline_s),
            }
            .into());
        }
        if now >= next_poll {
            poll(device)?;
            // The next period; after a stall, a period from now rather than a burst.
            next_poll += POLL_PERIOD;
            if next_poll < now {
                next_poll = now + POLL_PERIOD;
            }
        }
        let wait = next_poll
            .min(deadline)
            .saturating_duration_since(Instant::now())
            .min(READ_SLICE);
        device.listen(u64::try_from(wait.as_millis()).unwrap_or(u64::MAX))?;
    }
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let Some(options) = parse_args(&args) else {
        eprintln!("{USAGE}");
        return ExitCode::from(2);
    };
    match run(&options) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            // a NACK, a timeout, a connection that failed, the deadline
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
