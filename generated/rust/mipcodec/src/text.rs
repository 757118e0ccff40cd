//! Text helpers (std) used by the command-line tools and the tests: a byte stream to canonical
//! JSON lines, and JSON lines back to bytes (`docs/conformance.md` §4, §5).

use crate::builder::PacketBuilder;
use crate::dispatch::{write_foreign_json, write_packet_json, write_skip_json, Device, FieldValue};
use crate::fields::Packet;
use crate::json_read::{hex_bytes, parse, FromJson, Json, JsonError, Obj};
use crate::parser::{Event, Parser};
use crate::samples::SampleTracker;

/// Decodes a byte stream fed in chunks into canonical JSON lines.
pub struct StreamDecoder {
    parser: Parser,
    device: Option<Device>,
    samples: Option<SampleTracker>,
    // Input bytes from stream offset `hist_base` on, kept to print skipped bytes.
    hist: Vec<u8>,
    hist_base: u64,
}

fn write_event(
    out: &mut String,
    event: Event<'_>,
    hist: &[u8],
    hist_base: u64,
    device: Option<Device>,
    samples: &mut Option<SampleTracker>,
) {
    let start_of_line = out.len();
    // Writing to a String cannot fail.
    let _ = match event {
        Event::Skip { offset, count } => {
            let start = (offset - hist_base) as usize;
            write_skip_json(out, offset, &hist[start..start + count as usize])
        }
        Event::Nmea { offset, bytes } | Event::Rtcm { offset, bytes } => {
            write_foreign_json(out, offset, bytes)
        }
        Event::Packet { offset, bytes } => match Packet::new(bytes) {
            Some(packet) => {
                let r = write_packet_json(out, offset, &packet, device);
                let place = samples.as_mut().and_then(|t| t.feed(&packet));
                if let (Some(place), Some(at)) = (place, out[start_of_line..].find(",\"fields\":"))
                {
                    out.insert_str(start_of_line + at, &format!(",\"sample\":{}", place.number));
                }
                r
            }
            None => Ok(()),
        },
    };
    out.push('\n');
}

impl StreamDecoder {
    /// A decoder at stream offset 0; `device` selects per-device layouts.
    pub fn new(device: Option<Device>) -> Self {
        Self {
            parser: Parser::new(),
            device,
            samples: None,
            hist: Vec::new(),
            hist_base: 0,
        }
    }

    /// Numbers the samples of data packets (`"sample":N`, `docs/conformance.md` §6).
    pub fn with_samples(mut self) -> Self {
        self.samples = Some(SampleTracker::new());
        self
    }

    /// Feeds `chunk`; appends the lines of completed events to `out`.
    pub fn feed(&mut self, chunk: &[u8], out: &mut String) {
        self.hist.extend_from_slice(chunk);
        let (hist, base, device, samples) =
            (&self.hist, self.hist_base, self.device, &mut self.samples);
        self.parser.feed(chunk, |event| {
            write_event(out, event, hist, base, device, samples)
        });
        self.trim();
    }

    /// End of input: appends the remaining lines to `out`.
    pub fn finish(&mut self, out: &mut String) {
        let (hist, base, device, samples) =
            (&self.hist, self.hist_base, self.device, &mut self.samples);
        self.parser
            .flush(|event| write_event(out, event, hist, base, device, samples));
        self.trim();
    }

    fn trim(&mut self) {
        let keep = self.parser.retain_from();
        let drop = (keep - self.hist_base) as usize;
        if drop > 0 {
            self.hist.drain(..drop);
            self.hist_base = keep;
        }
    }
}

/// The canonical JSON lines of `input`, fed to the parser in chunks of `chunk` bytes.
pub fn decode_bytes(input: &[u8], device: Option<Device>, chunk: usize) -> String {
    let mut out = String::new();
    let mut decoder = StreamDecoder::new(device);
    for piece in input.chunks(chunk.max(1)) {
        decoder.feed(piece, &mut out);
    }
    decoder.finish(&mut out);
    out
}

/// "error" of a raw field or trailing entry: a string, its text not used (docs/conformance.md §5).
fn error_text(v: &Json) -> Result<(), JsonError> {
    match v {
        Json::String(_) => Ok(()),
        other => Err(JsonError::new(format!(
            "expected a string, got {}",
            other.kind()
        ))),
    }
}

fn field_bytes(set: u8, field: &Json, builder: &mut PacketBuilder) -> Result<(), JsonError> {
    if field.get("trailing").is_some() {
        let o = Obj::new(field, &["trailing", "error"])?;
        o.req("error", error_text)?;
        let bytes = o.req("trailing", hex_bytes)?;
        return builder
            .add_bytes(&bytes)
            .map_err(|e| JsonError::new(e.to_string()).at("trailing"));
    }
    if field.get("data").is_some() {
        let o = Obj::new(field, &["descriptor", "data", "error"])?;
        o.req("error", error_text)?;
        let descriptor = o.req("descriptor", u8::from_json)?;
        let data = o.req("data", hex_bytes)?;
        return builder
            .add_raw_field(descriptor, &data)
            .map_err(|e| JsonError::new(e.to_string()).at("data"));
    }
    let o = Obj::new(field, &["descriptor", "name", "device", "values"])?;
    let descriptor = o.req("descriptor", u8::from_json)?;
    let device = o.opt("device", |v| match v {
        Json::String(id) => {
            Device::from_id(id).ok_or_else(|| JsonError::new(format!("unknown device \"{id}\"")))
        }
        other => Err(JsonError::new(format!(
            "expected a device id string, got {}",
            other.kind()
        ))),
    })?;
    let values = field
        .get("values")
        .ok_or_else(|| JsonError::new("missing \"values\" (or \"data\" for a raw field)"))?;
    let value = FieldValue::from_json(set, descriptor, device, values)?;
    let name = field
        .get("name")
        .ok_or_else(|| JsonError::new("missing \"name\""))?;
    if *name != Json::String(value.name().to_string()) {
        return Err(JsonError::new(format!(
            "descriptor {descriptor} in set {set} is \"{}\"",
            value.name()
        ))
        .at("name"));
    }
    builder
        .add_field_with(descriptor, |w| value.encode_data(w))
        .map_err(|e| JsonError::new(e.to_string()).at("values"))
}

/// The bytes of one JSON line as printed by the decoder: a packet (rebuilt from its fields, with
/// payload length and checksum recomputed) or a skip run (its bytes).
pub fn encode_line(line: &str) -> Result<Vec<u8>, JsonError> {
    let v = parse(line)?;
    if !matches!(v, Json::Object(_)) {
        return Err(JsonError::new(format!(
            "expected a JSON object, got {}",
            v.kind()
        )));
    }
    if v.get("skipped").is_some() {
        let o = Obj::new(&v, &["offset", "skipped"])?;
        o.req("offset", u64::from_json)?;
        return o.req("skipped", hex_bytes);
    }
    if v.get("fields").is_none() {
        return Err(JsonError::new(
            "expected a packet ({\"offset\",\"set\",\"fields\"}) or a skip run ({\"offset\",\"skipped\"})",
        ));
    }
    let o = Obj::new(&v, &["offset", "set", "fields"])?;
    o.req("offset", u64::from_json)?;
    let set = o.req("set", u8::from_json)?;
    let fields = o.req("fields", |f| match f {
        Json::Array(items) => Ok(items),
        other => Err(JsonError::new(format!(
            "expected an array, got {}",
            other.kind()
        ))),
    })?;
    let mut builder = PacketBuilder::new(set);
    for (i, field) in fields.iter().enumerate() {
        field_bytes(set, field, &mut builder).map_err(|e| e.index(i).at("fields"))?;
    }
    Ok(builder.finish().to_vec())
}

/// The bytes of several JSON lines (blank lines are ignored); on error, the 1-based line
/// number and the error.
pub fn encode_text(text: &str) -> Result<Vec<u8>, (usize, JsonError)> {
    let mut out = Vec::new();
    for (i, line) in text.lines().enumerate() {
        if line
            .trim_matches(|c: char| matches!(c, ' ' | '\t' | '\r' | '\n'))
            .is_empty()
        {
            continue;
        }
        out.extend(encode_line(line).map_err(|e| (i + 1, e))?);
    }
    Ok(out)
}
