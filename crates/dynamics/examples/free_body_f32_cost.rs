//! What one `f32` frame step costs ([`FreeBodyF32::try_step`] and
//! [`try_free_body_step_f32`]) for the cases its module docs name: a game
//! spin at 60 Hz (one PDMV10 step), a symmetric body (closed form), fast
//! spins (sub-steps), and beyond 256 sub-steps (the exact solution).
//!
//! ```text
//! cargo run --release -p kreisel-dynamics --example free_body_f32_cost
//! ```
//!
//! Timings are medians of 7 repetitions on whatever machine runs it; this
//! is a measurement, never a test.

use std::hint::black_box;
use std::time::Instant;

use glam::{Quat, Vec3};
use kreisel_dynamics::{FreeBodyF32, try_free_body_step_f32};

/// Median over 7 repetitions of the time per call of `f`, ns.
fn median_ns(calls: usize, mut f: impl FnMut()) -> f64 {
    let mut times: Vec<f64> = (0..7)
        .map(|_| {
            let start = Instant::now();
            for _ in 0..calls {
                f();
            }
            start.elapsed().as_secs_f64() * 1e9 / calls as f64
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[3]
}

fn main() {
    let frame = Quat::from_rotation_y(0.2);
    let brick = Vec3::new(1.0, 2.0, 3.0);
    let q0 = Quat::from_rotation_x(0.3);
    let spin = |w: f32| q0 * Vec3::new(0.01, 1.0, 0.0).normalize() * w;
    let dt = 1.0 / 60.0;
    println!("| case | ω_max dt (rad) | PDMV10 sub-steps | ns per call |");
    println!("|---|---|---|---|");
    for (case, moments, w, dt, calls) in [
        ("asymmetric, 6 rad/s at 60 Hz", brick, 6.0, dt, 200_000),
        (
            "symmetric, 6 rad/s at 60 Hz",
            Vec3::new(1.0, 1.0, 1.5),
            6.0,
            dt,
            200_000,
        ),
        ("asymmetric, 300 rad/s at 60 Hz", brick, 300.0, dt, 100_000),
        ("asymmetric, 2 rad/s over 1 s", brick, 2.0, 1.0, 50_000),
        ("asymmetric, 100 rad/s over 1 s", brick, 100.0, 1.0, 300),
    ] {
        let body = FreeBodyF32::new(moments, frame);
        let w = spin(w);
        let ns = median_ns(calls, || {
            black_box(body.try_step(black_box(q0), black_box(w), black_box(dt))).unwrap();
        });
        // The module's bound: ω_max² = 2E / I_min, E = ½ Σ Iₖ ωₖ² (principal axes).
        let w_principal = ((q0 * frame).inverse() * w).as_dvec3();
        let moments64 = moments.as_dvec3();
        let two_e = (moments64 * w_principal * w_principal).element_sum();
        let span = (two_e / moments64.min_element()).sqrt() * f64::from(dt);
        let substeps = (span / 0.25).ceil();
        let how = if moments.x == moments.y || moments.y == moments.z || moments.x == moments.z {
            "closed form".to_string()
        } else if substeps > 256.0 {
            "exact solution".to_string()
        } else {
            format!("{substeps}")
        };
        println!("| {case} | {span:.3} | {how} | {ns:.0} |");
    }
    let w = spin(6.0);
    let ns = median_ns(200_000, || {
        black_box(try_free_body_step_f32(
            black_box(brick),
            black_box(frame),
            black_box(q0),
            black_box(w),
            black_box(dt),
        ))
        .unwrap();
    });
    println!(
        "| try_free_body_step_f32 (set-up per call), asymmetric, 6 rad/s at 60 Hz | as above | 1 | {ns:.0} |"
    );
}
