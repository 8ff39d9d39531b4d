//! Kreisel against glam on Euler conversions, measured so that a noisy
//! machine still gives a trustworthy ratio.
//!
//! Two modes:
//!
//! ```text
//! # wall clock, interleaved: 400 rounds, each times a 1024-rotation batch with
//! # kreisel and with glam (alternating which goes first); prints median ns per conversion and the
//! # median of the per-round ratios kreisel/glam
//! cargo run --release --example euler_throughput -- ratio
//!
//! # a fixed workload for instruction counting (deterministic)
//! cargo build --release --example euler_throughput
//! valgrind --tool=callgrind --callgrind-out-file=/dev/null \
//!     target/release/examples/euler_throughput count kreisel to-euler XYZ 100000
//! ```
//!
//! `count` takes `kreisel|glam|none` (`none`: only the input generation, to
//! subtract), `to-euler|to-quat`, a convention (`XYZ`, `zxz`, … as in
//! scipy) and the number of conversions, and prints a checksum so that the
//! work cannot be optimised away.

use std::hint::black_box;
use std::process::ExitCode;
use std::time::Instant;

use glam::{DQuat, DVec3};

#[path = "support/glam_euler.rs"]
mod glam_euler;
use glam_euler::glam_rot;
use kreisel::kinematics::EulerSequence;

/// Smoothly varying angles covering the whole range.
fn angles(i: u64) -> DVec3 {
    let t = i as f64 * 1e-4;
    DVec3::new(t.sin() * 3.0, t.cos() * 0.7, (2.0 * t).sin() * 3.0)
}

/// Sums `f` over `n` generated inputs (the closure is inlined into the loop).
fn run(n: u64, f: impl Fn(DQuat, DVec3) -> f64) -> f64 {
    let mut sum = 0.0;
    for i in 0..n {
        let a = black_box(angles(i));
        let q = DQuat::from_xyzw(a.x, a.y, a.z, 1.0).normalize();
        sum += f(q, a);
    }
    sum
}

fn count(args: &[String]) -> ExitCode {
    let [library, direction, seq, n] = args else {
        eprintln!("usage: euler_throughput count kreisel|glam|none to-euler|to-quat SEQ N");
        return ExitCode::FAILURE;
    };
    let (Ok(seq), Ok(n)) = (seq.parse::<EulerSequence>(), n.parse::<u64>()) else {
        eprintln!("bad convention or count");
        return ExitCode::FAILURE;
    };
    let rot = glam_rot(seq);
    let sum = match (library.as_str(), direction.as_str()) {
        ("kreisel", "to-euler") => run(n, |q, _| seq.from_quat(q).angles.x),
        ("glam", "to-euler") => run(n, |q, _| q.to_euler(rot).0),
        ("kreisel", "to-quat") => run(n, |_, a| seq.to_quat(a).w),
        ("glam", "to-quat") => run(n, |_, a| DQuat::from_euler(rot, a.x, a.y, a.z).w),
        ("none", _) => run(n, |q, a| a.x + q.w),
        _ => {
            eprintln!("unknown library or direction");
            return ExitCode::FAILURE;
        }
    };
    println!("checksum {sum}");
    ExitCode::SUCCESS
}

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn ratio() -> ExitCode {
    const BATCH: usize = 1024;
    const ROUNDS: usize = 400;
    println!("| conversion | convention | kreisel ns | glam ns | kreisel/glam |");
    println!("|---|---|---|---|---|");
    for direction in ["to-euler", "to-quat"] {
        for name in ["XYZ", "ZXZ", "xyz", "zxz"] {
            let Ok(seq) = name.parse::<EulerSequence>() else {
                return ExitCode::FAILURE;
            };
            let rot = glam_rot(seq);
            // Pre-computed inputs: each batch times only the conversions.
            let inputs: Vec<(DQuat, DVec3)> = (0..BATCH as u64)
                .map(|i| {
                    let a = angles(i * 37);
                    (DQuat::from_xyzw(a.x, a.y, a.z, 1.0).normalize(), a)
                })
                .collect();
            let time = |library: &str| {
                let start = Instant::now();
                let mut sum = 0.0;
                for &(q, a) in black_box(&inputs) {
                    sum += match (library, direction) {
                        ("kreisel", "to-euler") => seq.from_quat(q).angles.x,
                        ("glam", "to-euler") => q.to_euler(rot).0,
                        ("kreisel", _) => seq.to_quat(a).w,
                        _ => DQuat::from_euler(rot, a.x, a.y, a.z).w,
                    };
                }
                black_box(sum);
                start.elapsed().as_secs_f64() * 1e9 / BATCH as f64
            };
            let (mut k, mut g, mut r) = (Vec::new(), Vec::new(), Vec::new());
            for round in 0..ROUNDS {
                // Alternate which library goes first, so neither gains from order.
                let (tk, tg) = if round % 2 == 0 {
                    let tk = time("kreisel");
                    (tk, time("glam"))
                } else {
                    let tg = time("glam");
                    (time("kreisel"), tg)
                };
                k.push(tk);
                g.push(tg);
                r.push(tk / tg);
            }
            println!(
                "| {direction} | {name} | {:.1} | {:.1} | {:.2} |",
                median(&mut k),
                median(&mut g),
                median(&mut r)
            );
        }
    }
    ExitCode::SUCCESS
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        Some("ratio") => ratio(),
        Some("count") => count(&args[1..]),
        _ => {
            eprintln!("usage: euler_throughput ratio | count LIBRARY DIRECTION SEQ N");
            ExitCode::FAILURE
        }
    }
}
