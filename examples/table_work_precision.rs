//! Work–precision of the nonsmooth table (`TableMotion`, issue 26): for
//! each tolerance, the evaluations of the vector field, the wall time and
//! the error of
//!
//! - `ball`: a ball dropped from 1 m with e = 0.9 — the largest error of
//!   its first 20 impact times against the closed form, and of its
//!   accumulation point (the Zeno time);
//! - `tippe_top_one_contact`: Leine & Glocker's tippe top with its stem,
//!   at 1.2 s (one contact, slipping: between events) — the state's
//!   distance from a run at rtol 1e-13;
//! - `tippe_top_through_impact`: the same top at 2.0 s, after the stem's
//!   plastic landing and the ball's lift-off (through events) — the
//!   landing time's error and the state's distance from the 1e-13 run.
//!
//! Distances: positions over R, velocities over R ω₀, attitude, L over
//! |L₀| (`crates/dynamics/tests/common/tippe_top.rs::flat`). Prints a Markdown table
//! (BENCHMARKS.md) and, with `--csv FILE`, writes
//! `problem,rtol,evaluations,error,time_error_s,wall_ms`.
//!
//! ```text
//! cargo run --release --example table_work_precision -- --csv benches/table_work_precision.csv
//! ```

use std::io::Write;
use std::time::Instant;

use kreisel::dynamics::{TableEventKind, TableMotion};

#[allow(dead_code)]
#[path = "../crates/dynamics/tests/common/tippe_top.rs"]
mod tippe_top;

use tippe_top::{contensou_law, distance, flat, table_motion};

#[allow(dead_code)]
#[path = "../crates/dynamics/tests/common/bouncing_ball.rs"]
mod bouncing_ball;

use bouncing_ball::dropped_ball;

#[allow(dead_code)]
#[path = "../crates/dynamics/tests/common/euler_disk.rs"]
mod euler_disk;

/// Euler's disk (μ = 5, the air layer's floor 1e-5 a) from its steady
/// rolling at 0.2 rad to 4 s, past 700 turns of its precession: its tilt's
/// sine there.
fn euler_disk(rtol: f64) -> (f64, usize, f64) {
    let clock = Instant::now();
    let mut run = euler_disk::rolling_disk(5.0, 1e-5 * euler_disk::A, 0.2, rtol);
    run.try_advance_to(4.0).unwrap();
    let n = run.state().world_from_body.normalize() * glam::DVec3::Z;
    let wall_ms = clock.elapsed().as_secs_f64() * 1e3;
    (
        glam::DVec3::Z.cross(n).length(),
        run.stats().evaluations,
        wall_ms,
    )
}

/// Tolerances (rtol = atol).
const TOLERANCES: [f64; 7] = [1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12];

/// One measured point.
struct Point {
    problem: &'static str,
    rtol: f64,
    evaluations: usize,
    error: f64,
    time_error: f64,
    wall_ms: f64,
}

/// The ball's run to 10 s: its impacts' and accumulation point's error.
fn ball(rtol: f64) -> Point {
    let (g, r, e) = (bouncing_ball::G, bouncing_ball::R, bouncing_ball::E);
    let clock = Instant::now();
    let mut run = dropped_ball(rtol);
    run.try_advance_to(10.0).unwrap();
    let wall_ms = clock.elapsed().as_secs_f64() * 1e3;
    let d = 1.0 - r;
    let (t1, v1) = ((2.0 * d / g).sqrt(), (2.0 * g * d).sqrt());
    let mut expected = t1;
    let mut worst: f64 = 0.0;
    let impacts = run
        .events()
        .iter()
        .filter(|ev| matches!(ev.kind, TableEventKind::Impact { .. }));
    for (n, ev) in impacts.take(20).enumerate() {
        worst = worst.max((ev.time - expected).abs());
        expected += 2.0 * e.powi(n as i32 + 1) * v1 / g;
    }
    let zeno = t1 + 2.0 * e * v1 / (g * (1.0 - e));
    let accumulation = run.events().iter().find_map(|ev| match ev.kind {
        TableEventKind::ImpactsAccumulate { accumulation_time } => Some(accumulation_time),
        _ => None,
    });
    Point {
        problem: "ball",
        rtol,
        evaluations: run.stats().evaluations,
        error: worst,
        time_error: accumulation.map_or(f64::NAN, |t| (t - zeno).abs()),
        wall_ms,
    }
}

/// The tippe top's state at `t` and its stem's landing time.
fn tippe_top(rtol: f64, t: f64) -> (TableMotion, f64) {
    let clock = Instant::now();
    let mut run = table_motion(contensou_law(), rtol);
    run.try_advance_to(t).unwrap();
    (run, clock.elapsed().as_secs_f64() * 1e3)
}

fn landing(run: &TableMotion) -> f64 {
    run.events()
        .iter()
        .find(|e| e.contact == Some(1) && matches!(e.kind, TableEventKind::Impact { .. }))
        .map_or(f64::NAN, |e| e.time)
}

fn main() {
    let csv = std::env::args().skip_while(|a| a != "--csv").nth(1);
    let l0 = table_motion(contensou_law(), 1e-13)
        .state()
        .l_world
        .length();
    let reference_12 = tippe_top(1e-13, 1.2).0;
    let reference_20 = tippe_top(1e-13, 2.0).0;
    let disk_reference = euler_disk(1e-13).0;
    let mut points = Vec::new();
    for &rtol in &TOLERANCES {
        let (tilt, evaluations, wall_ms) = euler_disk(rtol);
        points.push(Point {
            problem: "euler_disk",
            rtol,
            evaluations,
            error: (tilt - disk_reference).abs(),
            time_error: f64::NAN,
            wall_ms,
        });
        points.push(ball(rtol));
        let (run, wall_ms) = tippe_top(rtol, 1.2);
        points.push(Point {
            problem: "tippe_top_one_contact",
            rtol,
            evaluations: run.stats().evaluations,
            error: distance(&flat(run.state(), l0), &flat(reference_12.state(), l0)),
            time_error: f64::NAN,
            wall_ms,
        });
        let (run, wall_ms) = tippe_top(rtol, 2.0);
        points.push(Point {
            problem: "tippe_top_through_impact",
            rtol,
            evaluations: run.stats().evaluations,
            error: distance(&flat(run.state(), l0), &flat(reference_20.state(), l0)),
            time_error: (landing(&run) - landing(&reference_20)).abs(),
            wall_ms,
        });
    }
    println!("| problem | rtol | evaluations | error | time error (s) | wall (ms) |");
    println!("|---|---|---|---|---|---|");
    for p in &points {
        println!(
            "| {} | {:.0e} | {} | {:.2e} | {:.2e} | {:.2} |",
            p.problem, p.rtol, p.evaluations, p.error, p.time_error, p.wall_ms
        );
    }
    if let Some(path) = csv {
        let mut text = String::from("problem,rtol,evaluations,error,time_error_s,wall_ms\n");
        for p in &points {
            text += &format!(
                "{},{:e},{},{:e},{:e},{}\n",
                p.problem, p.rtol, p.evaluations, p.error, p.time_error, p.wall_ms
            );
        }
        let tmp = format!("{path}.tmp");
        std::fs::File::create(&tmp)
            .and_then(|mut f| f.write_all(text.as_bytes()))
            .and_then(|()| std::fs::rename(&tmp, &path))
            .unwrap_or_else(|e| panic!("cannot write {path}: {e}"));
    }
}
