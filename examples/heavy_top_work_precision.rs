//! Work–precision of the heavy-top integrators on the fast tops of
//! `tests/data/heavy_top/` (the Bruls–Cardona–Arnold benchmark and an
//! asymmetric top with its centre of mass off the principal axes, both
//! spinning at 150 rad/s, 2 s): the largest attitude error over the
//! reference samples (every 0.01 s) and the run time per step, for every
//! method of `kreisel::dynamics::HeavyTopMethod::ALL`, the Taylor series
//! (`HeavyTopTaylor::DEFAULT`, `taylor`) and, on the Lagrange top `bruls`,
//! the closed form (`HeavyTopClosedForm`, `closed_form`: built once, then
//! one `state_at` per step; its time per 2 s includes the set-up) over a
//! range of step sizes. Prints a Markdown table (used in BENCHMARKS.md)
//! and, with `--csv FILE`, writes `scenario,method,dt,error_rad,ns_per_step`.
//!
//! ```text
//! cargo run --release --example heavy_top_work_precision -- --csv benches/heavy_top_work_precision.csv
//! ```
//!
//! Timing: interleaved rounds (every round times every point once), the
//! median of eleven rounds; a run is the whole 2 s of one top.

use std::hint::black_box;
use std::io::Write;
use std::time::Instant;

use kreisel::dynamics::{HeavyTopClosedForm, HeavyTopIntegrator, HeavyTopMethod, HeavyTopTaylor};

#[path = "../crates/dynamics/tests/common/heavy_top.rs"]
mod heavy_top;

/// Step sizes, s (each divides the 0.01 s sample interval). The closed
/// form, evaluated at any t, also runs at 1/60 s, the game-loop frame.
const STEPS: [f64; 6] = [1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4];
/// Timed rounds over all points (the median is reported).
const ROUNDS: usize = 11;

/// How a point moves its top.
#[derive(Clone, Copy)]
enum Mover {
    /// A registered method, stepped.
    Method(HeavyTopMethod),
    /// `HeavyTopTaylor::DEFAULT`, stepped.
    Taylor,
    /// `HeavyTopClosedForm`: built once, evaluated every step.
    ClosedForm,
}

impl Mover {
    fn name(self) -> &'static str {
        match self {
            Mover::Method(method) => method.name(),
            Mover::Taylor => "taylor",
            Mover::ClosedForm => "closed_form",
        }
    }

    /// The whole run of `steps` steps of `dt` from the start; `visit(k, state)`
    /// after every step.
    fn run(
        self,
        r: &heavy_top::HeavyTopReference,
        dt: f64,
        steps: usize,
        mut visit: impl FnMut(usize, &kreisel::dynamics::PrincipalState),
    ) {
        let stepped = |m: &dyn HeavyTopIntegrator, visit: &mut dyn FnMut(usize, &_)| {
            let mut s = r.start;
            for k in 1..=steps {
                m.step(&r.top, black_box(&mut s), dt);
                visit(k, &s);
            }
        };
        match self {
            Mover::Method(method) => stepped(method.integrator(), &mut visit),
            Mover::Taylor => stepped(&HeavyTopTaylor::DEFAULT, &mut visit),
            Mover::ClosedForm => {
                let closed = HeavyTopClosedForm::try_new(&r.top, black_box(r.start))
                    .expect("a Lagrange top");
                for k in 1..=steps {
                    visit(k, &closed.state_at(black_box(k as f64 * dt)));
                }
            }
        }
    }
}

/// One point of the set.
struct Point {
    scenario: &'static str,
    mover: Mover,
    dt: f64,
    steps: usize,
    error: f64,
    times_ns: Vec<f64>,
}

/// The largest attitude error over the samples the steps land on.
fn error(r: &heavy_top::HeavyTopReference, mover: Mover, dt: f64, steps: usize) -> f64 {
    let interval = r.samples[1].0 - r.samples[0].0;
    let mut worst: f64 = 0.0;
    mover.run(r, dt, steps, |k, s| {
        let t = k as f64 * dt;
        let sample = (t / interval).round();
        if (sample * interval - t).abs() < 1e-9 * interval {
            worst = worst.max(r.attitude_error(s, sample as usize));
        }
    });
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
        let mut movers: Vec<Mover> = HeavyTopMethod::ALL.into_iter().map(Mover::Method).collect();
        movers.push(Mover::Taylor);
        if r.top.symmetry_axis().is_some() {
            movers.push(Mover::ClosedForm);
        }
        for mover in movers {
            let mut steps_list = STEPS.to_vec();
            if matches!(mover, Mover::ClosedForm) {
                steps_list.insert(0, 1.0 / 60.0);
            }
            for dt in steps_list {
                let steps = (duration / dt).round() as usize;
                points.push(Point {
                    scenario,
                    mover,
                    dt,
                    steps,
                    error: error(r, mover, dt, steps),
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
            let start = Instant::now();
            p.mover.run(r, p.dt, p.steps, |_, s| {
                black_box(s);
            });
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
        let dt = if (p.dt - 1.0 / 60.0).abs() < 1e-15 {
            "1/60".to_owned()
        } else {
            format!("{:e}", p.dt)
        };
        println!(
            "| {} | {} | {dt} | {:.1e} | {:.0} | {:.3} |",
            p.scenario,
            p.mover.name(),
            p.error,
            ns,
            ns * p.steps as f64 * 1e-6
        );
        rows.push(format!(
            "{},{},{:e},{:e},{:.1}",
            p.scenario,
            p.mover.name(),
            p.dt,
            p.error,
            ns
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
