//! Mesh mass properties, kreisel against parry, measured so that a noisy
//! machine still gives a trustworthy ratio.
//!
//! ```text
//! # wall clock, interleaved: rounds alternate kreisel and parry on the same
//! # UV-sphere mesh; prints median ns per triangle and the median ratio
//! cargo run --release --example inertia_throughput -- ratio
//!
//! # a fixed workload for instruction counting (deterministic)
//! cargo build --release --example inertia_throughput
//! valgrind --tool=callgrind --callgrind-out-file=/dev/null \
//!     target/release/examples/inertia_throughput count kreisel 316
//! ```
//!
//! `count LIBRARY N` integrates an N-segment sphere (N² triangles) three
//! times with `kreisel`, `parry` or `none` (mesh generation only, to
//! subtract).

use std::hint::black_box;
use std::process::ExitCode;
use std::time::Instant;

use kreisel::inertia::{MeshMoments, TriMesh, to_parry};
use parry3d_f64::mass_properties::MassProperties as ParryMassProperties;

#[path = "../tests/common/shapes.rs"]
mod shapes;

/// Mass by kreisel.
fn kreisel_mass(mesh: &TriMesh) -> f64 {
    MeshMoments::solid(mesh).zeroth
}

/// Mass by parry (vertices converted outside the timed region).
fn parry_mass(points: &[parry3d_f64::math::Vector], mesh: &TriMesh) -> f64 {
    ParryMassProperties::from_trimesh(1.0, points, mesh.triangles()).mass()
}

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn ratio() -> ExitCode {
    println!("| triangles | kreisel ns/triangle | parry ns/triangle | parry/kreisel |");
    println!("|---|---|---|---|");
    for (segments, rounds) in [(32, 2000), (100, 200), (316, 40), (1000, 8), (2236, 4)] {
        let mesh = shapes::sphere(1.0, segments);
        let points: Vec<_> = mesh.vertices().iter().map(|&v| to_parry(v)).collect();
        let n = mesh.triangles().len() as f64;
        let time = |f: &dyn Fn() -> f64| {
            let start = Instant::now();
            black_box(f());
            start.elapsed().as_secs_f64() * 1e9 / n
        };
        let (mut k, mut p, mut r) = (Vec::new(), Vec::new(), Vec::new());
        for round in 0..rounds {
            // Alternate which goes first, so neither gains from order.
            let (tk, tp) = if round % 2 == 0 {
                let tk = time(&|| kreisel_mass(&mesh));
                (tk, time(&|| parry_mass(&points, &mesh)))
            } else {
                let tp = time(&|| parry_mass(&points, &mesh));
                (time(&|| kreisel_mass(&mesh)), tp)
            };
            k.push(tk);
            p.push(tp);
            r.push(tp / tk);
        }
        println!(
            "| {} | {:.2} | {:.1} | {:.1} |",
            mesh.triangles().len(),
            median(&mut k),
            median(&mut p),
            median(&mut r)
        );
    }
    ExitCode::SUCCESS
}

fn count(args: &[String]) -> ExitCode {
    let [library, segments] = args else {
        eprintln!("usage: inertia_throughput count kreisel|parry|none SEGMENTS");
        return ExitCode::FAILURE;
    };
    let Ok(segments) = segments.parse::<usize>() else {
        eprintln!("SEGMENTS must be a whole number");
        return ExitCode::FAILURE;
    };
    let mesh = shapes::sphere(1.0, segments);
    let points: Vec<_> = mesh.vertices().iter().map(|&v| to_parry(v)).collect();
    let mut sum = 0.0;
    for _ in 0..3 {
        sum += match library.as_str() {
            "kreisel" => kreisel_mass(black_box(&mesh)),
            "parry" => parry_mass(black_box(&points), &mesh),
            "none" => 0.0,
            _ => {
                eprintln!("unknown library");
                return ExitCode::FAILURE;
            }
        };
    }
    println!("{} triangles, checksum {sum}", mesh.triangles().len());
    ExitCode::SUCCESS
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        Some("ratio") => ratio(),
        Some("count") => count(&args[1..]),
        _ => {
            eprintln!("usage: inertia_throughput ratio | count LIBRARY SEGMENTS");
            ExitCode::FAILURE
        }
    }
}
