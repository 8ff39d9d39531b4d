//! Hand computations for the tops on a table (`tests/contact_sphere*.rs`).

/// Where and when a one-degree-of-freedom rocking body lifts off, by hand:
/// the angle `θ*` where the closed-form normal force `normal_force(θ)`
/// changes sign (bisection between `theta_start`, where it pushes, and
/// `theta_beyond`, where it would pull), and the time to get there with
/// `θ̇² = rate2(θ)` (Simpson's rule on `dt = dθ/θ̇`).
///
/// ```text
/// N(θ*) = 0,   t* = ∫_{θ_s}^{θ*} dθ / √(rate2(θ))
/// ```
pub fn lift_off_by_hand(
    theta_start: f64,
    theta_beyond: f64,
    normal_force: impl Fn(f64) -> f64,
    rate2: impl Fn(f64) -> f64,
) -> (f64, f64) {
    let (mut lo, mut hi) = (theta_start, theta_beyond);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if normal_force(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let theta_star = lo;
    let n = 20_000;
    let dx = (theta_star - theta_start) / n as f64;
    let f = |th: f64| 1.0 / rate2(th).sqrt();
    let t_star = (f(theta_start)
        + f(theta_star)
        + (1..n)
            .map(|k| if k % 2 == 1 { 4.0 } else { 2.0 } * f(theta_start + k as f64 * dx))
            .sum::<f64>())
        * dx
        / 3.0;
    (theta_star, t_star)
}
