//! `cv7_ahrs ADDRESS [--samples N] [--deadline-s N]`: a 3DM-CV7-GNSS/INS used as an AHRS on its
//! own magnetometer, the manual's getting-started flow (3dm-cv7-ins-docs.txt "Getting Started",
//! "Filter Initialization", "Filter Aiding Measurements"; contract: tests/apps/README.md).
//!
//! It configures the device through the crate's typed command API (idle, device information, the
//! filter data message, the magnetometer as the only aiding source, heading initialized from the
//! magnetometer), resets the filter and resumes. Then it prints `mode N` whenever the filter mode
//! changes and, once in AHRS mode or better, one JSON line per filter packet until `--samples`
//! were printed (exit 0). Wrong arguments: exit 2; a command that is not acknowledged, a
//! connection that fails or the deadline passing: exit 1.

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
use mipcodec::session::for_each_field;
use mipcodec::types::{
    AidingMeasurementSource, DescriptorRate, FilterInitialConditionSource, FilterModeCv7,
    FilterReferenceFrame, HeadingAlignmentMethods,
};
use mipcodec::{Device as Model, FieldValue};

const USAGE: &str = "usage: cv7_ahrs ADDRESS [--samples N] [--deadline-s N]";

/// The filter (navigation) data set and the fields configured in it.
const FILTER_SET: u8 = 0x82;
const GPS_TIMESTAMP: u8 = 0x11;
const FILTER_STATUS: u8 = 0x10;
const EULER_ANGLES: u8 = 0x05;
/// Filter data rate (Hz): the decimation is the base rate divided by it.
const RATE_HZ: u16 = 10;
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

// ------------------------------------------------------------------------------ navigation data

/// What the filter data handler keeps between packets.
struct Navigation {
    /// The filter mode last printed.
    mode: Option<u16>,
    /// AHRS samples printed, and how many to print.
    printed: usize,
    wanted: usize,
    /// Writing to stdout failed.
    output: Option<io::Error>,
}

/// The fields of one filter data packet.
#[derive(Default)]
struct Sample {
    tow: Option<f64>,
    mode: Option<u16>,
    euler: Option<([f32; 3], u16)>,
}

impl Navigation {
    /// Handles one filter data packet (0x82).
    fn on_filter_packet(&mut self, packet: &Packet<'_>) {
        let mut s = Sample::default();
        for_each_field(packet, Some(Model::Cv7Ins), |_, value| {
            let FieldValue::FilterData(field) = value else {
                return;
            };
            match field {
                FilterData::GpsTimestamp(v) => s.tow = Some(v.tow),
                FilterData::FilterStatus(FilterStatus::Cv7Ins(v)) => {
                    s.mode = Some(v.filter_state.0)
                }
                FilterData::EulerAngles(v) => {
                    s.euler = Some(([v.roll, v.pitch, v.yaw], v.valid_flags.0));
                }
                _ => {}
            }
        });
        let Some(mode) = s.mode else {
            return;
        };
        if self.mode != Some(mode) {
            self.mode = Some(mode);
            self.emit(&format!("mode {mode}"));
        }
        if mode < FilterModeCv7::AHRS.0 || self.printed >= self.wanted {
            return;
        }
        if let (Some(tow), Some((euler, euler_valid))) = (s.tow, s.euler) {
            self.printed += 1;
            self.emit(&format!(
                "{{\"tow\":{},\"euler\":[{},{},{}],\"euler_valid\":{euler_valid}}}",
                Num(tow),
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
    let mut device = connect(&options.address, Some(Model::Cv7Ins), DEFAULT_BAUD)?;
    // Every filter data packet goes to one handler, also while a command waits for its reply.
    let nav = Rc::new(RefCell::new(Navigation {
        mode: None,
        printed: 0,
        wanted: options.samples,
        output: None,
    }));
    let handler = Rc::clone(&nav);
    device.on_packet(move |_offset, packet| {
        if packet.set() == FILTER_SET {
            handler.borrow_mut().on_filter_packet(packet);
        }
    });
    configure(&mut device, &nav)?;
    navigate(&mut device, &nav, options, started)
}

/// The getting-started flow, each step acknowledged.
fn configure(device: &mut Device, nav: &RefCell<Navigation>) -> Result<(), Box<dyn Error>> {
    device.base().ping()?;
    device.base().set_to_idle()?;
    let info = device.base().get_device_info()?.info;
    {
        let mut n = nav.borrow_mut();
        n.emit(&format!(
            "model {}",
            String::from_utf8_lossy(info.model_name.trimmed())
        ));
        n.emit(&format!(
            "serial {}",
            String::from_utf8_lossy(info.serial_number.trimmed())
        ));
        n.emit(&format!("firmware {}", info.firmware_version));
    }
    let base = device.threedm().get_base_rate(FILTER_SET)?.rate;
    let decimation = base / RATE_HZ;
    if decimation == 0 {
        return Err(format!("the filter data base rate is {base} Hz, below {RATE_HZ} Hz").into());
    }
    let fields = [GPS_TIMESTAMP, FILTER_STATUS, EULER_ANGLES].map(|descriptor| DescriptorRate {
        descriptor,
        decimation,
    });
    let descriptors = BoundedVec::from_slice(&fields).ok_or("too many descriptors")?;
    device
        .threedm()
        .message_format()
        .write(FILTER_SET, descriptors)?;
    // The magnetometer only: no GNSS (an AHRS has no position).
    for (source, enable) in [
        (AidingMeasurementSource::MAGNETOMETER, true),
        (AidingMeasurementSource::GNSS_POS_VEL, false),
        (AidingMeasurementSource::GNSS_HEADING, false),
    ] {
        device
            .filter()
            .aiding_measurement_control()
            .write(source, enable)?;
    }
    device.filter().initialization_configuration().write(
        0, // do not wait for the run command
        FilterInitialConditionSource::AUTO_POS_VEL_ATT,
        HeadingAlignmentMethods(HeadingAlignmentMethods::MAGNETOMETER),
        0.0,
        0.0,
        0.0,
        [0.0; 3],
        [0.0; 3],
        FilterReferenceFrame::LLH,
    )?;
    device.filter().reset_filter()?;
    device.base().resume()?;
    Ok(())
}

/// Reads the filter data until the samples were printed or the deadline (counted from the start)
/// passes.
fn navigate(
    device: &mut Device,
    nav: &RefCell<Navigation>,
    options: &Options,
    started: Instant,
) -> Result<(), Box<dyn Error>> {
    let deadline = started + Duration::from_secs(options.deadline_s);
    loop {
        {
            let mut n = nav.borrow_mut();
            if let Some(e) = n.output.take() {
                return Err(format!("cannot write the output: {}", io_message(&e)).into());
            }
            if n.printed >= n.wanted {
                return Ok(());
            }
        }
        let now = Instant::now();
        if now >= deadline {
            let n = nav.borrow();
            return Err(match n.mode {
                Some(m) => format!(
                    "{} of {} AHRS samples within {} s (filter mode {m})",
                    n.printed, n.wanted, options.deadline_s
                ),
                None => format!("no filter status within {} s", options.deadline_s),
            }
            .into());
        }
        let wait = deadline.saturating_duration_since(now).min(READ_SLICE);
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
