//! The notes of the `inertia --urdf` tables in one short style: a mesh is
//! named as the URDF writes it (not by the path it resolved to, absolute
//! after a `package://` search), and every decimal number has at most six
//! significant digits in shortest form (`-8.51927e-7`, `0`), as in the
//! table's columns. Whole numbers (counts, indices) are left as they are.

use std::path::Path;

use super::urdf_table::sig;

/// `text` with the resolved path `resolved` named as `written`, and its
/// decimal numbers shortened.
pub fn tidy(text: &str, resolved: &Path, written: &str) -> String {
    let resolved = resolved.display().to_string();
    if resolved.is_empty() {
        return shorten_numbers(text);
    }
    text.split(resolved.as_str())
        .map(shorten_numbers)
        .collect::<Vec<_>>()
        .join(written)
}

/// Whether the byte at `i` of `b` can continue a number token.
fn in_number(b: &[u8], i: usize) -> bool {
    b[i].is_ascii_digit()
        || b[i] == b'.'
        || ((b[i] == b'e' || b[i] == b'E') && i > 0 && b[i - 1].is_ascii_digit())
        || ((b[i] == b'-' || b[i] == b'+') && i > 0 && (b[i - 1] == b'e' || b[i - 1] == b'E'))
}

/// Every decimal number of `text` (a token with a `.` or an exponent that
/// parses as a finite f64, not inside a word) to six significant digits.
pub fn shorten_numbers(text: &str) -> String {
    let b = text.as_bytes();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    while i < b.len() {
        let word_before = i > 0 && (b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_');
        let starts =
            b[i].is_ascii_digit() || (b[i] == b'-' && i + 1 < b.len() && b[i + 1].is_ascii_digit());
        if !starts || word_before {
            let c = text[i..].chars().next().unwrap_or(' ');
            out.push(c);
            i += c.len_utf8();
            continue;
        }
        let mut j = i + 1;
        while j < b.len() && in_number(b, j) {
            j += 1;
        }
        // A trailing '.' ends a sentence, not the number.
        let mut end = j;
        while end > i + 1 && b[end - 1] == b'.' {
            end -= 1;
        }
        let token = &text[i..end];
        let word_after = end < b.len() && (b[end].is_ascii_alphabetic() || b[end] == b'_');
        let decimal = token.contains(['.', 'e', 'E']);
        match token.parse::<f64>() {
            Ok(x) if decimal && !word_after && x.is_finite() => out.push_str(&sig(x)),
            _ => out.push_str(token),
        }
        i = end;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_in_one_short_style() {
        assert_eq!(
            shorten_numbers(
                "mesh is open: 77 boundary edges, one at (-0.000000851927325129509, 0.0814937949180603, 0e0)."
            ),
            "mesh is open: 77 boundary edges, one at (-8.51927e-7, 0.0814938, 0)."
        );
        assert_eq!(
            shorten_numbers("welded 2 vertices within 3.981e-7 (largest move 3.630e-19)"),
            "welded 2 vertices within 3.981e-7 (largest move 3.63e-19)"
        );
        // Names keep their digits.
        assert_eq!(
            shorten_numbers("link_1.stl v2.0 x1.25y"),
            "link_1.stl v2.0 x1.25y"
        );
    }

    #[test]
    fn paths_as_written() {
        let resolved = Path::new("/home/u/ws/src/bot/meshes/a.stl");
        assert_eq!(
            tidy(
                "cannot read /home/u/ws/src/bot/meshes/a.stl: gone at 1.23456789",
                resolved,
                "package://bot/meshes/a.stl"
            ),
            "cannot read package://bot/meshes/a.stl: gone at 1.23457"
        );
    }
}
