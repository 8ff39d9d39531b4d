//! Arrays of `N` lanes for the side-by-side (SIMD) conversions.

/// `[f(0), …, f(N − 1)]`, one lane an element.
///
/// ```text
/// lanes(f) = [f(0), f(1), …, f(N − 1)]
/// ```
///
/// A plain loop into an array that starts as `[fill; N]`, always inlined:
/// `core::array::from_fn` does the same, but its closure wrapper was left
/// out of line in the Python module's as_euler loop (a call and a stack
/// round trip per lane, ~25 % of the time, `perf`).
#[inline(always)]
pub(crate) fn lanes<T: Copy, const N: usize>(fill: T, mut f: impl FnMut(usize) -> T) -> [T; N] {
    let mut out = [fill; N];
    for (i, slot) in out.iter_mut().enumerate() {
        *slot = f(i);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lane_i_is_f_of_i() {
        let squares: [f64; 5] = lanes(0.0, |i| (i * i) as f64);
        assert_eq!(squares, [0.0, 1.0, 4.0, 9.0, 16.0]);
        let none: [bool; 0] = lanes(true, |_| false);
        assert_eq!(none, []);
    }
}
