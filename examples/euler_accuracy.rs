//! How accurately do kreisel, glam and nalgebra recover Euler angles next to
//! gimbal lock? Prints a Markdown table (used in `BENCHMARKS.md`).
//!
//! ```text
//! cargo run --release --example euler_accuracy
//! ```
//!
//! For every one of the 24 conventions, rotations are built from angles
//! `(α, lock ± δ, γ)` with random α, γ; each library turns the quaternion
//! back into angles, and the error is the angle of the rotation between the
//! input and the rotation recomposed from those angles (recomposed with
//! kreisel's `to_quat`, which agrees with 50-digit mpmath to 5e-16 rad, see
//! `tests/euler_reference.rs`).

use std::f64::consts::PI;
use std::panic;

use glam::{DQuat, DVec3};

#[path = "support/glam_euler.rs"]
mod glam_euler;
use glam_euler::glam_rot;
use kreisel::kinematics::{EulerSequence, Frame, rotation_angle_between};
use nalgebra::{Quaternion, Rotation3, Unit, UnitQuaternion, Vector3};

fn kreisel_angles(seq: EulerSequence, q: DQuat) -> Option<DVec3> {
    Some(seq.from_quat(q).angles)
}

fn glam_angles(seq: EulerSequence, q: DQuat) -> Option<DVec3> {
    let (a, b, c) = q.to_euler(glam_rot(seq));
    Some(DVec3::new(a, b, c))
}

/// nalgebra's general `euler_angles_ordered` (Shuster & Markley 2006);
/// `None` when it panics.
fn nalgebra_angles(seq: EulerSequence, q: DQuat) -> Option<DVec3> {
    let axes = seq.axes().map(|a| {
        let u = a.unit();
        Unit::new_unchecked(Vector3::new(u.x, u.y, u.z))
    });
    let rot: Rotation3<f64> =
        UnitQuaternion::new_unchecked(Quaternion::new(q.w, q.x, q.y, q.z)).to_rotation_matrix();
    let extrinsic = seq.frame() == Frame::Extrinsic;
    panic::catch_unwind(|| rot.euler_angles_ordered(axes, extrinsic))
        .ok()
        .map(|(a, _)| DVec3::new(a[0], a[1], a[2]))
}

/// Deterministic uniform numbers in [0, 1).
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

type Method = fn(EulerSequence, DQuat) -> Option<DVec3>;

/// Worst error (rad) and count of failures (NaN or panic) at distance `delta` from the lock.
fn worst(method: Method, delta: f64, proper_only: Option<bool>) -> (f64, usize) {
    let mut rng = Lcg(12345);
    let (mut worst, mut failed) = (0.0_f64, 0);
    for seq in EulerSequence::all() {
        if proper_only.is_some_and(|p| p != seq.is_proper()) {
            continue;
        }
        for (which, lock) in seq.gimbal_lock_angles().into_iter().enumerate() {
            let inward = if which == 0 { 1.0 } else { -1.0 };
            for _ in 0..100 {
                let a = (rng.next() * 2.0 - 1.0) * PI;
                let c = (rng.next() * 2.0 - 1.0) * PI;
                let q = seq.to_quat(DVec3::new(a, lock + inward * delta, c));
                match method(seq, q) {
                    Some(angles) if angles.is_finite() => {
                        worst = worst.max(rotation_angle_between(q, seq.to_quat(angles)));
                    }
                    _ => failed += 1,
                }
            }
        }
    }
    (worst, failed)
}

fn main() {
    panic::set_hook(Box::new(|_| {}));
    let deltas = [1e-3, 1e-5, 1e-7, 1e-9, 1e-12, 0.0];
    let methods: [(&str, Method); 3] = [
        ("kreisel", kreisel_angles),
        ("glam 0.34 `to_euler`", glam_angles),
        ("nalgebra 0.35 `euler_angles_ordered`", nalgebra_angles),
    ];
    print!("| library | sequences |");
    for d in deltas {
        if d == 0.0 {
            print!(" at the lock |");
        } else {
            print!(" δ = {d:e} |");
        }
    }
    println!();
    println!("|---|---|{}", "---|".repeat(deltas.len()));
    for (name, method) in methods {
        for (kind, proper) in [("Tait–Bryan", false), ("proper Euler", true)] {
            print!("| {name} | {kind} |");
            for d in deltas {
                let (w, failed) = worst(method, d, Some(proper));
                if failed > 0 {
                    print!(" {w:.1e} ({failed} NaN/panic) |");
                } else {
                    print!(" {w:.1e} |");
                }
            }
            println!();
        }
    }
}
