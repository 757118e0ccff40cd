//! `cv7_external_aiding ADDRESS FEED [--period-ms N] [--samples N] [--deadline-s N]`: the CV7-INS
//! navigation application with external aiding (tests/apps/README.md).
//!
//! It configures the device through the crate's typed command API (idle, defaults, gyro bias
//! capture, the filter data message, the aiding frames, the aiding sources, the filter's
//! initialization), resumes it, then sends the aiding measurements of FEED (external heading, LLH
//! position, NED velocity, body-frame velocity) every period while it reads the filter data
//! (0x82): `mode N` whenever the filter mode changes, then one JSON line per full-navigation
//! packet until `--samples` were printed (exit 0). Wrong arguments: exit 2; a command that is not
//! acknowledged, a connection or feed that fails, or the deadline passing: exit 1.

use std::cell::RefCell;
use std::error::Error;
use std::fmt;
use std::io::{self, Write};
use std::process::ExitCode;
use std::rc::Rc;
use std::time::{Duration, Instant};

use mipcodec::bounded::BoundedVec;
use mipcodec::device::{connect, io_message, Device, SessionError, DEFAULT_BAUD};
use mipcodec::fields::Packet;
use mipcodec::filter_data::{FilterStatus, SetField as FilterData};
use mipcodec::session::for_each_field;
use mipcodec::types::{
    AidingFrameEuler, AidingFrameFormat, AidingFrameRotation, AidingLlhValidFlags,
    AidingMeasurementSource, AidingTime, AidingTimebase, AidingVectorValidFlags, DescriptorRate,
    FilterInitialConditionSource, FilterModeCv7, FilterReferenceFrame, HeadingAlignmentMethods,
};
use mipcodec::{Device as Model, FieldValue};

const PROG: &str = "cv7_external_aiding";
const USAGE: &str =
    "usage: cv7_external_aiding ADDRESS FEED [--period-ms N] [--samples N] [--deadline-s N]";

/// The filter (navigation) data set and the fields configured in it.
const FILTER_SET: u8 = 0x82;
const GPS_TIMESTAMP: u8 = 0x11;
const FILTER_STATUS: u8 = 0x10;
const LLH_POSITION: u8 = 0x01;
const NED_VELOCITY: u8 = 0x02;
const EULER_ANGLES: u8 = 0x05;
/// Filter data rate (Hz): the decimation is the base rate divided by it.
const RATE_HZ: u16 = 10;
/// Aiding frames: the heading sensor, the GNSS antenna, the body-frame velocity sensor.
const HEADING_FRAME: u8 = 1;
const GNSS_FRAME: u8 = 2;
const BODY_VELOCITY_FRAME: u8 = 3;
/// Averaging time of the gyro bias capture (its reply comes after it).
const GYRO_BIAS_MS: u16 = 2000;
/// How long one read waits at most, so that a finished run ends promptly.
const READ_SLICE: Duration = Duration::from_millis(20);

/// The command line.
struct Options {
    address: String,
    feed: String,
    period_ms: u64,
    samples: usize,
    deadline_s: u64,
}

/// The options, or `None` for wrong arguments.
fn parse_args(args: &[String]) -> Option<Options> {
    let (mut period_ms, mut samples, mut deadline_s) = (500u64, 30u64, 60u64);
    let mut positional = Vec::new();
    let mut it = args.iter();
    while let Some(arg) = it.next() {
        let slot = match arg.as_str() {
            "--period-ms" => &mut period_ms,
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
    let [address, feed]: [String; 2] = positional.try_into().ok()?;
    Some(Options {
        address,
        feed,
        period_ms,
        samples: usize::try_from(samples).ok()?,
        deadline_s,
    })
}

// ------------------------------------------------------------------------------ the aiding feed

/// One row of the feed: what the aiding sensors measured at one instant.
struct Row {
    tow: f64,
    ns: u64,
    lat: f64,
    lon: f64,
    height: f64,
    vel: [f32; 3],
    heading: f32,
    body: [f32; 3],
}

/// The rows of the feed file, sorted by time of week.
fn read_feed(path: &str) -> Result<Vec<Row>, String> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read the feed {path}: {}", io_message(&e)))?;
    let mut rows = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        rows.push(parse_row(line).ok_or_else(|| {
            format!(
                "{path}:{}: want 12 numbers: tow ns lat lon height vn ve vd heading bx by bz",
                i + 1
            )
        })?);
    }
    if rows.is_empty() {
        return Err(format!("the feed {path} has no rows"));
    }
    rows.sort_by(|a, b| a.tow.total_cmp(&b.tow));
    Ok(rows)
}

fn parse_row(line: &str) -> Option<Row> {
    let words: Vec<&str> = line.split_whitespace().collect();
    if words.len() != 12 {
        return None;
    }
    let mut x = [0.0f64; 12];
    for (k, word) in words.iter().enumerate() {
        if k != 1 {
            x[k] = word.parse::<f64>().ok().filter(|v| v.is_finite())?;
        }
    }
    Some(Row {
        tow: x[0],
        ns: words[1].parse().ok()?,
        lat: x[2],
        lon: x[3],
        height: x[4],
        vel: [x[5] as f32, x[6] as f32, x[7] as f32],
        heading: x[8] as f32,
        body: [x[9] as f32, x[10] as f32, x[11] as f32],
    })
}

/// The row nearest `tow` (rows: sorted, not empty).
fn nearest(rows: &[Row], tow: f64) -> &Row {
    let i = rows.partition_point(|r| r.tow < tow).min(rows.len() - 1);
    match i.checked_sub(1).map(|j| &rows[j]) {
        Some(before) if tow - before.tow <= rows[i].tow - tow => before,
        _ => &rows[i],
    }
}

// ------------------------------------------------------------------------------ navigation data

/// What the filter data handler keeps between packets.
struct Navigation {
    /// The latest GPS time of week (0x82,0x11): aiding is sent for it.
    tow: Option<f64>,
    /// The filter mode last printed.
    mode: Option<u16>,
    /// Full-navigation samples printed, and how many to print.
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
    llh: Option<([f64; 3], u16)>,
    vel: Option<[f32; 3]>,
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
                FilterData::LlhPosition(v) => {
                    s.llh = Some((
                        [v.latitude, v.longitude, v.ellipsoid_height],
                        v.valid_flags.0,
                    ));
                }
                FilterData::NedVelocity(v) => s.vel = Some([v.north, v.east, v.down]),
                FilterData::EulerAngles(v) => {
                    s.euler = Some(([v.roll, v.pitch, v.yaw], v.valid_flags.0));
                }
                _ => {}
            }
        });
        if s.tow.is_some() {
            self.tow = s.tow;
        }
        let Some(mode) = s.mode else {
            return;
        };
        if self.mode != Some(mode) {
            self.mode = Some(mode);
            self.emit(&format!("mode {mode}"));
        }
        if mode != FilterModeCv7::FULL_NAV.0 || self.printed >= self.wanted {
            return;
        }
        if let (Some(tow), Some((llh, llh_valid)), Some(vel), Some((euler, euler_valid))) =
            (s.tow, s.llh, s.vel, s.euler)
        {
            self.printed += 1;
            self.emit(&format!(
                "{{\"tow\":{},\"lat\":{},\"lon\":{},\"height\":{},\"vel\":[{},{},{}],\
                 \"euler\":[{},{},{}],\"llh_valid\":{llh_valid},\"euler_valid\":{euler_valid}}}",
                Num(tow),
                Num(llh[0]),
                Num(llh[1]),
                Num(llh[2]),
                Num(vel[0].into()),
                Num(vel[1].into()),
                Num(vel[2].into()),
                Num(euler[0].into()),
                Num(euler[1].into()),
                Num(euler[2].into()),
            ));
        }
    }

    /// Prints one line now (stdout is line-buffered); the first failure is kept.
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
    let feed = read_feed(&options.feed)?;
    let mut device = connect(&options.address, Some(Model::Cv7Ins), DEFAULT_BAUD)?;
    // Every filter data packet goes to one handler, also while a command waits for its reply.
    let nav = Rc::new(RefCell::new(Navigation {
        tow: None,
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
    configure(&mut device)?;
    navigate(&mut device, &nav, &feed, options, started)
}

/// The start of the flow, in the order of the issue, each step acknowledged.
fn configure(device: &mut Device) -> Result<(), Box<dyn Error>> {
    device.base().ping()?;
    device.base().set_to_idle()?;
    let info = device.base().get_device_info()?.info;
    eprintln!(
        "{PROG}: {} (firmware {})",
        String::from_utf8_lossy(info.model_name.trimmed()),
        info.firmware_version
    );
    device.threedm().device_startup_settings().default()?;
    // The reply comes after the averaging time: the command's timeout includes it.
    device.threedm().capture_gyro_bias(GYRO_BIAS_MS)?;
    let base = device.threedm().get_base_rate(FILTER_SET)?.rate;
    let decimation = base / RATE_HZ;
    if decimation == 0 {
        return Err(format!("the filter data base rate is {base} Hz, below {RATE_HZ} Hz").into());
    }
    let fields = [
        GPS_TIMESTAMP,
        FILTER_STATUS,
        LLH_POSITION,
        NED_VELOCITY,
        EULER_ANGLES,
    ]
    .map(|descriptor| DescriptorRate {
        descriptor,
        decimation,
    });
    let descriptors = BoundedVec::from_slice(&fields).ok_or("too many descriptors")?;
    device
        .threedm()
        .message_format()
        .write(FILTER_SET, descriptors)?;
    for frame in [HEADING_FRAME, GNSS_FRAME, BODY_VELOCITY_FRAME] {
        device.aiding().frame_config().write(
            frame,
            AidingFrameFormat::EULER,
            false,
            [0.0; 3],
            AidingFrameRotation::Euler(AidingFrameEuler { euler: [0.0; 3] }),
        )?;
    }
    for source in [
        AidingMeasurementSource::GNSS_POS_VEL,
        AidingMeasurementSource::EXTERNAL_HEADING,
    ] {
        device
            .filter()
            .aiding_measurement_control()
            .write(source, true)?;
    }
    device.filter().initialization_configuration().write(
        0, // do not wait for the run command
        FilterInitialConditionSource::AUTO_POS_VEL_ATT,
        HeadingAlignmentMethods(HeadingAlignmentMethods::EXTERNAL),
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

/// Sends the aiding of `row`: heading, position and velocity stamped with the time they were
/// measured (the device's internal reference time), body-frame velocity with its arrival.
fn send_aiding(device: &mut Device, row: &Row) -> Result<(), SessionError> {
    let measured = AidingTime {
        timebase: AidingTimebase::INTERNAL_REFERENCE,
        reserved: 0,
        nanoseconds: row.ns,
    };
    let arrival = AidingTime {
        timebase: AidingTimebase::TIME_OF_ARRIVAL,
        reserved: 0,
        nanoseconds: 0,
    };
    let llh = AidingLlhValidFlags(
        AidingLlhValidFlags::LATITUDE
            | AidingLlhValidFlags::LONGITUDE
            | AidingLlhValidFlags::HEIGHT,
    );
    let xyz = AidingVectorValidFlags(
        AidingVectorValidFlags::X | AidingVectorValidFlags::Y | AidingVectorValidFlags::Z,
    );
    device
        .aiding()
        .true_heading(measured, HEADING_FRAME, row.heading, 0.01, 1)?;
    device.aiding().llh_position(
        measured, GNSS_FRAME, row.lat, row.lon, row.height, [1.0; 3], llh,
    )?;
    device
        .aiding()
        .ned_velocity(measured, GNSS_FRAME, row.vel, [0.1; 3], xyz)?;
    device
        .aiding()
        .body_frame_velocity(arrival, BODY_VELOCITY_FRAME, row.body, [0.1; 3], xyz)?;
    Ok(())
}

/// Aids every period (once a GPS time is known) and reads the filter data until the samples
/// were printed or the deadline (counted from the start) passes.
fn navigate(
    device: &mut Device,
    nav: &RefCell<Navigation>,
    feed: &[Row],
    options: &Options,
    started: Instant,
) -> Result<(), Box<dyn Error>> {
    let deadline = started + Duration::from_secs(options.deadline_s);
    let period = Duration::from_millis(options.period_ms);
    let mut next_aiding = Instant::now();
    loop {
        let tow = {
            let mut n = nav.borrow_mut();
            if let Some(e) = n.output.take() {
                return Err(format!("cannot write the output: {}", io_message(&e)).into());
            }
            if n.printed >= n.wanted {
                return Ok(());
            }
            n.tow
        };
        let now = Instant::now();
        if now >= deadline {
            let n = nav.borrow();
            return Err(match n.mode {
                Some(m) if m == FilterModeCv7::FULL_NAV.0 => format!(
                    "{} of {} full-navigation samples within {} s",
                    n.printed, n.wanted, options.deadline_s
                ),
                Some(m) => format!(
                    "no full navigation within {} s (filter mode {m})",
                    options.deadline_s
                ),
                None => format!("no filter status within {} s", options.deadline_s),
            }
            .into());
        }
        if now >= next_aiding {
            if let Some(tow) = tow {
                send_aiding(device, nearest(feed, tow))?;
            }
            // The next period; after a stall, a period from now rather than a burst.
            next_aiding += period;
            if next_aiding < now {
                next_aiding = now + period;
            }
        }
        let wait = next_aiding
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
            // a NACK, a timeout, a connection or feed that failed, the deadline
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
