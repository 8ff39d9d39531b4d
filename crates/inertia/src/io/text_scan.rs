//! Byte-level scanning for the text formats (OBJ, ASCII PLY): lines, words
//! and plain decimal integers, without building a `str` per line.
//!
//! Why by hand: on a 1e6-triangle OBJ, `String::from_utf8_lossy` over the
//! whole file, `str::lines` and a `char`-based word split took ≈ 35 % of a
//! whole `kreisel inertia` run (`perf record`), and `str::parse::<i64>` for
//! every face index (with its error path and sign handling) another few
//! percent. Every function here gives exactly what the standard library's
//! counterpart gives (tests below compare them), and falls back to it for
//! anything off the plain path.

/// The next line of `rest` without its `\n`, advancing past it; `None` at
/// the end. The same lines as `str::lines` except that a `\r` before the
/// `\n` is kept (every caller treats it as a blank).
#[inline]
pub(super) fn next_line<'a>(rest: &mut &'a [u8]) -> Option<&'a [u8]> {
    if rest.is_empty() {
        return None;
    }
    let bytes: &'a [u8] = rest;
    match newline(bytes) {
        Some(end) => {
            *rest = &bytes[end + 1..];
            Some(&bytes[..end])
        }
        None => {
            *rest = &[];
            Some(bytes)
        }
    }
}

/// The index of the first `\n`, eight bytes at a time.
#[inline]
fn newline(bytes: &[u8]) -> Option<usize> {
    const ONES: u64 = 0x0101_0101_0101_0101;
    const HIGHS: u64 = 0x8080_8080_8080_8080;
    let mut at = 0;
    let mut rest = bytes;
    while let Some((chunk, tail)) = rest.split_first_chunk::<8>() {
        let x = u64::from_le_bytes(*chunk) ^ (ONES * u64::from(b'\n'));
        // A byte of `x` is zero where the chunk holds `\n`; the lowest set
        // bit of `found` marks the first such byte (borrows only run upward).
        let found = x.wrapping_sub(ONES) & !x & HIGHS;
        if found != 0 {
            return Some(at + (found.trailing_zeros() / 8) as usize);
        }
        at += 8;
        rest = tail;
    }
    rest.iter().position(|&b| b == b'\n').map(|p| at + p)
}

/// Whether `b` separates words in an ASCII line as `str::split_whitespace`
/// separates them (the ASCII `White_Space` characters: space, `\t`, `\n`,
/// `\x0B`, `\x0C`, `\r`).
#[inline]
pub(super) fn is_blank(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\n' | 0x0B | 0x0C | b'\r')
}

/// The next word of `rest` split at the bytes `blank` accepts, advancing
/// past it.
#[inline]
pub(super) fn next_word<'a>(rest: &mut &'a [u8], blank: impl Fn(u8) -> bool) -> Option<&'a [u8]> {
    let bytes: &'a [u8] = rest;
    let start = bytes.iter().position(|&b| !blank(b))?;
    let end = bytes[start..]
        .iter()
        .position(|&b| blank(b))
        .map_or(bytes.len(), |e| start + e);
    *rest = &bytes[end..];
    Some(&bytes[start..end])
}

/// The value of a word of 1 to 18 ASCII digits (no sign), which no integer
/// type's `FromStr` reads differently; `None` for anything else.
#[inline]
pub(super) fn plain_digits(word: &[u8]) -> Option<i64> {
    if word.is_empty() || word.len() > 18 {
        return None;
    }
    let mut value: i64 = 0;
    for &b in word {
        let d = b.wrapping_sub(b'0');
        if d > 9 {
            return None;
        }
        value = value * 10 + i64::from(d);
    }
    Some(value)
}

/// The next word of `rest` (split as [`next_word`] splits) with its value
/// when it is 1 to 18 ASCII digits, advancing past it; `None`, with nothing
/// consumed, for any other word (one pass over the digits instead of
/// splitting first and parsing after).
#[inline]
pub(super) fn next_plain_digits<'a>(
    rest: &mut &'a [u8],
    blank: impl Fn(u8) -> bool,
) -> Option<(i64, &'a [u8])> {
    let bytes: &'a [u8] = rest;
    let start = bytes.iter().position(|&b| !blank(b))?;
    let mut value: i64 = 0;
    let mut end = start;
    while let Some(&b) = bytes.get(end) {
        let d = b.wrapping_sub(b'0');
        if d > 9 || end - start == 18 {
            break;
        }
        value = value * 10 + i64::from(d);
        end += 1;
    }
    if end == start || bytes.get(end).is_some_and(|&b| !blank(b)) {
        return None;
    }
    *rest = &bytes[end..];
    Some((value, &bytes[start..end]))
}

/// `word` as `T`, exactly as `str::parse::<T>` reads it (plain digits by
/// hand, anything else by the standard library).
#[inline]
pub(super) fn parse_integer<T: TryFrom<i64> + core::str::FromStr>(word: &[u8]) -> Option<T> {
    match plain_digits(word) {
        Some(v) => T::try_from(v).ok(),
        None => core::str::from_utf8(word).ok()?.parse().ok(),
    }
}

/// `word` as a float (`f32` or `f64`) by `str::parse` (correctly rounded).
#[inline]
pub(super) fn parse_float<T: core::str::FromStr>(word: &[u8]) -> Option<T> {
    core::str::from_utf8(word).ok()?.parse().ok()
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;

    /// The lines as `next_line` splits them, each without a trailing `\r`
    /// (`str::lines` strips one only before a `\n`; compared without it).
    fn lines_of(text: &str) -> Vec<String> {
        let mut rest = text.as_bytes();
        let mut out = Vec::new();
        while let Some(line) = next_line(&mut rest) {
            out.push(
                String::from_utf8_lossy(line)
                    .trim_end_matches('\r')
                    .to_owned(),
            );
        }
        out
    }

    fn std_lines(text: &str) -> Vec<String> {
        text.lines()
            .map(|l| l.trim_end_matches('\r').to_owned())
            .collect()
    }

    #[test]
    fn lines_match_str_lines() {
        for text in [
            "",
            "\n",
            "a",
            "a\n",
            "a\r\nb",
            "\n\n\nlong line of more than eight bytes\nx\n",
            "0123456\n01234567\n012345678\n",
            "no newline at all in this longer text",
        ] {
            assert_eq!(lines_of(text), std_lines(text), "{text:?}");
        }
    }

    #[test]
    fn words_match_split_whitespace_on_ascii() {
        let line = " \tv  1.5\x0B2\x0C3\r ";
        let mut rest = line.as_bytes();
        let mut words = Vec::new();
        while let Some(w) = next_word(&mut rest, is_blank) {
            words.push(core::str::from_utf8(w).unwrap());
        }
        assert_eq!(words, line.split_whitespace().collect::<Vec<_>>());
    }

    #[test]
    fn integers_match_from_str() {
        for word in [
            "0",
            "007",
            "+5",
            "-5",
            "-0",
            "",
            "+",
            "-",
            "1a",
            "255",
            "256",
            "-128",
            "-129",
            "4294967295",
            "4294967296",
            "999999999999999999",
            "9223372036854775807",
            "9223372036854775808",
            "99999999999999999999999",
        ] {
            let w = word.as_bytes();
            assert_eq!(parse_integer::<u8>(w), word.parse().ok(), "{word}");
            assert_eq!(parse_integer::<i8>(w), word.parse().ok(), "{word}");
            assert_eq!(parse_integer::<u32>(w), word.parse().ok(), "{word}");
            assert_eq!(parse_integer::<i32>(w), word.parse().ok(), "{word}");
            assert_eq!(parse_integer::<i64>(w), word.parse().ok(), "{word}");
        }
    }

    #[test]
    fn plain_digit_words_are_taken_in_one_pass_and_others_left() {
        let line = b" 12\t007 -3 4a 1234567890123456789 123456789012345678 5";
        let mut fused = &line[..];
        let mut split = &line[..];
        while let Some(word) = next_word(&mut split, |b| b.is_ascii_whitespace()) {
            let before = fused;
            match next_plain_digits(&mut fused, |b| b.is_ascii_whitespace()) {
                Some((value, w)) => assert_eq!((Some(value), w), (plain_digits(word), word)),
                None => {
                    assert_eq!((plain_digits(word), fused), (None, before));
                    next_word(&mut fused, |b| b.is_ascii_whitespace());
                }
            }
        }
        assert_eq!(
            next_plain_digits(&mut fused, |b| b.is_ascii_whitespace()),
            None
        );
    }

    proptest! {
        #[test]
        fn any_text_splits_into_the_same_lines(text in "[a\n\r ]{0,40}") {
            prop_assert_eq!(lines_of(&text), std_lines(&text));
        }

        #[test]
        fn any_word_parses_as_from_str(word in "[-+]?[0-9]{0,22}|[0-9a ]{0,4}") {
            let w = word.as_bytes();
            prop_assert_eq!(parse_integer::<i64>(w), word.parse::<i64>().ok());
            prop_assert_eq!(parse_integer::<u16>(w), word.parse::<u16>().ok());
        }
    }
}
