//! `cargo fuzz run convert_lines`: the first byte picks the input and
//! output representations and `--degrees`, the rest is lines for `kreisel
//! convert`: each line an error or finite numbers, never a panic.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|bytes: &[u8]| kreisel_fuzz::convert_lines(bytes));
