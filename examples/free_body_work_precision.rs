//! Work–precision of the free-body integrators on rapier's Dzhanibekov
//! scenario (I = (1, 2, 3), ω₀ = (0.01, 1, 0), 100 s): attitude error at
//! t = 100 s against the mpmath reference, and run time per step, for
//! every registered method (`kreisel::dynamics::FreeBodyMethod::ALL` except `auto`) and
//! for rapier3d-f64 (a dev-dependency, via `tests/common/rapier.rs`) over a
//! range of step sizes. Prints a Markdown table (used in BENCHMARKS.md)
//! and, with `--csv FILE`, writes the same numbers as CSV
//! (`method,dt,steps,error_rad,ns_per_step`) for
//! `benches/plot_work_precision.py`.
//!
//! ```text
//! cargo run --release --example free_body_work_precision -- --csv benches/work_precision.csv
//! python3 benches/plot_work_precision.py benches/work_precision.csv
//! ```
//!
//! Timing: interleaved rounds (every round times every point once, so a
//! busy spell of the machine spreads over all points), the median of
//! seven rounds reported. A kreisel run is the whole 100 s of one body
//! (its state is 7 numbers, so more bodies cost the same per body-step);
//! a point whose run takes over 2 s is timed once. A rapier run is 100
//! steps of a world of 1000 identical bodies (full `PhysicsWorld::step`
//! pipeline, one thread), divided by 100 000 body-steps; rapier's error
//! comes from a one-body world run over the whole 100 s.

use std::hint::black_box;
use std::io::Write;
use std::time::Instant;

use kreisel::dynamics::{FreeBodyMethod, PrincipalState, integrate};
use kreisel::kinematics::rotation_angle_between;

#[path = "../crates/dynamics/tests/common/free_body.rs"]
mod free_body;
#[path = "../tests/common/rapier.rs"]
mod rapier;

/// Steps per second of simulated time.
const STEPS_PER_SECOND: [f64; 5] = [10.0, 20.0, 60.0, 100.0, 1000.0];
/// Bodies in rapier's timing world.
const RAPIER_BODIES: usize = 1000;
/// Steps per timed run of rapier's world.
const RAPIER_TIMED_STEPS: usize = 100;
/// Timed rounds over all points (the median is reported).
const ROUNDS: usize = 7;
/// A point whose one run takes longer than this (s) is timed in the
/// first round only.
const SLOW_RUN: f64 = 2.0;

/// One point of the work–precision set.
struct Point {
    method: String,
    steps_per_second: f64,
    steps: usize,
    error: f64,
    /// One timed run, and the number of (body-)steps it takes.
    run: Box<dyn FnMut()>,
    per: f64,
    slow: bool,
    times_ns: Vec<f64>,
}

fn main() {
    let mut args = std::env::args().skip(1);
    let mut csv_path = None;
    while let Some(arg) = args.next() {
        match arg.as_str() {
            "--csv" => csv_path = Some(args.next().expect("--csv FILE")),
            _ => panic!("unknown argument {arg}; usage: free_body_work_precision [--csv FILE]"),
        }
    }

    let r = free_body::load("rapier");
    let (_, q0, l0) = r.samples[0];
    let &(t_end, q_ref, _) = r.samples.last().unwrap_or(&r.samples[0]);
    let moments = r.moments;
    let mut points = Vec::new();
    // Errors (one untimed run per point, which also warms up).
    for method in FreeBodyMethod::ALL
        .into_iter()
        .filter(|&m| m != FreeBodyMethod::Auto)
    {
        let (name, m) = (method.name(), method.integrator());
        for steps_per_second in STEPS_PER_SECOND {
            let h = 1.0 / steps_per_second;
            let steps = (t_end * steps_per_second).round() as usize;
            let run = move || {
                let mut s = PrincipalState {
                    world_from_principal: q0,
                    l_principal: l0,
                };
                integrate(m, moments, &mut s, h, steps).unwrap_or_else(|e| panic!("{e}"));
                s
            };
            let start = Instant::now();
            let error = rotation_angle_between(run().world_from_principal, q_ref);
            points.push(Point {
                method: name.to_owned(),
                steps_per_second,
                steps,
                error,
                slow: start.elapsed().as_secs_f64() > SLOW_RUN,
                run: Box::new(move || {
                    black_box(run());
                }),
                per: steps as f64,
                times_ns: Vec::new(),
            });
        }
    }
    for steps_per_second in STEPS_PER_SECOND {
        let h = 1.0 / steps_per_second;
        let steps = (t_end * steps_per_second).round() as usize;
        let mut one = rapier::RapierBodies::single(moments, q0, l0, h);
        one.steps(steps);
        let error = rotation_angle_between(one.attitude(0), q_ref);
        let mut world = rapier::RapierBodies::new(moments, q0, l0, h, RAPIER_BODIES);
        world.steps(RAPIER_TIMED_STEPS);
        points.push(Point {
            method: "rapier".to_owned(),
            steps_per_second,
            steps,
            error,
            slow: false,
            run: Box::new(move || {
                world.steps(RAPIER_TIMED_STEPS);
                black_box(world.attitude(0));
            }),
            per: (RAPIER_TIMED_STEPS * RAPIER_BODIES) as f64,
            times_ns: Vec::new(),
        });
    }
    // Timings, interleaved: every round times every point once, so that
    // a slow spell of the machine spreads over all points.
    for round in 0..ROUNDS {
        for p in points.iter_mut().filter(|p| round == 0 || !p.slow) {
            let start = Instant::now();
            (p.run)();
            p.times_ns.push(start.elapsed().as_secs_f64() * 1e9 / p.per);
        }
    }
    let median = |p: &Point| {
        let mut t = p.times_ns.clone();
        t.sort_by(f64::total_cmp);
        t[t.len() / 2]
    };

    println!("| method | dt (s) | steps | attitude error at t = {t_end} s (rad) | ns per step |");
    println!("|---|---|---|---|---|");
    for p in &points {
        println!(
            "| {} | 1/{} | {} | {:.2e} | {:.0} |",
            p.method,
            p.steps_per_second,
            p.steps,
            p.error,
            median(p)
        );
    }
    if let Some(path) = csv_path {
        let mut out = std::io::BufWriter::new(
            std::fs::File::create(&path).unwrap_or_else(|e| panic!("{path}: {e}")),
        );
        writeln!(out, "method,dt,steps,error_rad,ns_per_step").unwrap();
        for p in &points {
            writeln!(
                out,
                "{},{},{},{:e},{:.1}",
                p.method,
                1.0 / p.steps_per_second,
                p.steps,
                p.error,
                median(p)
            )
            .unwrap();
        }
        out.flush().unwrap();
        eprintln!("wrote {path}");
    }
}
