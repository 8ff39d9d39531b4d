//! Bounces on the table that accumulate (issue 26), the shared checks of
//! `tests/table_bouncing_ball.rs` and `tests/table_face_impact.rs`.

use kreisel_dynamics::{TableEventKind, TableMotion};

/// The impacts of `run` so far: time, approach and rebound speeds.
pub fn impacts(run: &TableMotion) -> Vec<(f64, f64, f64)> {
    run.events()
        .iter()
        .filter_map(|e| match e.kind {
            TableEventKind::Impact {
                approach_speed,
                rebound_speed,
            } => Some((e.time, approach_speed, rebound_speed)),
            _ => None,
        })
        .collect()
}

/// Asserts that `run`'s bounces accumulate at `zeno` and it rests there
/// (both within 10⁻⁹ s), each bounce followed rebounding at `e` times its
/// approach (to 10⁻¹² of it) but the last, summed (no rebound); returns
/// how many were followed and the last one's approach speed.
pub fn assert_accumulates_at(run: &TableMotion, zeno: f64, e: f64) -> (usize, f64) {
    let accumulated = run
        .events()
        .iter()
        .find_map(|e| match e.kind {
            TableEventKind::ImpactsAccumulate { accumulation_time } => Some(accumulation_time),
            _ => None,
        })
        .expect("the bounces accumulate");
    assert!((accumulated - zeno).abs() < 1e-9, "{accumulated} vs {zeno}");
    let rest = run.events().last().unwrap();
    assert_eq!(rest.kind, TableEventKind::Rest);
    assert!(
        (rest.time - zeno).abs() < 1e-9,
        "rest at {} vs {zeno}",
        rest.time
    );
    let found = impacts(run);
    let (last, bounces) = found.split_last().unwrap();
    for &(t, approach, rebound) in bounces {
        assert!(
            (rebound - e * approach).abs() <= 1e-12 * approach,
            "at {t}: {approach} → {rebound}"
        );
    }
    assert!(last.2.abs() < 1e-15, "{last:?}");
    (bounces.len(), last.1)
}

/// The closed form of bounces: the first impact at `t1` with speed `v1`,
/// restitution `e`, gravity `g`.
pub struct Bounces {
    pub t1: f64,
    pub v1: f64,
    pub e: f64,
    pub g: f64,
}

impl Bounces {
    /// Advances `run` to the apex of each of its first `count` bounces
    /// (after impact n it rises at `eⁿ v₁`), asserting the centre of
    /// mass's height there against `apex(n)` and then each impact's time
    /// (`t₁ + 2 v₁ (e + … + eⁿ)/g`) to 10⁻¹² relative; `each` runs at
    /// every apex. The impacts found.
    pub fn assert_followed(
        &self,
        run: &mut TableMotion,
        count: i32,
        apex: &dyn Fn(i32) -> f64,
        each: &mut dyn FnMut(&TableMotion),
    ) -> Vec<(f64, f64, f64)> {
        let mut t_impact = self.t1;
        for n in 1..=count {
            let rebound = self.e.powi(n) * self.v1;
            run.try_advance_to(t_impact + rebound / self.g).unwrap();
            let z = run.state().com_world.z;
            let apex = apex(n);
            assert!(
                ((z - apex) / apex).abs() < 1e-12,
                "apex {n}: {z} vs {apex} (relative {:e})",
                (z - apex) / apex
            );
            each(run);
            t_impact += 2.0 * rebound / self.g;
        }
        let found = impacts(run);
        assert_eq!(found.len(), count as usize);
        let mut expected = self.t1;
        for (n, &(t, _, _)) in found.iter().enumerate() {
            assert!(
                ((t - expected) / expected).abs() < 1e-12,
                "impact {n}: {t} vs {expected}"
            );
            expected += 2.0 * self.e.powi(n as i32 + 1) * self.v1 / self.g;
        }
        found
    }
}
