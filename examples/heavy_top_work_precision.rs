//! Work–precision of the heavy-top integrators on the fast tops of
//! `tests/data/heavy_top/` (the Bruls–Cardona–Arnold benchmark and an
//! asymmetric top with its centre of mass off the principal axes, both
//! spinning at 150 rad/s, 2 s): the largest attitude error over the
//! reference samples (every 0.01 s) and the run time per step, for every
//! method of `kreisel::dynamics::HEAVY_TOP_METHODS` over a range of step
//! sizes. Prints a Markdown table (used in BENCHMARKS.md) and, with
//! `--csv FILE`, writes `scenario,method,dt,error_rad,ns_per_step`.
//!
//! ```text
//! cargo run --release --example heavy_top_work_precision -- --csv benches/heavy_top_work_precision.csv
//! ```
//!
//! Timing: interleaved rounds (every round times every point once), the
//! median of five rounds; a run is the whole 2 s of one top.

use std::hint::black_box;
use std::io::Write;
use std::time::Instant;

use kreisel::dynamics::{HEAVY_TOP_METHODS, heavy_top_method};

#[path = "../tests/common/heavy_top.rs"]
mod heavy_top;

/// Step sizes, s (each divides the 0.01 s sample interval).
const STEPS: [f64; 6] = [1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4];
/// Timed rounds over all points (the median is reported).
const ROUNDS: usize = 5;

/// One point of the set.
struct Point {
    scenario: &'static str,
    method: &'static str,
    dt: f64,
    steps: usize,
    error: f64,
    times_ns: Vec<f64>,
}

/// Runs `method` over the reference with step `dt`; the largest attitude
/// error over the samples.
fn error(r: &heavy_top::HeavyTopReference, method: &str, dt: f64) -> f64 {
    let m = heavy_top_method(method).expect("registered");
    let interval = r.samples[1].0 - r.samples[0].0;
    let per_sample = (interval / dt).round() as usize;
    let mut s = r.start;
    let mut worst: f64 = 0.0;
    for k in 1..r.samples.len() {
        for _ in 0..per_sample {
            m.step(&r.top, &mut s, dt);
        }
        worst = worst.max(r.attitude_error(&s, k));
    }
    worst
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let csv = args
        .iter()
        .position(|a| a == "--csv")
        .and_then(|i| args.get(i + 1));
    let scenarios = ["bruls", "asymmetric_fast"];
    let references: Vec<_> = scenarios.iter().map(|n| heavy_top::load(n)).collect();
    let mut points = Vec::new();
    for (scenario, r) in scenarios.iter().zip(&references) {
        let duration = r.samples.last().expect("samples").0;
        for method in HEAVY_TOP_METHODS {
            for dt in STEPS {
                points.push(Point {
                    scenario,
                    method,
                    dt,
                    steps: (duration / dt).round() as usize,
                    error: error(r, method, dt),
                    times_ns: Vec::new(),
                });
            }
        }
    }
    for _ in 0..ROUNDS {
        for p in &mut points {
            let r = &references[scenarios
                .iter()
                .position(|s| *s == p.scenario)
                .expect("known")];
            let m = heavy_top_method(p.method).expect("registered");
            let mut s = r.start;
            let start = Instant::now();
            for _ in 0..p.steps {
                m.step(&r.top, black_box(&mut s), p.dt);
            }
            black_box(s);
            p.times_ns
                .push(start.elapsed().as_nanos() as f64 / p.steps as f64);
        }
    }
    println!("| top | method | dt (s) | max attitude error (rad) | ns/step | ms per 2 s |");
    println!("|---|---|---|---|---|---|");
    let mut rows = Vec::new();
    for p in &mut points {
        p.times_ns.sort_by(f64::total_cmp);
        let ns = p.times_ns[ROUNDS / 2];
        println!(
            "| {} | {} | {:e} | {:.1e} | {:.0} | {:.2} |",
            p.scenario,
            p.method,
            p.dt,
            p.error,
            ns,
            ns * p.steps as f64 * 1e-6
        );
        rows.push(format!(
            "{},{},{:e},{:e},{:.1}",
            p.scenario, p.method, p.dt, p.error, ns
        ));
    }
    if let Some(path) = csv {
        let mut f = std::fs::File::create(path).expect("create the CSV");
        writeln!(f, "scenario,method,dt,error_rad,ns_per_step").expect("write");
        for row in rows {
            writeln!(f, "{row}").expect("write");
        }
    }
}
