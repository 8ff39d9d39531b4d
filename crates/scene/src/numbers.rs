//! The text of one line ⇄ a short list of numbers.
//!
//! Reading: numbers are separated by commas and/or whitespace (spaces, tabs);
//! whitespace around a comma belongs to the separator, so `0.1, 0.2 0.3`,
//! `0.1,0.2,0.3` and `0.1\t0.2\t0.3` are the same three numbers. Each number
//! is parsed by `f64::from_str` (so `1e-3`, `-.5`, `+2` are fine) and must
//! be finite. Writing: comma-separated, no spaces, each number in Rust's
//! shortest round-trip form (`{}`, or `{:e}` for very small or large magnitudes).

#![forbid(unsafe_code)]

use core::fmt;
use std::io::{self, Write};

use crate::line_problem::LineProblem;

/// The most numbers any representation has (a 3 × 3 matrix).
pub const MAX_NUMBERS: usize = 9;

/// Up to [`MAX_NUMBERS`] numbers, stored inline (no allocation per line), and
/// how many the line held in total.
///
/// Numbers beyond [`MAX_NUMBERS`] are checked but not kept; [`Numbers::count`]
/// still counts them, so an error can say how many were found.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Numbers {
    values: [f64; MAX_NUMBERS],
    count: usize,
}

impl Numbers {
    /// Numbers from a fixed-size array (at most [`MAX_NUMBERS`], checked at compile time).
    pub fn from_array<const N: usize>(values: [f64; N]) -> Self {
        const { assert!(N <= MAX_NUMBERS) };
        let mut out = Self {
            values: [0.0; MAX_NUMBERS],
            count: N,
        };
        out.values[..N].copy_from_slice(&values);
        out
    }

    /// How many numbers the line held (may exceed [`MAX_NUMBERS`]).
    pub fn count(&self) -> usize {
        self.count
    }

    /// The numbers kept (the first `min(count, MAX_NUMBERS)`).
    pub fn as_slice(&self) -> &[f64] {
        &self.values[..self.count.min(MAX_NUMBERS)]
    }

    /// Appends one number (counted always, kept while there is room).
    fn push(&mut self, value: f64) {
        if let Some(slot) = self.values.get_mut(self.count) {
            *slot = value;
        }
        self.count += 1;
    }
}

/// Parses the numbers of one (non-blank, non-comment) line.
///
/// ```text
/// line      = field ("," field)*
/// field     = number (whitespace+ number)*      (surrounding whitespace ignored)
/// ```
///
/// # Errors
/// [`LineProblem::EmptyNumber`] for an empty field (`1,,2`, a leading or
/// trailing comma), [`LineProblem::BadNumber`] for a token `f64::from_str`
/// rejects, [`LineProblem::NonFinite`] for NaN, infinities and overflowing
/// numbers such as `1e999`.
pub fn parse_numbers(text: &str) -> Result<Numbers, LineProblem> {
    let mut numbers = Numbers {
        values: [0.0; MAX_NUMBERS],
        count: 0,
    };
    for field in text.split(',') {
        let mut tokens = field.split_whitespace().peekable();
        if tokens.peek().is_none() {
            return Err(LineProblem::EmptyNumber {
                position: numbers.count + 1,
            });
        }
        for token in tokens {
            let value: f64 = token.parse().map_err(|_| LineProblem::BadNumber {
                token: token.to_owned(),
            })?;
            if !value.is_finite() {
                return Err(LineProblem::NonFinite {
                    token: token.to_owned(),
                });
            }
            numbers.push(value);
        }
    }
    Ok(numbers)
}

/// Writes numbers comma-separated, without spaces, followed by a newline.
///
/// Each number is written with the fewest digits that parse back to the
/// same `f64`: with `{}` (`0.25`, `-3`), or with `{:e}` (`1.5e-300`) when
/// `|x| < 1e-4` or `|x| ≥ 1e16`, where `{}` would spell out hundreds of
/// zeros (the same switch as Rust's `{:?}`, without its `.0`). A negative
/// zero is written as `0`, since its sign carries no meaning for a rotation.
pub fn write_numbers<W: Write + ?Sized>(out: &mut W, numbers: &[f64]) -> io::Result<()> {
    for (n, &value) in numbers.iter().enumerate() {
        if n > 0 {
            out.write_all(b",")?;
        }
        write!(out, "{}", Shortest(value))?;
    }
    out.write_all(b"\n")
}

/// One number in shortest round-trip form, as [`write_numbers`] writes it.
///
/// `{}` (`0.25`, `-3`), or `{:e}` (`1.5e-300`) when `|x| < 1e-4` or
/// `|x| ≥ 1e16`; a negative zero is written as `0`. Non-finite values are
/// written as Rust does (`NaN`, `inf`): callers that need a strict syntax
/// (JSON) check finiteness first.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Shortest(pub f64);

impl fmt::Display for Shortest {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // −0 + 0 = +0 in round-to-nearest; every other value is unchanged.
        let value = self.0 + 0.0;
        let magnitude = value.abs();
        if magnitude != 0.0 && magnitude.is_finite() && !(1e-4..1e16).contains(&magnitude) {
            write!(f, "{value:e}")
        } else {
            write!(f, "{value}")
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(text: &str) -> Vec<f64> {
        match parse_numbers(text) {
            Ok(n) => n.as_slice().to_vec(),
            Err(e) => panic!("{text:?}: {e}"),
        }
    }

    #[test]
    fn separators_commas_whitespace_mixed() {
        let expect = vec![0.1, 0.2, 0.3];
        for text in [
            "0.1,0.2,0.3",
            "0.1 0.2 0.3",
            "0.1, 0.2 0.3",
            "0.1\t0.2\t0.3",
            "  0.1 ,\t0.2 ,0.3  ",
            "0.1 ,0.2\t, 0.3",
        ] {
            assert_eq!(parse(text), expect, "{text:?}");
        }
        assert_eq!(parse("1e-3 -.5 +2 5."), vec![1e-3, -0.5, 2.0, 5.0]);
    }

    #[test]
    fn empty_fields_are_errors() {
        for (text, position) in [("1,,2", 2), (",1,2", 1), ("1,2,", 3), ("1, ,2", 2)] {
            match parse_numbers(text) {
                Err(LineProblem::EmptyNumber { position: p }) => assert_eq!(p, position, "{text}"),
                other => panic!("{text:?}: {other:?}"),
            }
        }
    }

    #[test]
    fn bad_and_non_finite_tokens_are_quoted() {
        match parse_numbers("1, 2x, 3") {
            Err(LineProblem::BadNumber { token }) => assert_eq!(token, "2x"),
            other => panic!("{other:?}"),
        }
        for token in ["nan", "inf", "-infinity", "1e999"] {
            match parse_numbers(&format!("1 {token} 3")) {
                Err(LineProblem::NonFinite { token: t }) => assert_eq!(t, token),
                other => panic!("{token}: {other:?}"),
            }
        }
    }

    #[test]
    fn counts_beyond_capacity() {
        let n = parse_numbers("1 2 3 4 5 6 7 8 9 10 11").unwrap();
        assert_eq!(n.count(), 11);
        assert_eq!(n.as_slice().len(), MAX_NUMBERS);
    }

    #[test]
    fn writes_shortest_round_trip_without_negative_zero() {
        let mut out = Vec::new();
        let values = [1.0, -0.0, 0.1, -2.5e-300, 1e-4, 9.5e-5, 1.5e16, -3.0];
        write_numbers(&mut out, &values).unwrap();
        let text = String::from_utf8(out).unwrap();
        assert_eq!(text, "1,0,0.1,-2.5e-300,0.0001,9.5e-5,1.5e16,-3\n");
        let mut out = Vec::new();
        let values = [0.1 + 0.2, 1e-320, f64::MAX, -f64::MIN_POSITIVE, 123456.789];
        write_numbers(&mut out, &values).unwrap();
        let text = String::from_utf8(out).unwrap();
        let back: Vec<f64> = text.trim().split(',').map(|t| t.parse().unwrap()).collect();
        assert_eq!(back, values);
    }

    #[test]
    fn shortest_matches_write_numbers() {
        let shown: Vec<String> = [1.0, -0.0, 2.5e-300, 1.5e16, 0.1 + 0.2]
            .iter()
            .map(|&x| Shortest(x).to_string())
            .collect();
        assert_eq!(
            shown,
            ["1", "0", "2.5e-300", "1.5e16", "0.30000000000000004"]
        );
    }
}
