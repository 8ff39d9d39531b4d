//! The Euler conversions of `kreisel-kinematics` against committed reference
//! data from scipy 1.17 and 50-digit mpmath (`tests/data/gen/rotations.py`).
//!
//! Regenerate the data with
//! `pip install -r tests/data/gen/requirements.txt && python3 tests/data/gen/rotations.py`.

mod common;

use common::{Table, angle_difference};
use kreisel::kinematics::{EulerSequence, rotation_angle_between};

/// Worst case allowed anywhere (issue #2): 1e-14 rad.
const WORST: f64 = 1e-14;
/// Typical (root-mean-square) error allowed: 1e-15 rad.
const TYPICAL: f64 = 1e-15;

struct Stats {
    max: f64,
    sum_sq: f64,
    n: usize,
}

impl Stats {
    fn new() -> Self {
        Stats {
            max: 0.0,
            sum_sq: 0.0,
            n: 0,
        }
    }
    fn add(&mut self, e: f64) {
        self.max = self.max.max(e);
        self.sum_sq += e * e;
        self.n += 1;
    }
    fn rms(&self) -> f64 {
        (self.sum_sq / self.n as f64).sqrt()
    }
    fn check(&self, what: &str) {
        eprintln!(
            "{what}: {} rows, max {:e} rad, rms {:e} rad",
            self.n,
            self.max,
            self.rms()
        );
        assert!(self.n > 0, "{what}: no rows");
        assert!(
            self.max <= WORST,
            "{what}: max error {:e} > {WORST:e}",
            self.max
        );
        assert!(
            self.rms() <= TYPICAL,
            "{what}: rms error {:e} > {TYPICAL:e}",
            self.rms()
        );
    }
}

#[test]
fn quat_to_euler_matches_exact_angles_on_random_rotations() {
    let t = Table::load("quat_to_euler.csv");
    let mut angles = Stats::new();
    let mut recomposed = Stats::new();
    for row in t.rows.iter().filter(|r| t.text(r, "case") == "random") {
        let seq: EulerSequence = t.text(row, "seq").parse().unwrap();
        let q = t.quat(row);
        let found = seq.from_quat(q);
        assert!(!found.gimbal_lock);
        let expect = t.vec3(row, ["a0", "a1", "a2"]);
        for k in 0..3 {
            angles.add(angle_difference(found.angles[k], expect[k]).abs());
        }
        recomposed.add(rotation_angle_between(q, seq.to_quat(found.angles)));
    }
    angles.check("random quat→euler, angles vs mpmath");
    recomposed.check("random quat→euler, recomposed rotation");
}

#[test]
fn quat_to_euler_near_and_at_gimbal_lock() {
    let t = Table::load("quat_to_euler.csv");
    let mut middle = Stats::new();
    let mut recomposed = Stats::new();
    let mut scipy_worst: f64 = 0.0;
    let mut locked = 0;
    for row in t.rows.iter().filter(|r| t.text(r, "case") != "random") {
        let seq: EulerSequence = t.text(row, "seq").parse().unwrap();
        let q = t.quat(row);
        let found = seq.from_quat(q);
        // The middle angle is well conditioned even at the lock.
        middle.add((found.angles.y - t.num(row, "a1")).abs());
        recomposed.add(rotation_angle_between(q, seq.to_quat(found.angles)));
        scipy_worst = scipy_worst.max(t.num(row, "scipy_err"));
        if found.gimbal_lock {
            locked += 1;
            assert_eq!(found.angles.z, 0.0, "{seq}: third angle at lock");
        }
    }
    middle.check("near-lock quat→euler, middle angle vs mpmath");
    recomposed.check("near-lock quat→euler, recomposed rotation");
    eprintln!(
        "scipy's worst recomposition error on the same rows: {scipy_worst:e} rad; rows flagged as locked: {locked}"
    );
    // The data really probes the regime where scipy fails.
    assert!(scipy_worst > 1e-8);
    assert!(locked > 0);
}

#[test]
fn euler_to_quat_matches_scipy_and_mpmath() {
    let t = Table::load("euler_to_quat.csv");
    let mut err = Stats::new();
    for row in &t.rows {
        let seq: EulerSequence = t.text(row, "seq").parse().unwrap();
        let q = seq.to_quat(t.vec3(row, ["a0", "a1", "a2"]));
        err.add(rotation_angle_between(q, t.quat(row)));
    }
    err.check("euler→quat vs mpmath/scipy");
}

#[test]
fn all_24_conventions_are_covered_by_the_data() {
    for file in ["quat_to_euler.csv", "euler_to_quat.csv"] {
        let t = Table::load(file);
        for seq in EulerSequence::all() {
            let name = seq.to_string();
            assert!(
                t.rows.iter().any(|r| t.text(r, "seq") == name),
                "{file} lacks {name}"
            );
        }
    }
}
