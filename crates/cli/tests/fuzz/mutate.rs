//! Mutated seed files as a proptest strategy: a seed from `fuzz/corpus/`
//! (the cargo-fuzz seed corpus) with a few byte-level and token-level edits.

use std::path::{Path, PathBuf};

use proptest::collection::vec;
use proptest::prelude::*;
use proptest::sample::select;
use proptest::test_runner::RngSeed;

/// The proptest settings of the CI pass: `cases` per test, no persistence
/// files, and a fixed RNG seed so that CI runs the same inputs every time
/// (set `PROPTEST_RNG_SEED` to explore others; the campaign explores more).
pub fn ci_config(cases: u32) -> ProptestConfig {
    let mut config = ProptestConfig {
        cases,
        failure_persistence: None,
        ..ProptestConfig::default()
    };
    if std::env::var_os("PROPTEST_RNG_SEED").is_none() {
        config.rng_seed = RngSeed::Fixed(0x006b_7265_6973_656c);
    }
    config
}

/// The committed seed corpus of one fuzz target.
pub fn corpus_dir(target: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../fuzz/corpus")
        .join(target)
}

/// Every seed of a fuzz target, sorted by file name (so runs repeat).
pub fn seeds(target: &str) -> Vec<Vec<u8>> {
    let dir = corpus_dir(target);
    let mut paths: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|entry| entry.expect("corpus entry").path())
        .filter(|p| p.is_file())
        .collect();
    paths.sort();
    assert!(!paths.is_empty(), "no seeds in {}", dir.display());
    paths
        .iter()
        .map(|p| std::fs::read(p).expect("read seed"))
        .collect()
}

/// Text that parsers find hard: extreme and non-finite numbers, separators,
/// line ends, a BOM, a NUL.
const TEXT_TOKENS: &[&str] = &[
    "nan",
    "NaN",
    "inf",
    "-inf",
    "1e308",
    "-1e308",
    "1e999",
    "1e-320",
    "5e-324",
    "1e16",
    "1e-16",
    "0",
    "-0",
    "-1",
    "1e300",
    "1e-300",
    "4294967295",
    "18446744073709551616",
    "9007199254740993",
    "0.1",
    "\n",
    "\r",
    "\r\n",
    "\0",
    "\u{feff}",
    ",",
    " ",
    "#",
    "[",
    "]",
    "=",
    "\"",
    "{",
    "}",
    "/",
    "//",
    "-",
    "1e10",
    "100000",
];

/// Little-endian words that binary headers and counts find hard.
const BINARY_TOKENS: &[&[u8]] = &[
    &[0, 0, 0, 0],
    &[1, 0, 0, 0],
    &[0xff, 0xff, 0xff, 0xff],
    &[0xff, 0xff, 0xff, 0x7f],
    &[0, 0, 0, 0x80],
    &[0, 0, 0xc0, 0x7f],             // f32 NaN
    &[0, 0, 0x80, 0x7f],             // f32 +inf
    &[0xff, 0xff, 0x7f, 0x7f],       // f32::MAX
    &[1, 0, 0, 0],                   // f32 smallest subnormal
    &[0, 0, 0, 0, 0, 0, 0xf8, 0x7f], // f64 NaN
];

/// One edit of a byte string; positions are taken modulo its length.
#[derive(Debug, Clone)]
pub enum Edit {
    /// Flips one bit.
    Flip { at: usize, bit: u8 },
    /// Sets one byte.
    Set { at: usize, byte: u8 },
    /// Inserts bytes.
    Insert { at: usize, bytes: Vec<u8> },
    /// Removes up to `len` bytes.
    Delete { at: usize, len: usize },
    /// Replaces the number (run of `0-9.eE+-`) at a position with a token.
    ReplaceNumber { at: usize, token: &'static str },
    /// Inserts a token.
    InsertToken { at: usize, token: &'static str },
    /// Overwrites bytes with a binary word.
    Overwrite { at: usize, word: &'static [u8] },
    /// Copies a chunk to another position (repeats lines, faces, tables).
    Duplicate { from: usize, len: usize, to: usize },
}

fn edit() -> impl Strategy<Value = Edit> {
    prop_oneof![
        1 => (any::<usize>(), 0u8..8).prop_map(|(at, bit)| Edit::Flip { at, bit }),
        1 => (any::<usize>(), any::<u8>()).prop_map(|(at, byte)| Edit::Set { at, byte }),
        1 => (any::<usize>(), vec(any::<u8>(), 1..8)).prop_map(|(at, bytes)| Edit::Insert { at, bytes }),
        1 => (any::<usize>(), 1usize..64).prop_map(|(at, len)| Edit::Delete { at, len }),
        3 => (any::<usize>(), select(TEXT_TOKENS)).prop_map(|(at, token)| Edit::ReplaceNumber { at, token }),
        1 => (any::<usize>(), select(TEXT_TOKENS)).prop_map(|(at, token)| Edit::InsertToken { at, token }),
        1 => (any::<usize>(), select(BINARY_TOKENS)).prop_map(|(at, word)| Edit::Overwrite { at, word }),
        1 => (any::<usize>(), 1usize..200, any::<usize>())
            .prop_map(|(from, len, to)| Edit::Duplicate { from, len, to }),
    ]
}

/// Whether `b` can be part of a number.
fn numeric(b: u8) -> bool {
    b.is_ascii_digit() || matches!(b, b'.' | b'e' | b'E' | b'+' | b'-')
}

/// `bytes` after one edit.
pub fn apply(bytes: &mut Vec<u8>, edit: &Edit) {
    let n = bytes.len();
    let pos = |at: usize| if n == 0 { 0 } else { at % n };
    let end = |at: usize| if n == 0 { 0 } else { at % (n + 1) };
    match edit {
        Edit::Flip { at, bit } if n > 0 => bytes[pos(*at)] ^= 1 << bit,
        Edit::Set { at, byte } if n > 0 => bytes[pos(*at)] = *byte,
        Edit::Insert { at, bytes: new } => {
            let at = end(*at);
            bytes.splice(at..at, new.iter().copied());
        }
        Edit::Delete { at, len } if n > 0 => {
            let at = pos(*at);
            bytes.drain(at..(at + len).min(n));
        }
        Edit::ReplaceNumber { at, token } if n > 0 => {
            // The run of number characters at or after `at` (else insert).
            let start = (pos(*at)..n)
                .find(|&i| bytes[i].is_ascii_digit())
                .unwrap_or(pos(*at));
            let mut from = start;
            while from > 0 && numeric(bytes[from - 1]) {
                from -= 1;
            }
            let mut to = start;
            while to < n && numeric(bytes[to]) {
                to += 1;
            }
            bytes.splice(from..to, token.bytes());
        }
        Edit::InsertToken { at, token } => {
            let at = end(*at);
            bytes.splice(at..at, token.bytes());
        }
        Edit::Overwrite { at, word } if n > 0 => {
            let at = pos(*at);
            for (k, &b) in word.iter().enumerate() {
                if let Some(slot) = bytes.get_mut(at + k) {
                    *slot = b;
                }
            }
        }
        Edit::Duplicate { from, len, to } if n > 0 => {
            let from = pos(*from);
            let chunk = bytes[from..(from + len).min(n)].to_vec();
            let to = end(*to);
            bytes.splice(to..to, chunk);
        }
        _ => {}
    }
}

/// A seed of `target` with up to five edits (none, sometimes: the seeds
/// themselves are cases too).
pub fn mutated(target: &str) -> impl Strategy<Value = Vec<u8>> + use<> {
    (select(seeds(target)), vec(edit(), 0..6)).prop_map(|(mut bytes, edits)| {
        for e in &edits {
            apply(&mut bytes, e);
        }
        bytes
    })
}

#[test]
fn edits_change_what_they_name() {
    let mut b = b"v 1.5 2 3".to_vec();
    apply(
        &mut b,
        &Edit::ReplaceNumber {
            at: 3,
            token: "nan",
        },
    );
    assert_eq!(b, b"v nan 2 3");
    apply(
        &mut b,
        &Edit::Duplicate {
            from: 0,
            len: 2,
            to: 9,
        },
    );
    assert_eq!(b, b"v nan 2 3v ");
    apply(&mut b, &Edit::Delete { at: 9, len: 100 });
    assert_eq!(b, b"v nan 2 3");
    let mut empty = Vec::new();
    apply(&mut empty, &Edit::Delete { at: 5, len: 5 });
    apply(
        &mut empty,
        &Edit::InsertToken {
            at: 7,
            token: "inf",
        },
    );
    assert_eq!(empty, b"inf");
}
