//! Quaternion ⇄ Euler conversion speed: kreisel against glam's
//! `to_euler`/`from_euler` and nalgebra's `euler_angles`/`from_euler_angles`,
//! measured in one run on the same inputs.
//!
//! Run with `cargo bench --bench kinematics`; the numbers are reported in
//! `BENCHMARKS.md`. Each iteration converts a batch of `N` rotations, so the
//! time per conversion is the reported time divided by `N` (criterion's
//! throughput line shows elements/s).

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use glam::{DQuat, DVec3};
use kreisel::kinematics::EulerSequence;
use nalgebra::{Quaternion, UnitQuaternion};

#[path = "../examples/support/glam_euler.rs"]
mod glam_euler;
use glam_euler::glam_rot;

const N: usize = 1024;

/// Deterministic, well-spread unit quaternions (a tiny LCG: no rand dependency).
fn quats() -> Vec<DQuat> {
    let mut s: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut next = || {
        s = s
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (s >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    (0..N)
        .map(|_| DQuat::from_xyzw(next(), next(), next(), next()).normalize())
        .collect()
}

/// The conventions compared (glam's equivalent from `glam_rot`).
const CONVENTIONS: [&str; 4] = ["XYZ", "ZXZ", "xyz", "zxz"];

fn quat_to_euler(c: &mut Criterion) {
    let qs = quats();
    let mut group = c.benchmark_group("quat_to_euler");
    group.throughput(Throughput::Elements(N as u64));
    for name in CONVENTIONS {
        let seq: EulerSequence = name.parse().unwrap();
        let rot = glam_rot(seq);
        group.bench_function(format!("kreisel/{name}"), |b| {
            b.iter(|| {
                let mut acc = DVec3::ZERO;
                for &q in black_box(&qs) {
                    acc += seq.from_quat(q).angles;
                }
                acc
            })
        });
        group.bench_function(format!("glam/{name}"), |b| {
            b.iter(|| {
                let mut acc = DVec3::ZERO;
                for &q in black_box(&qs) {
                    let (x, y, z) = q.to_euler(rot);
                    acc += DVec3::new(x, y, z);
                }
                acc
            })
        });
    }
    // nalgebra offers extrinsic xyz (roll, pitch, yaw) on quaternions.
    let nq: Vec<UnitQuaternion<f64>> = qs
        .iter()
        .map(|q| UnitQuaternion::new_unchecked(Quaternion::new(q.w, q.x, q.y, q.z)))
        .collect();
    group.bench_function("nalgebra/xyz", |b| {
        b.iter(|| {
            let mut acc = DVec3::ZERO;
            for q in black_box(&nq) {
                let (x, y, z) = q.euler_angles();
                acc += DVec3::new(x, y, z);
            }
            acc
        })
    });
    group.finish();
}

fn euler_to_quat(c: &mut Criterion) {
    let angles: Vec<DVec3> = quats()
        .iter()
        .map(|q| DVec3::new(q.x, q.y, q.z) * 3.0)
        .collect();
    let mut group = c.benchmark_group("euler_to_quat");
    group.throughput(Throughput::Elements(N as u64));
    for name in CONVENTIONS {
        let seq: EulerSequence = name.parse().unwrap();
        let rot = glam_rot(seq);
        group.bench_function(format!("kreisel/{name}"), |b| {
            b.iter(|| {
                let mut acc = DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0);
                for &a in black_box(&angles) {
                    acc += seq.to_quat(a);
                }
                acc
            })
        });
        group.bench_function(format!("glam/{name}"), |b| {
            b.iter(|| {
                let mut acc = DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0);
                for &a in black_box(&angles) {
                    acc += DQuat::from_euler(rot, a.x, a.y, a.z);
                }
                acc
            })
        });
    }
    group.bench_function("nalgebra/xyz", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for &a in black_box(&angles) {
                acc += UnitQuaternion::from_euler_angles(a.x, a.y, a.z).w;
            }
            acc
        })
    });
    group.finish();
}

criterion_group!(benches, quat_to_euler, euler_to_quat);
criterion_main!(benches);
