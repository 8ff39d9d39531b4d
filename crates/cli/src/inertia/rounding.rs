//! `--digits N`: numbers rounded to N significant digits, and components
//! that are mere round-off next to the largest one of their vector or
//! tensor snapped to exactly 0.
//!
//! Rounding goes through Rust's correctly rounded decimal formatting
//! (`{:.*e}`) and back, so the f64 printed in shortest form is exactly the
//! N-digit decimal (`1.23e-5`, not `1.2300000000000001e-5`).

/// The fewest and most significant digits `--digits` accepts (17 digits
/// identify every f64).
pub const DIGITS: core::ops::RangeInclusive<u32> = 1..=17;

/// `x` rounded to `digits` significant digits (round half to even on the
/// exact binary value); 0, infinities and NaN unchanged.
///
/// ```text
/// significant(1234.5678, 3) = 1230,   significant(-6.4e-23, 2) = -6.4e-23
/// ```
pub fn significant(x: f64, digits: u32) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let precision = digits.saturating_sub(1) as usize;
    format!("{x:.precision$e}").parse().unwrap_or(x)
}

/// Half the last digit of `reference` written with `digits` significant
/// digits: a value smaller than this in magnitude does not show at that
/// precision next to `reference`.
///
/// ```text
/// resolution(1.5e-3, 3) = 0.5 · 10^(−3 − 2) = 5e-6
/// ```
pub fn resolution(reference: f64, digits: u32) -> f64 {
    let reference = reference.abs();
    if reference == 0.0 || !reference.is_finite() {
        return 0.0;
    }
    // The decimal exponent of the rounded reference (9.996 → 1.00e1 at 3 digits).
    let exponent = significant(reference, digits).log10().floor();
    0.5 * 10f64.powf(exponent - f64::from(digits.saturating_sub(1)))
}

/// `x` rounded to `digits` significant digits, or 0 when `|x|` is below
/// [`resolution`]`(reference, digits)`.
pub fn snapped(x: f64, reference: f64, digits: u32) -> f64 {
    if x.abs() < resolution(reference, digits) {
        0.0
    } else {
        significant(x, digits)
    }
}

/// Every element of `values` rounded with [`snapped`] against the largest
/// magnitude among them (or `reference`, when larger).
pub fn snapped_all<const N: usize>(values: [f64; N], reference: f64, digits: u32) -> [f64; N] {
    let largest = values.iter().fold(reference.abs(), |a, v| a.max(v.abs()));
    values.map(|v| snapped(v, largest, digits))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn significant_digits_are_exact_decimals() {
        assert_eq!(significant(1234.5678, 3), 1230.0);
        assert_eq!(significant(0.000_123_456, 2), 1.2e-4);
        assert_eq!(significant(-2.0 / 3.0, 4), -0.6667);
        assert_eq!(significant(9.9996, 4), 10.0);
        assert_eq!(significant(1.0 / 3.0, 17), 1.0 / 3.0);
        assert_eq!(significant(0.0, 3), 0.0);
        assert!(significant(f64::NAN, 3).is_nan());
    }

    #[test]
    fn resolution_follows_the_last_digit() {
        assert_eq!(resolution(1.5e-3, 3), 0.5e-5);
        assert_eq!(resolution(-250.0, 1), 50.0);
        // 9.996 rounds up to 10.0: the last digit is then 0.1.
        assert_eq!(resolution(9.996, 3), 0.05);
        assert_eq!(resolution(0.0, 3), 0.0);
    }

    #[test]
    fn round_off_next_to_the_largest_is_zero() {
        // The issue's example: a product of 6.4e-23 next to moments of 1e-5.
        assert_eq!(snapped(6.4e-23, 1.07e-5, 6), 0.0);
        assert_eq!(snapped(-3.3e-6, 1.07e-5, 2), -3.3e-6);
        assert_eq!(snapped(-3.3e-7, 1.07e-5, 2), 0.0);
        assert_eq!(snapped_all([0.5, 1e-17, -0.25], 0.0, 3), [0.5, 0.0, -0.25]);
        assert_eq!(snapped_all([1e-17, 2e-17], 1.0, 3), [0.0, 0.0]);
    }
}
