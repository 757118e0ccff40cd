//! The blocking session API (std): a [`Device`] runs commands over a [`Transport`] (TCP, or a
//! serial port with the `serial` feature), feeding every received byte to a
//! [`Session`], so data packets reach the handlers while a command
//! waits for its reply (`docs/conformance.md` §8). The typed command API
//! (the generated `command_api` module, `device.threedm().sensor_to_vehicle_euler().read()` and so on) is
//! generated on top of [`Device::call`].

use std::fmt;
use std::io::{self, Read, Write};
use std::net::{TcpStream, ToSocketAddrs};
use std::time::{Duration, Instant};

use crate::dispatch::{decode_field, Device as Model, FieldValue};
use crate::fields::{FieldItem, Fields, Packet};
use crate::session::{
    CommandFacts, CommandResult, Expect, ResultError, Session, SessionEvent, StartError,
    StartOptions, Status,
};

/// Baud rate of a serial port when none is given.
pub const DEFAULT_BAUD: u32 = 115_200;

/// A byte connection to a device.
pub trait Transport {
    /// Writes all of `bytes`.
    fn send(&mut self, bytes: &[u8]) -> io::Result<()>;
    /// Waits up to `timeout` for bytes and reads what arrived into `buf`: 0 when nothing came in
    /// time. The end of the connection is an error (`UnexpectedEof`).
    fn receive(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize>;
}

impl<T: Transport + ?Sized> Transport for Box<T> {
    fn send(&mut self, bytes: &[u8]) -> io::Result<()> {
        (**self).send(bytes)
    }
    fn receive(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
        (**self).receive(buf, timeout)
    }
}

/// A TCP connection (`tcp:HOST:PORT`).
pub struct TcpTransport {
    stream: TcpStream,
}

impl TcpTransport {
    /// Connects to `host:port` (a bracketed IPv6 host, `[::1]:port`, works too).
    pub fn connect(address: &str) -> io::Result<Self> {
        let mut last = io::Error::new(io::ErrorKind::InvalidInput, "no address");
        for addr in address.to_socket_addrs()? {
            match TcpStream::connect_timeout(&addr, Duration::from_secs(10)) {
                Ok(stream) => return Ok(Self::new(stream)),
                Err(e) => last = e,
            }
        }
        Err(last)
    }

    /// Wraps a connected stream.
    pub fn new(stream: TcpStream) -> Self {
        let _ = stream.set_nodelay(true);
        Self { stream }
    }
}

impl Transport for TcpTransport {
    fn send(&mut self, bytes: &[u8]) -> io::Result<()> {
        self.stream.write_all(bytes)
    }

    fn receive(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
        // A zero timeout means "block forever" to the socket: wait at least 1 ms.
        self.stream
            .set_read_timeout(Some(timeout.max(Duration::from_millis(1))))?;
        match self.stream.read(buf) {
            Ok(0) => Err(io::Error::new(
                io::ErrorKind::UnexpectedEof,
                "the device closed the connection",
            )),
            Ok(n) => Ok(n),
            Err(e)
                if matches!(
                    e.kind(),
                    io::ErrorKind::WouldBlock
                        | io::ErrorKind::TimedOut
                        | io::ErrorKind::Interrupted
                ) =>
            {
                Ok(0)
            }
            Err(e) => Err(e),
        }
    }
}

/// A serial port (the `serialport` crate; 8 data bits, no parity, one stop bit).
#[cfg(feature = "serial")]
pub struct SerialTransport {
    port: Box<dyn serialport::SerialPort>,
}

#[cfg(feature = "serial")]
impl SerialTransport {
    /// Opens the port `path` (`/dev/ttyUSB0`, `COM3`) at `baud`.
    pub fn open(path: &str, baud: u32) -> io::Result<Self> {
        let port = serialport::new(path, baud)
            .timeout(Duration::from_millis(10))
            .open()
            .map_err(io::Error::from)?;
        Ok(Self { port })
    }
}

#[cfg(feature = "serial")]
impl Transport for SerialTransport {
    fn send(&mut self, bytes: &[u8]) -> io::Result<()> {
        self.port.write_all(bytes)?;
        self.port.flush()
    }

    fn receive(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
        self.port
            .set_timeout(timeout.max(Duration::from_millis(1)))
            .map_err(io::Error::from)?;
        match self.port.read(buf) {
            Ok(n) => Ok(n),
            Err(e)
                if matches!(
                    e.kind(),
                    io::ErrorKind::TimedOut | io::ErrorKind::Interrupted
                ) =>
            {
                Ok(0)
            }
            Err(e) => Err(e),
        }
    }
}

/// Opens `address`: `tcp:HOST:PORT` (an IPv6 host in brackets) or a serial port path, opened
/// at `baud` (needs the `serial` feature).
pub fn open_transport(address: &str, baud: u32) -> Result<Box<dyn Transport>, SessionError> {
    if let Some(rest) = address.strip_prefix("tcp:") {
        let bad = || {
            SessionError::Address(format!(
                "bad TCP address '{address}' (expected tcp:HOST:PORT)"
            ))
        };
        let (host, port) = rest.rsplit_once(':').ok_or_else(bad)?;
        let port: u16 = port.parse().map_err(|_| bad())?;
        let host = host
            .strip_prefix('[')
            .and_then(|h| h.strip_suffix(']'))
            .unwrap_or(host);
        if host.is_empty() {
            return Err(bad());
        }
        let text = if host.contains(':') {
            format!("[{host}]:{port}")
        } else {
            format!("{host}:{port}")
        };
        return TcpTransport::connect(&text)
            .map(|t| Box::new(t) as Box<dyn Transport>)
            .map_err(|e| {
                SessionError::Connect(format!("cannot connect to {address}: {}", io_message(&e)))
            });
    }
    open_serial(address, baud)
}

#[cfg(feature = "serial")]
fn open_serial(path: &str, baud: u32) -> Result<Box<dyn Transport>, SessionError> {
    SerialTransport::open(path, baud)
        .map(|t| Box::new(t) as Box<dyn Transport>)
        .map_err(|e| SessionError::Connect(format!("cannot open {path}: {}", io_message(&e))))
}

#[cfg(not(feature = "serial"))]
fn open_serial(path: &str, _baud: u32) -> Result<Box<dyn Transport>, SessionError> {
    Err(SessionError::Connect(format!(
        "cannot open {path}: serial ports need the crate's `serial` feature (or use tcp:HOST:PORT)"
    )))
}

/// The OS error text without Rust's " (os error N)" suffix, as the other languages print it.
pub fn io_message(e: &io::Error) -> String {
    let text = e.to_string();
    match text.find(" (os error ") {
        Some(at) => text[..at].to_string(),
        None => text,
    }
}

/// An owned copy of a [`CommandResult`] (what the blocking API returns).
#[derive(Clone, Debug)]
pub struct Completed {
    /// The command layout's facts.
    pub facts: &'static CommandFacts,
    /// What happened.
    pub status: Status,
    /// The ack/nack code (ack, nack, invalid).
    pub code: Option<u32>,
    /// The error of an invalid or refused result.
    pub error: Option<ResultError>,
    /// The reply descriptors the command expected.
    pub expect: Expect,
    device: Option<Model>,
    reply: Vec<u8>,
    start: usize,
}

impl Completed {
    fn from_result(r: &CommandResult<'_>, device: Option<Model>) -> Self {
        Self {
            facts: r.facts,
            status: r.status,
            code: r.code,
            error: r.error,
            expect: r.expect,
            device,
            reply: r.reply_bytes().to_vec(),
            start: r.reply_offset(),
        }
    }

    /// True for ack and sent.
    pub fn is_ok(&self) -> bool {
        matches!(self.status, Status::Ack | Status::Sent)
    }

    /// The field entries of the reply.
    pub fn reply(&self) -> Fields<'_> {
        Fields::at(self.facts.set, &self.reply, self.start)
    }

    /// The typed reply field (the first decoded entry whose descriptor is expected, else the
    /// first decoded entry).
    pub fn response(&self) -> Option<FieldValue> {
        let mut first = None;
        for item in self.reply() {
            if let FieldItem::Field { descriptor, data } = item {
                if let Ok(v) = decode_field(self.facts.set, descriptor, data, self.device) {
                    if self.expect.as_slice().contains(&descriptor) {
                        return Some(v);
                    }
                    first = first.or(Some(v));
                }
            }
        }
        first
    }

    /// `Ok(self)` for ack and sent; else the error for the result.
    pub fn into_result(self) -> Result<Self, SessionError> {
        let name = self.facts.name;
        match self.status {
            Status::Ack | Status::Sent => Ok(self),
            Status::Nack => Err(SessionError::Nack {
                name,
                code: self.code.unwrap_or(0),
            }),
            Status::Timeout => Err(SessionError::Timeout { name }),
            Status::Invalid => Err(SessionError::Invalid {
                name,
                error: self.error.map(|e| e.to_string()).unwrap_or_default(),
            }),
            Status::Refused => Err(SessionError::Refused {
                name,
                error: self.error.map(|e| e.to_string()).unwrap_or_default(),
            }),
        }
    }
}

/// What the blocking API reports for anything but success.
#[derive(Debug)]
pub enum SessionError {
    /// The selected device does not support the command (or its function); nothing was sent.
    Refused {
        /// Command name.
        name: &'static str,
        /// Why.
        error: String,
    },
    /// The device answered with a NACK.
    Nack {
        /// Command name.
        name: &'static str,
        /// The device's error code.
        code: u32,
    },
    /// No reply before the command's deadline.
    Timeout {
        /// Command name.
        name: &'static str,
    },
    /// Acknowledged, but the reply does not decode (or the expected field is missing).
    Invalid {
        /// Command name.
        name: &'static str,
        /// Why.
        error: String,
    },
    /// The command could not be built.
    Start(StartError),
    /// A bad address.
    Address(String),
    /// The connection could not be opened.
    Connect(String),
    /// Reading or writing the connection failed.
    Io(io::Error),
}

impl fmt::Display for SessionError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SessionError::Refused { name, error } | SessionError::Invalid { name, error } => {
                if error.starts_with(name) || error.starts_with("function ") {
                    f.write_str(error)
                } else {
                    write!(f, "{name}: {error}")
                }
            }
            SessionError::Nack { name, code } => write!(f, "{name}: NACK, code {code}"),
            SessionError::Timeout { name } => write!(f, "{name}: no reply before the timeout"),
            SessionError::Start(e) => write!(f, "cannot start the command: {e}"),
            SessionError::Address(m) | SessionError::Connect(m) => f.write_str(m),
            SessionError::Io(e) => write!(f, "connection: {}", io_message(e)),
        }
    }
}

impl std::error::Error for SessionError {}

impl From<io::Error> for SessionError {
    fn from(e: io::Error) -> Self {
        SessionError::Io(e)
    }
}

type PacketHandler = Box<dyn FnMut(u64, &Packet<'_>)>;
type FieldHandler = Box<dyn FnMut(&FieldValue, &Packet<'_>)>;
type EventHandler = Box<dyn FnMut(&SessionEvent<'_>)>;

/// A session over a transport, blocking: [`Device::run`] sends a command and waits for its
/// result, feeding every received byte to the session, so data packets reach the handlers
/// meanwhile.
pub struct Device<T: Transport = Box<dyn Transport>> {
    transport: T,
    session: Session<1>,
    t0: Instant,
    buf: Vec<u8>,
    on_packet: Vec<PacketHandler>,
    on_field: Vec<(u8, u8, FieldHandler)>,
    on_event: Option<EventHandler>,
}

/// Connects to `address` (`tcp:HOST:PORT` or a serial port path at `baud`) for `model` (its
/// layouts decode, and commands it does not support are refused before sending).
pub fn connect(
    address: &str,
    model: Option<Model>,
    baud: u32,
) -> Result<Device<Box<dyn Transport>>, SessionError> {
    Ok(Device::new(open_transport(address, baud)?, model))
}

impl<T: Transport> Device<T> {
    /// A device on `transport`, for `model`.
    pub fn new(transport: T, model: Option<Model>) -> Self {
        Self {
            transport,
            session: Session::new(model),
            t0: Instant::now(),
            buf: vec![0; 4096],
            on_packet: Vec::new(),
            on_field: Vec::new(),
            on_event: None,
        }
    }

    /// Sets the reply timeout of every command (default 1000 ms, plus the spec's allowance).
    pub fn with_timeout_ms(mut self, ms: u64) -> Self {
        self.session = core::mem::take(&mut self.session).with_timeout_ms(ms);
        self
    }

    /// Turns the device support check off (or on) for every command.
    pub fn with_check_device(mut self, check: bool) -> Self {
        self.session = core::mem::take(&mut self.session).with_check_device(check);
        self
    }

    /// The selected device model.
    pub fn model(&self) -> Option<Model> {
        self.session.device()
    }

    /// Milliseconds since the device was opened (the session's clock).
    pub fn now_ms(&self) -> u64 {
        u64::try_from(self.t0.elapsed().as_millis()).unwrap_or(u64::MAX)
    }

    /// Calls `handler(offset, packet)` for every packet that is not a reply.
    pub fn on_packet(&mut self, handler: impl FnMut(u64, &Packet<'_>) + 'static) {
        self.on_packet.push(Box::new(handler));
    }

    /// Calls `handler(value, packet)` for every decoded field (set, descriptor) of a packet that
    /// is not a reply.
    pub fn on_field(
        &mut self,
        set: u8,
        descriptor: u8,
        handler: impl FnMut(&FieldValue, &Packet<'_>) + 'static,
    ) {
        self.on_field.push((set, descriptor, Box::new(handler)));
    }

    /// Calls `handler` for every event (results, packets, skip runs), before the other handlers.
    pub fn on_event(&mut self, handler: impl FnMut(&SessionEvent<'_>) + 'static) {
        self.on_event = Some(Box::new(handler));
    }

    /// Sends the command and waits for its result (never an error for nack, timeout or
    /// refusal: see [`Completed::status`]; errors are I/O and commands that do not encode).
    pub fn run(
        &mut self,
        command: &FieldValue,
        options: StartOptions,
    ) -> Result<Completed, SessionError> {
        let now = self.now_ms();
        let model = self.session.device();
        let started = self
            .session
            .start(command, now, options)
            .map_err(SessionError::Start)?;
        if let Some(r) = &started.result {
            let done = Completed::from_result(r, model);
            if !started.packet.is_empty() {
                let packet = started.packet.to_vec();
                self.transport.send(&packet)?;
            }
            return Ok(done);
        }
        let (id, deadline) = (started.id, started.deadline);
        let packet = started.packet.to_vec();
        self.transport.send(&packet)?;
        loop {
            let mut done = None;
            let wake = self.session.next_deadline().unwrap_or(deadline);
            let wait = wake.saturating_sub(self.now_ms());
            self.pump(wait, &mut |r| {
                if r.id == id {
                    done = Some(Completed::from_result(r, model));
                }
            })?;
            if let Some(done) = done {
                return Ok(done);
            }
        }
    }

    /// As [`Device::run`], but anything but ack or sent is an error.
    pub fn call(&mut self, command: &FieldValue) -> Result<Completed, SessionError> {
        self.run(command, StartOptions::default())?.into_result()
    }

    /// Receives for `duration_ms`, routing every packet to the handlers.
    pub fn listen(&mut self, duration_ms: u64) -> Result<(), SessionError> {
        let end = self.now_ms().saturating_add(duration_ms);
        loop {
            let now = self.now_ms();
            if now >= end {
                return Ok(());
            }
            self.pump(end - now, &mut |_| {})?;
        }
    }

    /// Waits up to `wait_ms` for bytes and feeds them (or runs the timeouts).
    fn pump(
        &mut self,
        wait_ms: u64,
        on_result: &mut dyn FnMut(&CommandResult<'_>),
    ) -> Result<(), SessionError> {
        let n = self
            .transport
            .receive(&mut self.buf, Duration::from_millis(wait_ms))?;
        let now = self.now_ms();
        let Self {
            session,
            buf,
            on_packet,
            on_field,
            on_event,
            ..
        } = self;
        let model = session.device();
        session.feed(&buf[..n], now, |e| {
            if let Some(h) = on_event.as_mut() {
                h(&e);
            }
            match e {
                SessionEvent::Result(r) => on_result(&r),
                SessionEvent::Packet { offset, packet } => {
                    for h in on_packet.iter_mut() {
                        h(offset, &packet);
                    }
                    if !on_field.is_empty() {
                        crate::session::for_each_field(&packet, model, |d, v| {
                            for (s, fd, h) in on_field.iter_mut() {
                                if *s == packet.set() && *fd == d {
                                    h(v, &packet);
                                }
                            }
                        });
                    }
                }
                SessionEvent::Skip { .. } => {}
            }
        });
        Ok(())
    }

    /// Ends the session: the bytes buffered are reported as skipped; returns the transport.
    pub fn close(mut self) -> T {
        let now = self.now_ms();
        let on_event = &mut self.on_event;
        self.session.close(now, |e| {
            if let Some(h) = on_event.as_mut() {
                h(&e);
            }
        });
        self.transport
    }
}

impl<T: Transport> fmt::Debug for Device<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Device")
            .field("model", &self.session.device())
            .finish()
    }
}

/// The command of one input line of the session tool: a canonical packet line (what `encode`
/// accepts, `docs/conformance.md` §5) with exactly one decoded command field; the error text
/// names the problem.
pub fn command_from_line(text: &str) -> Result<FieldValue, String> {
    use crate::json_read::{parse, FromJson, Json};
    crate::text::encode_line(text).map_err(|e| e.to_string())?;
    let v = parse(text).map_err(|e| e.to_string())?;
    let Some(Json::Array(fields)) = v.get("fields") else {
        return Err("expected a packet line with one command field, not a skip run".to_string());
    };
    if fields.len() != 1 {
        return Err(format!(
            "expected exactly one command field, got {}",
            fields.len()
        ));
    }
    let f = &fields[0];
    let Some(values) = f.get("values") else {
        return Err(
            "expected a decoded command field (descriptor, name, values), not a raw field"
                .to_string(),
        );
    };
    let number = |key: &str, j: &Json| j.get(key).and_then(|n| u8::from_json(n).ok());
    let (Some(set), Some(descriptor)) = (number("set", &v), number("descriptor", f)) else {
        return Err("expected a packet line with one command field".to_string());
    };
    let model = match f.get("device") {
        Some(Json::String(id)) => Model::from_id(id),
        _ => None,
    };
    let value = FieldValue::from_json(set, descriptor, model, values).map_err(|e| e.to_string())?;
    if crate::commands::command_facts(&value).is_none() {
        return Err(format!(
            "{} (set {set}, descriptor {descriptor}) is not a command",
            value.name()
        ));
    }
    Ok(value)
}
