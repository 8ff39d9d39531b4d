//! Garwin's superball (Am. J. Phys. 37 (1969) 88) on the table (issue 26):
//! normal restitution `e_n` and tangential restitution `e_t` of the contact
//! point's slip, friction high enough never to limit the impulse. Each
//! bounce's time and the velocities and spin after it against the committed
//! closed-form generator (`tests/data/gen/table_closed_forms.py`, mpmath).

use glam::{DMat3, DQuat, DVec3};
use kreisel_dynamics::{
    AdaptiveTolerance, ContactLaw, ContactShape, GroundTopState, SphereContact, TableBody,
    TableContact, TableEventKind, TableMotion,
};

const R: f64 = 0.03;
const M: f64 = 1.0;

/// One row of the reference: `(k, t, vx, vz, ωy)` just after impact `k`.
struct Row {
    k: usize,
    t: f64,
    after: [f64; 3],
}

fn reference(case: &str) -> Vec<Row> {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../tests/data/contact/superball.csv"
    ))
    .unwrap();
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let (k, t, vx, vz, wy) = (
        col("k"),
        col("t"),
        col("vx_after"),
        col("vz_after"),
        col("wy_after"),
    );
    lines
        .map(|l| l.split(',').collect::<Vec<_>>())
        .filter(|f| f[0] == case)
        .map(|f| {
            let x = |i: usize| f[i].parse::<f64>().unwrap();
            Row {
                k: f[k].parse().unwrap(),
                t: x(t),
                after: [x(vx), x(vz), x(wy)],
            }
        })
        .collect()
}

/// The ball touching the table at `t = 0`, thrown at (2, 0, −3) m/s with
/// spin 20 rad/s about y (the reference's first impact).
fn superball(e_n: f64, e_t: f64) -> TableMotion {
    let shape = ContactShape::Sphere(SphereContact::try_new(R, DVec3::ZERO).unwrap());
    let law = ContactLaw::new(100.0)
        .try_with_restitution(e_n)
        .unwrap()
        .try_with_tangential_restitution(e_t)
        .unwrap();
    let i = 0.4 * M * R * R;
    let body = TableBody::try_new(
        M,
        DMat3::from_diagonal(DVec3::splat(i)),
        vec![TableContact { shape, law }],
        9.81,
    )
    .unwrap();
    let start = GroundTopState {
        com_world: DVec3::new(0.0, 0.0, R),
        velocity_world: DVec3::new(2.0, 0.0, -3.0),
        world_from_body: DQuat::IDENTITY,
        l_world: DVec3::new(0.0, i * 20.0, 0.0),
    };
    TableMotion::try_new(body, start, AdaptiveTolerance::new(1e-12, 1e-12)).unwrap()
}

fn check(case: &str, e_n: f64, e_t: f64) {
    let rows = reference(case);
    assert_eq!(rows.len(), 10, "{case}");
    let mut run = superball(e_n, e_t);
    let i = 0.4 * M * R * R;
    for row in &rows {
        if row.k > 1 {
            // To the next impact.
            while run.try_advance_until_event(row.t + 1.0).unwrap() {
                if matches!(
                    run.events().last().unwrap().kind,
                    TableEventKind::Impact { .. }
                ) {
                    break;
                }
            }
        }
        let s = run.state();
        let got = [s.velocity_world.x, s.velocity_world.z, s.l_world.y / i];
        assert!(
            (run.time() - row.t).abs() < 1e-12 * (1.0 + row.t),
            "{case} impact {}: t {} vs {}",
            row.k,
            run.time(),
            row.t
        );
        for (c, (g, w)) in got.iter().zip(row.after).enumerate() {
            assert!(
                (g - w).abs() < 1e-11 * (1.0 + w.abs()),
                "{case} impact {} component {c}: {g} vs {w}",
                row.k
            );
        }
    }
}

#[test]
fn each_bounce_follows_garwins_impact_map() {
    check("en0.9_et0.8", 0.9, 0.8);
}

#[test]
fn the_elastic_superball_keeps_its_energy() {
    check("en1_et1", 1.0, 1.0);
}
