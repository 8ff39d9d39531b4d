//! Work–precision of the free-body integrators on rapier's Dzhanibekov
//! scenario (I = (1, 2, 3), ω₀ = (0.01, 1, 0), 100 s): attitude error at
//! t = 100 s against the mpmath reference, and run time per step, for
//! every method over a range of step sizes. Prints a Markdown table (used
//! in BENCHMARKS.md).
//!
//! ```text
//! cargo run --release --example free_body_work_precision
//! ```

use std::hint::black_box;
use std::time::Instant;

use kreisel::dynamics::{PrincipalState, integrate, method};
use kreisel::kinematics::rotation_angle_between;

#[path = "../tests/common/free_body.rs"]
mod free_body;

fn main() {
    let r = free_body::load("rapier");
    let (_, q0, l0) = r.samples[0];
    let &(t_end, q_ref, _) = r.samples.last().unwrap_or(&r.samples[0]);
    println!("| method | dt (s) | steps | attitude error at t = {t_end} s (rad) | ns per step |");
    println!("|---|---|---|---|---|");
    for name in [
        "rk4",
        "strang",
        "splitting",
        "splitting4",
        "splitting6",
        "splitting8",
    ] {
        let m = method(name).unwrap_or_else(|e| panic!("{e}"));
        for steps_per_second in [10.0, 20.0, 60.0, 100.0, 1000.0] {
            let h = 1.0 / steps_per_second;
            let steps = (t_end * steps_per_second).round() as usize;
            let run = || {
                let mut s = PrincipalState {
                    world_from_principal: q0,
                    l_principal: l0,
                };
                integrate(m.as_ref(), r.moments, &mut s, h, steps)
                    .unwrap_or_else(|e| panic!("{e}"));
                s
            };
            let error = rotation_angle_between(run().world_from_principal, q_ref);
            // Median of five timed runs.
            let mut times: Vec<f64> = (0..5)
                .map(|_| {
                    let start = Instant::now();
                    black_box(run());
                    start.elapsed().as_secs_f64() * 1e9 / steps as f64
                })
                .collect();
            times.sort_by(f64::total_cmp);
            println!(
                "| {name} | 1/{steps_per_second} | {steps} | {error:.2e} | {:.0} |",
                times[2]
            );
        }
    }
}
