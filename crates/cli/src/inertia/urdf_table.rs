//! The per-link tables of `inertia --urdf` on standard error: columns padded
//! to their widest cell, numbers to six significant digits.

use glam::DVec3;

use kreisel_scene::numbers::Shortest;

/// `x` to six significant digits, in shortest form (`0.0123457`).
pub fn sig(x: f64) -> String {
    let rounded: f64 = format!("{x:.5e}").parse().unwrap_or(x);
    Shortest(rounded).to_string()
}

/// A vector as `x y z`, six significant digits each.
pub fn sig3(v: DVec3) -> String {
    format!("{} {} {}", sig(v.x), sig(v.y), sig(v.z))
}

/// The table as text: a header, then one line per row; every column but the
/// last padded to its widest cell, two spaces apart.
pub fn render(header: &[&str], rows: &[Vec<String>]) -> String {
    let n = header.len();
    let mut widths: Vec<usize> = header.iter().map(|h| h.chars().count()).collect();
    for row in rows {
        for (w, cell) in widths.iter_mut().zip(row) {
            *w = (*w).max(cell.chars().count());
        }
    }
    let line = |cells: Vec<&str>| {
        let mut out = String::new();
        for (k, cell) in cells.iter().enumerate() {
            out.push_str(cell);
            if k + 1 < n {
                let pad = widths[k] - cell.chars().count() + 2;
                out.extend(std::iter::repeat_n(' ', pad));
            }
        }
        out.trim_end().to_owned() + "\n"
    };
    let mut out = line(header.to_vec());
    for row in rows {
        out.push_str(&line(row.iter().map(String::as_str).collect()));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn six_digits_and_padding() {
        assert_eq!(sig(0.012345678), "0.0123457");
        assert_eq!(sig(-2.0), "-2");
        assert_eq!(sig3(DVec3::new(1.0, 1e-20, 1234567.0)), "1 1e-20 1234570");
        let t = render(
            &["a", "bb", "c"],
            &[vec!["xxx".into(), "y".into(), "z z".into()]],
        );
        assert_eq!(t, "a    bb  c\nxxx  y   z z\n");
    }
}
