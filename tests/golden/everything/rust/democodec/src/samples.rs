//! Samples: continuation packets grouped by their shared timestamp (`docs/conformance.md` §6).
//!
//! [`SampleTracker`] (no allocation) gives each data packet its sample number; with the `std`
//! feature, [`SampleGrouper`] collects the packets of each sample.

use crate::fields::{FieldItem, Packet};
use crate::framing::FIELD_HEADER_SIZE;

// The sample rule of the protocol (`ir.json` → `protocols[].samples`).
pub use crate::framing::{DATA_SETS, FIRST_SHARED, MAX_KEY, TIMESTAMPS};

/// The key of a packet and the size of its leading shared run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SampleKey {
    bytes: [u8; MAX_KEY],
    len: usize,
    /// Payload bytes of the leading shared run.
    pub shared_prefix: usize,
}

impl SampleKey {
    /// The key bytes (empty: the packet has no key).
    pub fn bytes(&self) -> &[u8] {
        &self.bytes[..self.len]
    }
}

/// The key of a complete packet.
pub fn sample_key(packet: &Packet<'_>) -> SampleKey {
    let mut key = SampleKey {
        bytes: [0; MAX_KEY],
        len: 0,
        shared_prefix: 0,
    };
    let mut seen = [false; TIMESTAMPS.len()];
    let mut pos = 0;
    for item in packet.fields() {
        let FieldItem::Field { descriptor, data } = item else {
            break;
        };
        if u16::from(descriptor) < FIRST_SHARED {
            break;
        }
        let n = FIELD_HEADER_SIZE + data.len();
        if let Some(t) = TIMESTAMPS
            .iter()
            .position(|&(d, size)| d == descriptor && size == data.len())
        {
            if !seen[t] && key.len + n <= MAX_KEY {
                key.bytes[key.len..key.len + n].copy_from_slice(&packet.payload()[pos..pos + n]);
                key.len += n;
            }
            seen[t] = true;
        }
        pos += n;
        key.shared_prefix = pos;
    }
    key
}

/// Where a data packet belongs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SamplePlace {
    /// The sample number (from 0, in stream order).
    pub number: u64,
    /// A continuation of an earlier packet's sample.
    pub continues: bool,
    /// Payload bytes of the leading shared run (copies, in a continuation).
    pub shared_prefix: usize,
}

#[derive(Clone, Copy, Debug)]
struct Slot {
    used: bool,
    number: u64,
    key: SampleKey,
}

/// Numbers the samples of complete packets; fixed state, one slot per data set.
#[derive(Clone, Debug)]
pub struct SampleTracker {
    slots: [Slot; DATA_SETS.len()],
    next: u64,
}

impl Default for SampleTracker {
    fn default() -> Self {
        Self::new()
    }
}

impl SampleTracker {
    /// A tracker before the first packet.
    pub const fn new() -> Self {
        const EMPTY: Slot = Slot {
            used: false,
            number: 0,
            key: SampleKey {
                bytes: [0; MAX_KEY],
                len: 0,
                shared_prefix: 0,
            },
        };
        Self {
            slots: [EMPTY; DATA_SETS.len()],
            next: 0,
        }
    }

    /// The place of a packet of a data set; `None` for other packets.
    pub fn feed(&mut self, packet: &Packet<'_>) -> Option<SamplePlace> {
        let i = DATA_SETS.iter().position(|&s| s == packet.set())?;
        let key = sample_key(packet);
        let slot = &mut self.slots[i];
        if key.len > 0 && slot.used && slot.key.bytes() == key.bytes() {
            return Some(SamplePlace {
                number: slot.number,
                continues: true,
                shared_prefix: key.shared_prefix,
            });
        }
        *slot = Slot {
            used: true,
            number: self.next,
            key,
        };
        self.next += 1;
        Some(SamplePlace {
            number: slot.number,
            continues: false,
            shared_prefix: key.shared_prefix,
        })
    }
}

#[cfg(feature = "std")]
pub use grouper::{Sample, SampleGrouper};

#[cfg(feature = "std")]
mod grouper {
    use super::{SampleTracker, DATA_SETS};
    use crate::fields::{FieldItem, Fields, Packet};

    /// One sample: its set, number and packets.
    #[derive(Clone, Debug, PartialEq, Eq)]
    pub struct Sample {
        /// The sample number.
        pub number: u64,
        /// The descriptor set.
        pub set: u8,
        /// Stream offset of each packet.
        pub offsets: Vec<u64>,
        /// The complete packets, in order.
        pub packets: Vec<Vec<u8>>,
        skip: Vec<usize>,
    }

    impl Sample {
        /// Every field of the sample: the first packet's, then each continuation packet's after
        /// its leading shared run (those are copies).
        pub fn fields(&self) -> impl Iterator<Item = FieldItem<'_>> + '_ {
            self.packets.iter().zip(&self.skip).flat_map(|(p, &skip)| {
                let (set, payload) = Packet::new(p)
                    .map(|p| (p.set(), p.payload()))
                    .unwrap_or((0, &[]));
                Fields::new(set, payload.get(skip..).unwrap_or(&[]))
            })
        }
    }

    /// Groups data packets into samples; a sample is returned once complete (the next packet of
    /// its set starts another one), the rest by [`SampleGrouper::flush`].
    #[derive(Debug, Default)]
    pub struct SampleGrouper {
        tracker: SampleTracker,
        open: Vec<Option<Sample>>,
    }

    impl SampleGrouper {
        /// An empty grouper.
        pub fn new() -> Self {
            Self {
                tracker: SampleTracker::new(),
                open: vec![None; DATA_SETS.len()],
            }
        }

        /// Feeds one complete packet found at `offset`; returns the sample it completes, if any.
        pub fn feed(&mut self, packet: &Packet<'_>, offset: u64) -> Option<Sample> {
            let place = self.tracker.feed(packet)?;
            let i = DATA_SETS.iter().position(|&s| s == packet.set())?;
            if self.open.len() < DATA_SETS.len() {
                self.open.resize(DATA_SETS.len(), None);
            }
            if place.continues {
                if let Some(open) = self.open[i].as_mut() {
                    open.offsets.push(offset);
                    open.packets.push(packet.bytes().to_vec());
                    open.skip.push(place.shared_prefix);
                    return None;
                }
            }
            let new = Sample {
                number: place.number,
                set: packet.set(),
                offsets: vec![offset],
                packets: vec![packet.bytes().to_vec()],
                skip: vec![0],
            };
            self.open[i].replace(new)
        }

        /// The samples still open, in order of their numbers.
        pub fn flush(&mut self) -> Vec<Sample> {
            let mut done: Vec<Sample> = self.open.iter_mut().filter_map(Option::take).collect();
            done.sort_by_key(|s| s.number);
            done
        }
    }
}
