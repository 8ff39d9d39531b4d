//! Bounces on the table that accumulate (issue 26), the shared checks of
//! `tests/table_bouncing_ball.rs` and `tests/table_face_impact.rs`.

use kreisel::dynamics::{TableEventKind, TableMotion};

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
