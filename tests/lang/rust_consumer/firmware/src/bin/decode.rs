//! A firmware image for a Cortex-M4F (`thumbv7em-none-eabihf`) around the `no_std` consumer
//! (`consumer-core`): parses the bytes of a receive buffer and decodes every field (every decoder
//! of the crate's dispatch is linked: the field comes from the data), and builds a packet. No
//! global allocator is defined, so the image links only if nothing uses `alloc`. Built (never
//! run) by tests/lang/rust.sh embedded, which prints its size: with every set in the dispatch, and
//! with the feature `one-set` (one set's cargo feature `set-*`), which must stay under 32 kB.
#![no_std]
#![no_main]

use core::hint::black_box;
use core::panic::PanicInfo;

use consumer_core::{build_packet, count_fields};

/// Where a UART driver would put received bytes, and the field to send; `black_box` keeps the
/// optimizer from assuming their contents.
static RX: [u8; 256] = [0; 256];
static TX_FIELD: [u8; 3] = [0x01, 0x01, 0];

#[panic_handler]
fn panic(_: &PanicInfo) -> ! {
    loop {}
}

/// The reset handler.
#[no_mangle]
pub extern "C" fn reset() -> ! {
    loop {
        black_box(count_fields(black_box(&RX[..])));
        let [set, descriptor, len] = *black_box(&TX_FIELD);
        let mut tx = [0u8; 300];
        let data = [0u8; 16];
        let n = build_packet(set, descriptor, &data[..usize::from(len).min(16)], &mut tx);
        black_box(&tx[..n]);
    }
}

/// The reset vector, second word of the vector table (link.x).
#[link_section = ".vector_table.reset"]
#[no_mangle]
pub static RESET_VECTOR: extern "C" fn() -> ! = reset;
