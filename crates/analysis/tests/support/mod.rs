//! Measuring a mode from a nonlinear run: the growth rate and the
//! frequency of a sampled signal, independent of the linearisation.

// Each test target uses its own subset of these helpers.
#![allow(dead_code)]

use glam::{DQuat, DVec3};
use kreisel_dynamics::{Body, BodyId, World};

/// The least-squares slope of `y` on `t`.
pub fn slope(points: &[(f64, f64)]) -> f64 {
    let m = points.len() as f64;
    let (t_mean, y_mean) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), (t, y)| (a + t / m, b + y / m));
    let (num, den) = points.iter().fold((0.0, 0.0), |(a, b), (t, y)| {
        (a + (t - t_mean) * (y - y_mean), b + (t - t_mean).powi(2))
    });
    num / den
}

/// The angular frequency of an oscillating `y` sampled every `h`: its
/// zero crossings (linear interpolation) are `π/ω` apart.
pub fn frequency_from_zeros(samples: &[f64], h: f64) -> f64 {
    let mut zeros = Vec::new();
    for k in 1..samples.len() {
        let (a, b) = (samples[k - 1], samples[k]);
        if a * b < 0.0 {
            zeros.push(h * ((k - 1) as f64 + a / (a - b)));
        }
    }
    assert!(zeros.len() >= 4, "only {} zero crossings", zeros.len());
    let n = zeros.len();
    std::f64::consts::PI * (n - 1) as f64 / (zeros[n - 1] - zeros[0])
}

/// A world with one body, stepped every `h` for `steps` steps; `observe`
/// reads each sample (the start included) from the attitude and the
/// angular velocity in body axes.
pub fn run(
    gravity: DVec3,
    body: Body,
    h: f64,
    steps: usize,
    mut observe: impl FnMut(DQuat, DVec3) -> f64,
) -> Vec<f64> {
    let mut world = World::try_new(gravity, h).expect("a world");
    let id: BodyId = world.add(body).expect("a body");
    let read = |world: &World| world.state(id).expect("the body");
    let mut samples = Vec::with_capacity(steps + 1);
    let s = read(&world);
    samples.push(observe(s.world_from_body, s.omega_body));
    for _ in 0..steps {
        world.step(h).expect("a step");
        let s = read(&world);
        samples.push(observe(s.world_from_body, s.omega_body));
    }
    samples
}

/// The growth rate and angular frequency of `y = a e^{σt} cos(ωt + φ)`
/// sampled every `h`: its zeros are `π/ω` apart (an even number of
/// half periods, linear interpolation), its extrema (parabolas through
/// the three samples around each) lie on `ln|y| = const + σt`.
pub fn growth_and_frequency(samples: &[f64], h: f64) -> (f64, f64) {
    let (mut zeros, mut extrema) = (Vec::new(), Vec::new());
    for k in 1..samples.len() - 1 {
        let (a, b, c) = (samples[k - 1], samples[k], samples[k + 1]);
        if a * b < 0.0 {
            zeros.push(h * ((k - 1) as f64 + a / (a - b)));
        }
        if b.abs() > a.abs() && b.abs() >= c.abs() {
            let shift = 0.5 * (a - c) / (a - 2.0 * b + c);
            extrema.push((
                h * (k as f64 + shift),
                (b - 0.25 * (a - c) * shift).abs().ln(),
            ));
        }
    }
    assert!(zeros.len() >= 3, "only {} zero crossings", zeros.len());
    let spans = (zeros.len() - 1) & !1;
    let omega = std::f64::consts::PI * spans as f64 / (zeros[spans] - zeros[0]);
    (slope(&extrema), omega)
}

/// The growth rate of samples of `ln |y|` taken every `h` (from `t = 0`):
/// the least-squares slope over the last three quarters, where the
/// growing mode has left the others behind.
pub fn late_slope(log_samples: &[f64], h: f64) -> f64 {
    let points: Vec<(f64, f64)> = log_samples
        .iter()
        .enumerate()
        .map(|(k, &y)| (k as f64 * h, y))
        .collect();
    slope(&points[log_samples.len() / 4..])
}
