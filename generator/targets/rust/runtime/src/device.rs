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

use crate::clock::ClockModel;
use crate::dispatch::{decode_field, Device as Model, FieldValue};
use crate::fields::{FieldItem, Fields, Packet};
use crate::session::{
    CommandFacts, CommandResult, Expect, ResultError, Session, SessionEvent, StartError,
    StartOptions, Status,
};

/// Baud rate of a serial port when none is given.
pub const DEFAULT_BAUD: u32 = 115_200;
/// The most bytes one read from the transport asks for: after each read the bytes are fed to
/// the session with the current time and its events handled before the next read, so a
/// command's deadline is kept whatever arrives (`docs/conformance.md` §8).
pub const READ_MAX: usize = 65_536;

/// The time of a [`Device`]: how long since it was opened, and a wait (between reopens of a
/// lost port). The default is the system's monotonic clock and `std::thread::sleep`; a test can
/// give the device a clock of its own ([`Device::with_clock`]).
pub trait DeviceClock {
    /// The time since a fixed start (the default: the device's creation).
    fn elapsed(&self) -> Duration;
    /// Waits for `duration`.
    fn sleep(&mut self, duration: Duration);
}

/// The default [`DeviceClock`]: the system's monotonic clock.
struct SystemClock(Instant);

impl DeviceClock for SystemClock {
    fn elapsed(&self) -> Duration {
        self.0.elapsed()
    }
    fn sleep(&mut self, duration: Duration) {
        std::thread::sleep(duration);
    }
}

/// A byte connection to a device.
pub trait Transport {
    /// Writes all of `bytes`.
    fn send(&mut self, bytes: &[u8]) -> io::Result<()>;
    /// Waits up to `timeout` for bytes and reads what arrived into `buf`: 0 when nothing came in
    /// time. The end of the connection is an error (`UnexpectedEof`).
    fn receive(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize>;
    /// Discards what was received but not read yet (a serial port's input buffer); nothing
    /// where there is no such buffer.
    fn clear_input(&mut self) -> io::Result<()> {
        Ok(())
    }
    /// The line rate of a serial port; `None` where there is none (TCP).
    fn baud(&self) -> Option<u32> {
        None
    }
    /// Changes the line rate of a serial port (`Unsupported` where there is none).
    fn set_baud(&mut self, baud: u32) -> io::Result<()> {
        let _ = baud;
        Err(io::Error::new(
            io::ErrorKind::Unsupported,
            "this connection has no baud rate",
        ))
    }
}

impl<T: Transport + ?Sized> Transport for Box<T> {
    fn send(&mut self, bytes: &[u8]) -> io::Result<()> {
        (**self).send(bytes)
    }
    fn receive(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
        (**self).receive(buf, timeout)
    }
    fn clear_input(&mut self) -> io::Result<()> {
        (**self).clear_input()
    }
    fn baud(&self) -> Option<u32> {
        (**self).baud()
    }
    fn set_baud(&mut self, baud: u32) -> io::Result<()> {
        (**self).set_baud(baud)
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
    #[cfg(unix)]
    port: serialport::TTYPort,
    #[cfg(not(unix))]
    port: Box<dyn serialport::SerialPort>,
    baud: u32,
}

#[cfg(feature = "serial")]
impl SerialTransport {
    /// Opens the port `path` (`/dev/ttyUSB0`, `COM3`) at `baud`.
    pub fn open(path: &str, baud: u32) -> io::Result<Self> {
        let builder = serialport::new(path, baud).timeout(Duration::from_millis(10));
        #[cfg(unix)]
        let port = builder.open_native().map_err(io::Error::from)?;
        #[cfg(not(unix))]
        let port = builder.open().map_err(io::Error::from)?;
        let mut t = Self { port, baud };
        // A standard rate as its termios speed code (what a device driver, or a simulator
        // reading the line settings, understands).
        t.set_baud(baud)?;
        Ok(t)
    }
}

/// Sets a standard rate with its termios code (`cfsetspeed`, as C programs and pyserial do;
/// `serialport` sets every rate as an arbitrary one, `BOTHER`), another rate through `serialport`.
#[cfg(all(feature = "serial", unix))]
fn set_line_rate(port: &mut serialport::TTYPort, baud: u32) -> io::Result<()> {
    use nix::sys::termios::{cfsetspeed, tcgetattr, tcsetattr, BaudRate, SetArg};
    use std::os::unix::io::AsRawFd;
    let code = match baud {
        9600 => BaudRate::B9600,
        19200 => BaudRate::B19200,
        38400 => BaudRate::B38400,
        57600 => BaudRate::B57600,
        115_200 => BaudRate::B115200,
        230_400 => BaudRate::B230400,
        #[cfg(any(target_os = "linux", target_os = "android", target_os = "freebsd"))]
        460_800 => BaudRate::B460800,
        #[cfg(any(target_os = "linux", target_os = "android"))]
        921_600 => BaudRate::B921600,
        #[cfg(any(target_os = "linux", target_os = "android"))]
        3_000_000 => BaudRate::B3000000,
        _ => {
            use serialport::SerialPort;
            return port.set_baud_rate(baud).map_err(io::Error::from);
        }
    };
    let fd = port.as_raw_fd();
    let mut t = tcgetattr(fd).map_err(io::Error::from)?;
    cfsetspeed(&mut t, code).map_err(io::Error::from)?;
    tcsetattr(fd, SetArg::TCSANOW, &t).map_err(io::Error::from)
}

#[cfg(all(feature = "serial", not(unix)))]
fn set_line_rate(port: &mut Box<dyn serialport::SerialPort>, baud: u32) -> io::Result<()> {
    port.set_baud_rate(baud).map_err(io::Error::from)
}

#[cfg(feature = "serial")]
impl Transport for SerialTransport {
    fn send(&mut self, bytes: &[u8]) -> io::Result<()> {
        match self.port.write_all(bytes) {
            // A hang-up (see receive): writing tells the OS's error.
            #[cfg(unix)]
            Err(e) if e.kind() == io::ErrorKind::BrokenPipe => {
                use std::os::unix::io::AsRawFd;
                nix::unistd::write(self.port.as_raw_fd(), bytes).map_err(io::Error::from)?;
                Err(e)
            }
            r => r,
        }?;
        self.port.flush()
    }

    fn clear_input(&mut self) -> io::Result<()> {
        use serialport::SerialPort;
        self.port
            .clear(serialport::ClearBuffer::Input)
            .map_err(io::Error::from)
    }

    fn baud(&self) -> Option<u32> {
        Some(self.baud)
    }

    fn set_baud(&mut self, baud: u32) -> io::Result<()> {
        set_line_rate(&mut self.port, baud)?;
        self.baud = baud;
        Ok(())
    }

    fn receive(&mut self, buf: &mut [u8], timeout: Duration) -> io::Result<usize> {
        use serialport::SerialPort;
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
            // serialport reports a hang-up (the poll's POLLHUP) as a broken pipe of its own:
            // reading tells the OS's error (a pty whose other side closed: EIO).
            #[cfg(unix)]
            Err(e) if e.kind() == io::ErrorKind::BrokenPipe => {
                use std::os::unix::io::AsRawFd;
                match nix::unistd::read(self.port.as_raw_fd(), buf) {
                    Ok(0) => Err(io::Error::new(
                        io::ErrorKind::UnexpectedEof,
                        "the port was closed",
                    )),
                    Ok(n) => Ok(n),
                    Err(errno) => Err(io::Error::from(errno)),
                }
            }
            Err(e) => Err(e),
        }
    }
}

/// What an address names: a TCP endpoint or a serial port path ([`parse_address`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Address {
    /// `tcp:HOST:PORT`: the host (an IPv6 address without its brackets) and the port.
    Tcp {
        /// Host name or address.
        host: String,
        /// Port number.
        port: u16,
    },
    /// A serial port path (`/dev/ttyUSB0`, `COM3`, `\\.\COM10`).
    Serial(String),
}

/// What `address` names, without opening it: `tcp:HOST:PORT` (an IPv6 host in brackets) or a
/// serial port path. HOST:PORT without `tcp:` (`127.0.0.1:5000`, `[::1]:5000`) that is not an
/// existing path is refused with "did you mean tcp:HOST:PORT?" ([`looks_like_tcp`]).
pub fn parse_address(address: &str) -> Result<Address, SessionError> {
    if let Some(rest) = address.strip_prefix("tcp:") {
        let bad = || {
            SessionError::Address(format!(
                "bad TCP address '{address}' (expected tcp:HOST:PORT)"
            ))
        };
        let (host, port) = rest.rsplit_once(':').ok_or_else(bad)?;
        // Port 1..65535, ASCII digits only.
        let port: u16 = port
            .parse()
            .ok()
            .filter(|p| *p > 0 && port.bytes().all(|b| b.is_ascii_digit()))
            .ok_or_else(bad)?;
        let host = host
            .strip_prefix('[')
            .and_then(|h| h.strip_suffix(']'))
            .unwrap_or(host);
        if host.is_empty() || port == 0 {
            return Err(bad());
        }
        return Ok(Address::Tcp {
            host: host.to_string(),
            port,
        });
    }
    if address.is_empty() {
        return Err(SessionError::Address(
            "empty address (expected tcp:HOST:PORT or a serial port path)".to_string(),
        ));
    }
    if looks_like_tcp(address) && !std::path::Path::new(address).exists() {
        return Err(SessionError::Address(format!(
            "'{address}' is not a serial port: did you mean tcp:{address}?"
        )));
    }
    Ok(Address::Serial(address.to_string()))
}

/// True for HOST:PORT without `tcp:` (`127.0.0.1:5000`, `localhost:5000`, `[::1]:5000`): a
/// numeric port, no `/` or `\` (a path), an IPv6 host in brackets. The four languages share
/// the rule.
pub fn looks_like_tcp(address: &str) -> bool {
    let Some((host, port)) = address.rsplit_once(':') else {
        return false;
    };
    if host.is_empty()
        || port.is_empty()
        || !port.bytes().all(|b| b.is_ascii_digit())
        || address.contains('/')
        || address.contains('\\')
    {
        return false;
    }
    !host.contains(':') || (host.starts_with('[') && host.ends_with(']'))
}

/// Opens `address`: `tcp:HOST:PORT` (an IPv6 host in brackets) or a serial port path, opened
/// at `baud` (needs the `serial` feature).
pub fn open_transport(address: &str, baud: u32) -> Result<Box<dyn Transport>, SessionError> {
    match parse_address(address)? {
        Address::Tcp { host, port } => {
            let text = if host.contains(':') {
                format!("[{host}]:{port}")
            } else {
                format!("{host}:{port}")
            };
            TcpTransport::connect(&text)
                .map(|t| Box::new(t) as Box<dyn Transport>)
                .map_err(|e| {
                    SessionError::Connect(format!(
                        "cannot connect to {address}: {}",
                        io_message(&e)
                    ))
                })
        }
        Address::Serial(path) => open_serial(&path, baud),
    }
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
    /// What the result alone does not tell: after the first NACK for a command the device does
    /// not know, a device told a model asks the device what it is (the spec's identity command,
    /// once) and, when it is another model ([`model_note`]), says so here: "connected device is
    /// 3DM-GX5-45, this session was told cv7_ins".
    pub note: Option<String>,
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
            note: None,
            device,
            reply: r.reply_bytes().to_vec(),
            start: r.reply_offset(),
        }
    }

    /// True for ack and sent.
    pub fn is_ok(&self) -> bool {
        matches!(self.status, Status::Ack | Status::Sent)
    }

    /// Writes the session tool's line for input line `line` (as [`CommandResult::write_line`]).
    pub fn write_line(&self, w: &mut dyn fmt::Write, line: u64) -> fmt::Result {
        CommandResult {
            id: 0,
            facts: self.facts,
            status: self.status,
            code: self.code,
            error: self.error,
            expect: self.expect,
            device: self.device,
            reply: &self.reply,
            start: self.start,
        }
        .write_line(w, line)
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
    /// The port went away while the command waited for its reply: the command's result is
    /// **lost**, it is not retried. With reconnection on, the link was recovered before this was
    /// returned, unless `gave_up` says why not.
    LinkLost {
        /// Command name.
        name: &'static str,
        /// The system's error text of the failing call, or `end of file`.
        reason: String,
        /// `gave up reopening ADDRESS after D ms` when the port did not come back in time.
        gave_up: Option<String>,
    },
    /// Getting through failed (`idle: the protocol has no idle command`, `baud: no answer at any
    /// rate`, `gave up reopening ADDRESS after D ms`).
    Link(String),
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
            SessionError::LinkLost {
                gave_up: Some(m), ..
            } => write!(f, "link: {m}"),
            SessionError::LinkLost { name, reason, .. } => write!(f, "{name}: link lost: {reason}"),
            SessionError::Link(m) => write!(f, "link: {m}"),
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
type TimedPacketHandler = Box<dyn FnMut(u64, &Packet<'_>, Option<i64>)>;
type FieldHandler = Box<dyn FnMut(&FieldValue, &Packet<'_>)>;
type EventHandler = Box<dyn FnMut(&SessionEvent<'_>)>;
type BytesHandler = Box<dyn FnMut(&[u8])>;
type LinkHandler = Box<dyn FnMut(&str)>;
type Opener<T> = Box<dyn FnMut(u32) -> Result<T, SessionError>>;

/// How often a lost port is reopened, in milliseconds.
pub const RECONNECT_INTERVAL_MS: u64 = 500;
/// How long a lost port is reopened when the application asks for reconnection without a
/// deadline of its own, in milliseconds.
pub const DEFAULT_RECONNECT_MS: u64 = 10_000;
/// How long the input is left to drain after a flush before an idle attempt is repeated.
pub const QUIET_MS: u64 = 50;
/// The most settings a device remembers to re-apply after a reconnection (the latest per
/// command and first parameter wins; beyond this the oldest is forgotten).
pub const MAX_SETTINGS: usize = 64;

/// A session over a transport, blocking: [`Device::run`] sends a command and waits for its
/// result, feeding every received byte to the session, so data packets reach the handlers
/// meanwhile. It gets a streaming device to idle ([`Device::to_idle`]), finds the baud rate of
/// a serial port ([`Device::find_baud`]) and, when asked ([`Device::with_reconnect_ms`]),
/// reopens a lost port and re-applies the settings written since it connected, reporting each
/// step in one line ([`Device::on_link`]; `docs/conformance.md` §8, "Getting through").
pub struct Device<T: Transport = Box<dyn Transport>> {
    transport: T,
    session: Session<1>,
    clock: Box<dyn DeviceClock>,
    // The command that gets the device to idle (the spec's `link.idle`, unless replaced).
    idle_command: Option<(u8, u8)>,
    buf: Vec<u8>,
    on_packet: Vec<PacketHandler>,
    on_packet_at: Vec<TimedPacketHandler>,
    on_field: Vec<(u8, u8, FieldHandler)>,
    on_event: Option<EventHandler>,
    on_bytes: Option<BytesHandler>,
    on_link: Option<LinkHandler>,
    opener: Option<Opener<T>>,
    address: String,
    baud: u32,
    timeout_ms: u64,
    reconnect_ms: Option<u64>,
    recovering: bool,
    // Bytes dropped since `Some(0)`: while getting through, nothing reaches the handlers.
    dropping: Option<u64>,
    settings: Vec<(String, FieldValue)>,
    // The application's last idle or resume command was an idle (no resume after reconnecting).
    idle: bool,
    // The wrong-model check is done (or not to do: no model); inside it (its result is no event).
    identified: bool,
    identifying: bool,
}

/// Connects to `address` (`tcp:HOST:PORT` or a serial port path at `baud`) for `model` (its
/// layouts decode, and commands it does not support are refused before sending). The device
/// can reopen the address ([`Device::with_reconnect_ms`]).
pub fn connect(
    address: &str,
    model: Option<Model>,
    baud: u32,
) -> Result<Device<Box<dyn Transport>>, SessionError> {
    let transport = open_transport(address, baud)?;
    let again = address.to_string();
    let mut device = Device::new(transport, model);
    device.opener = Some(Box::new(move |b| open_transport(&again, b)));
    device.address = address.to_string();
    device.baud = baud;
    Ok(device)
}

impl<T: Transport> Device<T> {
    /// A device on `transport`, for `model`.
    pub fn new(transport: T, model: Option<Model>) -> Self {
        let baud = transport.baud().unwrap_or(DEFAULT_BAUD);
        Self {
            transport,
            session: Session::new(model),
            clock: Box::new(SystemClock(Instant::now())),
            idle_command: crate::framing::LINK_IDLE,
            buf: vec![0; READ_MAX],
            on_packet: Vec::new(),
            on_packet_at: Vec::new(),
            on_field: Vec::new(),
            on_event: None,
            on_bytes: None,
            on_link: None,
            opener: None,
            address: String::new(),
            baud,
            timeout_ms: crate::session::DEFAULT_TIMEOUT_MS,
            reconnect_ms: None,
            recovering: false,
            dropping: None,
            settings: Vec::new(),
            idle: false,
            identified: model.is_none(),
            identifying: false,
        }
    }

    /// Sets the reply timeout of every command (default 1000 ms, plus the spec's allowance).
    pub fn with_timeout_ms(mut self, ms: u64) -> Self {
        self.session = core::mem::take(&mut self.session).with_timeout_ms(ms);
        self.timeout_ms = ms;
        self
    }

    /// Turns the device support check off (or on) for every command.
    pub fn with_check_device(mut self, check: bool) -> Self {
        self.session = core::mem::take(&mut self.session).with_check_device(check);
        self
    }

    /// When the port goes away, reopens it at once, then every [`RECONNECT_INTERVAL_MS`] while
    /// the next try is within `ms` milliseconds of the loss ([`DEFAULT_RECONNECT_MS`] is the
    /// usual choice), then gets to idle, re-sends the settings written since connecting, in
    /// order, and resumes (unless the application's last idle or resume command was an idle).
    /// Needs a device made by [`connect`] or given a way to reopen ([`Device::with_opener`]).
    pub fn with_reconnect_ms(mut self, ms: u64) -> Self {
        self.reconnect_ms = Some(ms);
        self
    }

    /// How to reopen the connection (`open(baud)`), named `address` in the link's reports.
    pub fn with_opener(
        mut self,
        address: &str,
        open: impl FnMut(u32) -> Result<T, SessionError> + 'static,
    ) -> Self {
        self.opener = Some(Box::new(open));
        self.address = address.to_string();
        self
    }

    /// Reads the time from `clock` instead of the system's monotonic clock (the session's
    /// deadlines, [`Device::now_ms`], the waits between reopens): a test's fake clock.
    pub fn with_clock(mut self, clock: impl DeviceClock + 'static) -> Self {
        self.clock = Box::new(clock);
        self
    }

    /// The command (set, descriptor; it takes no parameters) that gets the device to idle
    /// ([`Device::to_idle`], and after a reconnection) instead of the spec's `link.idle`;
    /// `None`: no idle command.
    pub fn with_idle_command(mut self, idle: Option<(u8, u8)>) -> Self {
        self.idle_command = idle;
        self
    }

    /// The selected device model.
    pub fn model(&self) -> Option<Model> {
        self.session.device()
    }

    /// The baud rate the device is used at (the configured one, or the one found).
    pub fn baud(&self) -> u32 {
        self.baud
    }

    /// The earliest stream offset whose byte may still be reported to the handlers: a caller
    /// that keeps the input ([`Device::on_bytes`]) can drop everything before it.
    pub fn retain_from(&self) -> u64 {
        self.session.retain_from()
    }

    /// The settings that a reconnection re-applies, in the order they are sent: every command
    /// written (function `write` or `write_no_ack`) and acknowledged (or sent), the latest per
    /// key winning and moving to the end; the key is the command and the values of the
    /// parameters its `read` sends (`desc_set` of a message format, `port` of a port's rate).
    pub fn settings(&self) -> impl Iterator<Item = &FieldValue> {
        self.settings.iter().map(|(_, v)| v)
    }

    /// Milliseconds since the device was opened (the session's clock).
    pub fn now_ms(&self) -> u64 {
        u64::try_from(self.clock.elapsed().as_millis()).unwrap_or(u64::MAX)
    }

    /// Nanoseconds since the device was opened (the clock model's arrival times: the time the
    /// transport's read returned).
    pub fn now_ns(&self) -> i64 {
        i64::try_from(self.clock.elapsed().as_nanos()).unwrap_or(i64::MAX)
    }

    /// Starts (true: a new model) or stops the host clock model (`docs/time.md`): every data
    /// packet that carries the device's reference time feeds it at the time its bytes were read.
    pub fn use_clock(&mut self, on: bool) {
        self.session
            .use_clock(if on { Some(ClockModel::new()) } else { None });
    }

    /// The host clock model, when started ([`Device::use_clock`]).
    pub fn clock(&self) -> Option<&ClockModel> {
        self.session.clock()
    }

    /// Calls `handler(offset, packet, host_ns)` for every packet that is not a reply, `host_ns`
    /// its host time by the clock model ([`Device::use_clock`]; `None` without a model, an
    /// estimate or the reference time), in ns of [`Device::now_ns`]'s clock.
    pub fn on_packet_at(&mut self, handler: impl FnMut(u64, &Packet<'_>, Option<i64>) + 'static) {
        self.on_packet_at.push(Box::new(handler));
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

    /// Calls `handler` with every byte received, before it is parsed (those dropped while
    /// getting through too: see [`Device::retain_from`]).
    pub fn on_bytes(&mut self, handler: impl FnMut(&[u8]) + 'static) {
        self.on_bytes = Some(Box::new(handler));
    }

    /// Calls `handler` with one line for each step of getting through (`link: idle: no ACK in
    /// 300 ms while streaming (4212 bytes dropped), flushing, attempt 2 of 3`, `link: baud: ...`,
    /// `link: port lost ...`, `link: reconnected ...`).
    pub fn on_link(&mut self, handler: impl FnMut(&str) + 'static) {
        self.on_link = Some(Box::new(handler));
    }

    fn log(&mut self, text: &str) {
        if let Some(h) = self.on_link.as_mut() {
            h(&format!("link: {text}"));
        }
    }

    /// Sends the command and waits for its result (never an error for nack, timeout or
    /// refusal: see [`Completed::status`]; errors are I/O, commands that do not encode and a
    /// lost link: [`SessionError::LinkLost`]). An acknowledged write is remembered for
    /// reconnections ([`Device::settings`]).
    pub fn run(
        &mut self,
        command: &FieldValue,
        options: StartOptions,
    ) -> Result<Completed, SessionError> {
        let mut done = self.exchange(command, options)?;
        if !self.identified
            && !self.recovering
            && done.status == Status::Nack
            && matches!(done.code, Some(c) if crate::framing::IDENTITY_UNKNOWN_CODES.contains(&c))
        {
            self.identified = true;
            done.note = self.model_mismatch();
        }
        if done.is_ok() {
            self.remember(command);
        }
        Ok(done)
    }

    /// Asks the device for its identity (the spec's identity command, sent whatever the model):
    /// the note of [`model_note`] when the model name it reports is not the device's.
    fn model_mismatch(&mut self) -> Option<String> {
        let told = self.session.device()?;
        let (set, command, reply, offset, length) = crate::framing::IDENTITY?;
        let identity = link_command(Some((set, command)), Some(told))?;
        let options = StartOptions {
            check_device: Some(false),
            ..StartOptions::default()
        };
        self.identifying = true;
        let done = self.exchange(&identity, options);
        self.identifying = false;
        let done = done.ok().filter(|d| d.status == Status::Ack)?;
        let name = done.reply().find_map(|item| match item {
            FieldItem::Field { descriptor, data }
                if descriptor == reply && data.len() >= offset + length =>
            {
                Some(data[offset..offset + length].to_vec())
            }
            _ => None,
        })?;
        model_note(told, &name)
    }

    fn exchange(
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
        let (id, deadline, result) = (started.id, started.deadline, started.result);
        let packet = started.packet.to_vec();
        let name = crate::commands::command_facts(command).map_or("", |f| f.name);
        if let Some(r) = &result {
            let done = Completed::from_result(r, model);
            if self.dropping.is_none() && !self.identifying {
                if let Some(h) = self.on_event.as_mut() {
                    h(&SessionEvent::Result(*r));
                }
            }
            if !packet.is_empty() {
                if let Err(e) = self.transport.send(&packet) {
                    return Err(self.lost(e, name));
                }
            }
            return Ok(done);
        }
        if let Err(e) = self.transport.send(&packet) {
            return Err(self.lost(e, name));
        }
        loop {
            let mut done = None;
            let wake = self.session.next_deadline().unwrap_or(deadline);
            let wait = wake.saturating_sub(self.now_ms());
            let pumped = self.pump(wait, &mut |r| {
                if r.id == id {
                    done = Some(Completed::from_result(r, model));
                }
            });
            if let Err(e) = pumped {
                return Err(self.lost(e, name));
            }
            if let Some(done) = done {
                return Ok(done);
            }
        }
    }

    /// As [`Device::run`], but anything but ack or sent is an error.
    pub fn call(&mut self, command: &FieldValue) -> Result<Completed, SessionError> {
        self.run(command, StartOptions::default())?.into_result()
    }

    /// Receives for `duration_ms`, routing every packet to the handlers (with reconnection on,
    /// a lost port is reopened meanwhile).
    pub fn listen(&mut self, duration_ms: u64) -> Result<(), SessionError> {
        let end = self.now_ms().saturating_add(duration_ms);
        loop {
            let now = self.now_ms();
            if now >= end {
                return Ok(());
            }
            // Until the end, or the session's next wake-up (the look-ahead rule) if sooner.
            let wake = self.session.next_deadline().map_or(end, |d| d.min(end));
            if let Err(e) = self.pump(wake.saturating_sub(now), &mut |_| {}) {
                self.session.abandon();
                self.recover(e)?;
            }
        }
    }

    /// The port failed under a command: it is forgotten (not retried), the link recovered when
    /// reconnection is on; the error to return for the command.
    fn lost(&mut self, e: io::Error, name: &'static str) -> SessionError {
        self.session.abandon();
        if self.reconnect_ms.is_none() || self.opener.is_none() || self.recovering {
            return SessionError::Io(e);
        }
        let reason = lost_reason(&e);
        match self.recover(e) {
            Ok(()) => SessionError::LinkLost {
                name,
                reason,
                gave_up: None,
            },
            Err(SessionError::Link(m)) => SessionError::LinkLost {
                name,
                reason,
                gave_up: Some(m),
            },
            Err(err) => err,
        }
    }

    /// Reopens the lost port at once, then every [`RECONNECT_INTERVAL_MS`] while the next try is
    /// within the deadline, then gets to idle, re-applies the settings and resumes.
    fn recover(&mut self, e: io::Error) -> Result<(), SessionError> {
        let (Some(limit), false, true) =
            (self.reconnect_ms, self.recovering, self.opener.is_some())
        else {
            return Err(SessionError::Io(e));
        };
        let address = self.address.clone();
        self.log(&format!(
            "port lost ({}), reopening {address} every {RECONNECT_INTERVAL_MS} ms",
            lost_reason(&e)
        ));
        // Reopened at once, then every interval while the next try is within the deadline.
        let began = self.clock.elapsed();
        let interval = Duration::from_millis(RECONNECT_INTERVAL_MS);
        loop {
            let opened = match self.opener.as_mut() {
                Some(open) => open(self.baud),
                None => return Err(SessionError::Io(e)),
            };
            match opened {
                Ok(t) => {
                    self.transport = t;
                    break;
                }
                Err(_)
                    if self.clock.elapsed().saturating_sub(began) + interval
                        <= Duration::from_millis(limit) =>
                {
                    self.clock.sleep(interval);
                }
                Err(_) => {
                    let m = format!("gave up reopening {address} after {limit} ms");
                    self.log(&m);
                    return Err(SessionError::Link(m));
                }
            }
        }
        // What the old port left half-parsed is dropped.
        let now = self.now_ms();
        self.session.close(now, |_| {});
        self.recovering = true;
        let outer = self.dropping.replace(0);
        let applied = self.reapply();
        self.dropping = outer;
        self.recovering = false;
        let applied = applied?;
        self.log(&format!(
            "reconnected after {:.1} s, re-applied {applied} settings",
            self.clock.elapsed().saturating_sub(began).as_secs_f64()
        ));
        Ok(())
    }

    /// After a reconnection: to idle, the remembered settings in order, then resume unless the
    /// application had the device idle.
    fn reapply(&mut self) -> Result<usize, SessionError> {
        let model = self.session.device();
        if link_command(self.idle_command, model).is_some() {
            // The session's own idle: what the application left stays (resumed or idle).
            let idle = self.idle;
            let done = self.to_idle();
            self.idle = idle;
            done?;
        }
        let settings: Vec<FieldValue> = self.settings().copied().collect();
        let mut applied = 0;
        for command in &settings {
            if self.exchange(command, StartOptions::default())?.is_ok() {
                applied += 1;
            }
        }
        if !self.idle {
            if let Some(resume) = link_command(crate::framing::LINK_RESUME, model) {
                self.exchange(&resume, StartOptions::default())?;
            }
        }
        Ok(applied)
    }

    /// Remembers an acknowledged (or sent) write, and whether the device was last sent to idle
    /// or resumed.
    fn remember(&mut self, command: &FieldValue) {
        let Some(facts) = crate::commands::command_facts(command) else {
            return;
        };
        let key = Some((facts.set, facts.descriptor));
        if key == self.idle_command {
            self.idle = true;
            return;
        }
        if key == crate::framing::LINK_RESUME {
            self.idle = false;
            return;
        }
        let function =
            crate::commands::command_function(command).and_then(crate::commands::function_name);
        if !matches!(function, Some("write" | "write_no_ack")) {
            return;
        }
        let key = setting_key(command, facts);
        self.settings.retain(|(k, _)| *k != key);
        if self.settings.len() >= MAX_SETTINGS {
            self.settings.remove(0);
        }
        self.settings.push((key, *command));
    }

    /// Gets the device to idle while it may be streaming at full rate: sends the idle command
    /// and waits for its result with the reply timeout, dropping (and counting) the data and
    /// skipped bytes that arrive meanwhile; after a timeout, flushes the input, reads and
    /// discards for [`QUIET_MS`], flushes again and sends it again, up to the spec's attempts.
    /// Returns the last attempt's result (ack, nack, or timeout after the last attempt).
    pub fn to_idle(&mut self) -> Result<Completed, SessionError> {
        let model = self.session.device();
        let Some(idle) = link_command(self.idle_command, model) else {
            let m = "idle: the protocol has no idle command";
            self.log(m);
            return Err(SessionError::Link(m.into()));
        };
        let attempts = crate::framing::LINK_IDLE_ATTEMPTS.max(1);
        let outer = self.dropping;
        let mut attempt = 1;
        let done = loop {
            self.dropping = Some(0);
            let done = self.exchange(&idle, StartOptions::default());
            let dropped = self.dropping.unwrap_or(0);
            self.dropping = outer;
            let done = done?;
            if done.status != Status::Timeout {
                if done.is_ok() {
                    self.idle = true;
                    self.log(&format!(
                        "idle: ACK on attempt {attempt} of {attempts} ({dropped} bytes dropped)"
                    ));
                }
                break done;
            }
            if attempt == attempts {
                self.log(&format!(
                    "idle: no ACK after {attempts} attempts, giving up"
                ));
                break done;
            }
            let streaming = if dropped > 0 {
                format!(" while streaming ({dropped} bytes dropped)")
            } else {
                String::new()
            };
            attempt += 1;
            self.log(&format!(
                "idle: no ACK in {} ms{streaming}, flushing, attempt {attempt} of {attempts}",
                self.timeout_ms
            ));
            self.dropping = Some(0);
            let flushed = self.flush_input();
            self.dropping = outer;
            flushed?;
        };
        Ok(done)
    }

    /// Flushes the input: the transport's buffer, what arrives during a quiet time, and the
    /// parser's partial packet (its bytes were counted as dropped when they were read).
    fn flush_input(&mut self) -> Result<(), SessionError> {
        self.transport.clear_input()?;
        let end = self.now_ms().saturating_add(QUIET_MS);
        loop {
            let now = self.now_ms();
            if now >= end {
                break;
            }
            self.pump(end - now, &mut |_| {})?;
        }
        self.transport.clear_input()?;
        let now = self.now_ms();
        self.session.close(now, |_| {});
        Ok(())
    }

    /// Finds the baud rate of a serial port: a ping at the current rate; without an answer,
    /// the model's default rate, then its other rates from the highest down (without a model:
    /// every model's defaults, then all their rates), each after switching the port and
    /// flushing, with one ping each; stays at the first that answers and returns it. Over TCP
    /// there is no rate: `Ok(None)`. No answer at any rate is an error (the port is left at the
    /// rate it had).
    pub fn find_baud(&mut self) -> Result<Option<u32>, SessionError> {
        let Some(current) = self.transport.baud() else {
            return Ok(None);
        };
        let model = self.session.device();
        let ping = link_command(crate::framing::LINK_PING, model)
            .ok_or_else(|| SessionError::Link("baud: the protocol has no ping command".into()))?;
        let mut rates = vec![current];
        let models: Vec<Model> = match model {
            Some(m) => vec![m],
            None => Model::ALL.to_vec(),
        };
        rates.extend(models.iter().filter_map(|m| m.default_baud()));
        let mut others: Vec<u32> = models
            .iter()
            .flat_map(|m| m.baud_rates().iter().copied())
            .collect();
        others.sort_unstable_by(|a, b| b.cmp(a));
        rates.extend(others);
        let mut seen = Vec::new();
        rates.retain(|r| {
            let fresh = !seen.contains(r);
            seen.push(*r);
            fresh
        });
        let outer = self.dropping;
        self.dropping = Some(0);
        let found = self.try_rates(&ping, &rates);
        self.dropping = outer;
        match found {
            Ok(Some(rate)) => {
                self.baud = rate;
                if rate != current {
                    self.log(&format!("baud: device answers at {rate}"));
                }
                Ok(Some(rate))
            }
            Ok(None) => {
                self.log("baud: no answer at any rate");
                self.transport.set_baud(current)?;
                Err(SessionError::Link("baud: no answer at any rate".into()))
            }
            Err(e) => Err(e),
        }
    }

    /// One ping at each rate in turn (the first is the current one): the first that answers.
    fn try_rates(&mut self, ping: &FieldValue, rates: &[u32]) -> Result<Option<u32>, SessionError> {
        for (i, &rate) in rates.iter().enumerate() {
            if i > 0 {
                self.log(&format!(
                    "baud: no answer at {}, trying {rate}",
                    rates[i - 1]
                ));
                self.transport.set_baud(rate)?;
                self.flush_input()?;
            }
            let done = self.exchange(ping, StartOptions::default())?;
            if matches!(done.status, Status::Ack | Status::Nack | Status::Invalid) {
                return Ok(Some(rate));
            }
        }
        Ok(None)
    }

    /// Waits up to `wait_ms` for bytes and feeds them (or runs the timeouts).
    fn pump(
        &mut self,
        wait_ms: u64,
        on_result: &mut dyn FnMut(&CommandResult<'_>),
    ) -> io::Result<()> {
        let n = self
            .transport
            .receive(&mut self.buf, Duration::from_millis(wait_ms))?;
        let read_ns = self.now_ns();
        let now = u64::try_from(read_ns / 1_000_000).unwrap_or(0);
        let Self {
            session,
            buf,
            on_packet,
            on_packet_at,
            on_field,
            on_event,
            on_bytes,
            dropping,
            identifying,
            ..
        } = self;
        if let Some(h) = on_bytes.as_mut() {
            h(&buf[..n]);
        }
        if let Some(dropped) = dropping.as_mut() {
            *dropped += n as u64; // data, garbage and the reply alike
            session.feed_at(&buf[..n], now, read_ns, |e, _| {
                if let SessionEvent::Result(r) = e {
                    on_result(&r);
                }
            });
            return Ok(());
        }
        let model = session.device();
        let identifying = *identifying;
        session.feed_at(&buf[..n], now, read_ns, |e, host_ns| {
            if let Some(h) = on_event.as_mut() {
                // the identity query of the wrong-model check is no result of the caller's
                if !(identifying && matches!(e, SessionEvent::Result(_))) {
                    h(&e);
                }
            }
            match e {
                SessionEvent::Result(r) => on_result(&r),
                SessionEvent::Packet { offset, packet } => {
                    for h in on_packet.iter_mut() {
                        h(offset, &packet);
                    }
                    for h in on_packet_at.iter_mut() {
                        h(offset, &packet, host_ns);
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
                SessionEvent::Skip { .. }
                | SessionEvent::Nmea { .. }
                | SessionEvent::Rtcm { .. } => {}
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

/// The key of a remembered setting: the command and the values of the parameters its `read`
/// sends (those a read without them would miss: `desc_set` of a message format, `port` of a
/// port's rate).
fn setting_key(command: &FieldValue, facts: &CommandFacts) -> String {
    use crate::json_read::{parse, Json};
    let mut key = format!("{}/{}", facts.set, facts.descriptor);
    let mut text = String::new();
    let _ = command.write_values_json(&mut text);
    let (Ok(Json::Object(members)), Some(read)) = (
        parse(&text),
        (1..=u8::MAX).find(|&f| crate::commands::function_name(f) == Some("read")),
    ) else {
        return key;
    };
    let params: Vec<&(String, Json)> = members.iter().filter(|(k, _)| k != "function").collect();
    let function = ("function".to_string(), Json::Number(read.to_string()));
    for (name, value) in &params {
        let without = Json::Object(
            core::iter::once(function.clone())
                .chain(
                    params
                        .iter()
                        .filter(|(k, _)| k != name)
                        .map(|p| (*p).clone()),
                )
                .collect(),
        );
        let missed =
            FieldValue::from_json(facts.set, facts.descriptor, command.device(), &without).is_err();
        if missed {
            key.push_str(&format!("/{name}={value:?}"));
        }
    }
    key
}

/// The reason a port is lost: the system's error text, `end of file` for a read at the end.
fn lost_reason(e: &io::Error) -> String {
    if e.kind() == io::ErrorKind::UnexpectedEof {
        "end of file".to_string()
    } else {
        io_message(e)
    }
}

/// The command (set, descriptor) as a value, when it takes no parameters.
/// The wrong-model rule (the same in every language): `name` (as the device reported it) with
/// spaces and NULs at either end removed, is not empty and, upper case without spaces and
/// punctuation (a byte outside ASCII kept), is none of `told`'s [`Model::model_names`]: then
/// "connected device is NAME, this session was told ID", NAME with every byte outside printable
/// ASCII written `\xNN`. `None` when the name is the model's, or the device does not say.
pub fn model_note(told: Model, name: &[u8]) -> Option<String> {
    let pad = |b: &u8| *b == b' ' || *b == 0;
    let start = name.iter().position(|b| !pad(b))?;
    let end = name.iter().rposition(|b| !pad(b))? + 1;
    let name = &name[start..end];
    let plain: Vec<u8> = name
        .iter()
        .filter(|b| b.is_ascii_alphanumeric() || !b.is_ascii())
        .map(u8::to_ascii_uppercase)
        .collect();
    if !plain.is_empty() && told.model_names().iter().any(|n| n.as_bytes() == plain) {
        return None;
    }
    let mut shown = String::with_capacity(name.len());
    for &b in name {
        if (0x20..=0x7e).contains(&b) {
            shown.push(char::from(b));
        } else {
            shown.push_str(&format!("\\x{b:02x}"));
        }
    }
    Some(format!(
        "connected device is {shown}, this session was told {}",
        told.id()
    ))
}

fn link_command(which: Option<(u8, u8)>, model: Option<Model>) -> Option<FieldValue> {
    let (set, descriptor) = which?;
    decode_field(set, descriptor, &[], model).ok()
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
