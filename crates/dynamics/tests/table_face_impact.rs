//! A disk striking the table with its face (issue 26): Newton's
//! restitution over the face, friction at the impact, the bounces' Zeno
//! accumulation and rest flat — against closed forms.
//!
//! The disk: thin (`I = m a² (¼, ¼, ½)`, its centre of mass in the face's
//! plane), m = 10 g, a = 2 cm, dropped exactly flat with its face
//! h = 0.1 m above the table, e = 0.8, g = 9.81 m/s². Only `v_z` is
//! nonzero at the face: the pressure is uniform, `v_z⁺ = −e v_z⁻`. It
//! strikes at `t₁ = √(2h/g)` with `v₁ = √(2gh)`; after impact n it rises
//! at `eⁿ v₁` to `e²ⁿ h` and strikes again `2 eⁿ v₁/g` later; the bounces
//! accumulate at `t∞ = t₁ (1 + e)/(1 − e)`.
//!
//! Friction at the impact (Coulomb–Contensou on the face, lever
//! `ε = ⅔ a`): in the slip coordinates `s = (v_x, v_y, ε ω_z)` the
//! impulse `Λ = (P_x, P_y, M_z/ε)` moves `s` by `W Λ`, `W = diag(1/m,
//! 1/m, ε²/I_zz) = (1, 1, 8/9)/m`; with `β = μ (1 + e) v_n` (`P_N = m (1 +
//! e) v_n`) Newton's law with `e_T = 0` (`Λ = −μ P_N s⁺/|s⁺|`) gives
//!
//! ```text
//! s⁺_k = s⁻_k σ/(σ + β w_k),   σ = |s⁺| > 0 the root of Σ_k (s⁻_k/(σ + β w_k))² = 1,   w = (1, 1, 8/9)
//! s⁺ = 0 (sticking) when Σ_k (s⁻_k/(β w_k))² ≤ 1
//! ```
//!
//! — sliding without spin simply `Δv = −μ (1 + e) v_n` along `v`; spinning
//! without sliding `Δω_z = −(4/3) μ (1 + e) v_n/a`.

use glam::{DMat3, DQuat, DVec3};
use kreisel_dynamics::{
    AdaptiveTolerance, ContactLaw, ContactShape, DiskContact, GroundTopState, TableBody,
    TableContact, TableMotion,
};

mod common;

use common::bounces::{Bounces, assert_accumulates_at, impacts};

const M: f64 = 0.01;
const A: f64 = 0.02;
const H: f64 = 0.1;
const E: f64 = 0.8;
const G: f64 = 9.81;

/// The disk dropped exactly flat from `H` with `velocity` (horizontal)
/// and spin `omega_z`, friction `mu`.
fn dropped_flat(mu: f64, velocity: DVec3, omega_z: f64) -> TableMotion {
    dropped_tilted(mu, velocity, omega_z, 0.0)
}

/// [`dropped_flat`] tilted by `tilt` rad about x.
fn dropped_tilted(mu: f64, velocity: DVec3, omega_z: f64, tilt: f64) -> TableMotion {
    let rim = DiskContact::try_new(A, DVec3::ZERO, DVec3::Z).unwrap();
    let law = ContactLaw::new(mu).try_with_restitution(E).unwrap();
    let inertia = DMat3::from_diagonal(DVec3::new(0.25, 0.25, 0.5) * M * A * A);
    let contacts = vec![TableContact {
        shape: ContactShape::Disk(rim),
        law,
    }];
    let body = TableBody::try_new(M, inertia, contacts, G).unwrap();
    let start = GroundTopState {
        com_world: DVec3::new(0.0, 0.0, H),
        velocity_world: velocity,
        world_from_body: DQuat::from_rotation_x(tilt),
        l_world: DVec3::new(0.0, 0.0, 0.5 * M * A * A * omega_z),
    };
    TableMotion::try_new(body, start, AdaptiveTolerance::new(1e-12, 1e-12)).unwrap()
}

/// `(t₁, v₁)`.
fn first_impact() -> (f64, f64) {
    ((2.0 * H / G).sqrt(), (2.0 * G * H).sqrt())
}

#[test]
fn a_disk_dropped_flat_bounces_on_its_face_as_the_closed_form() {
    let mut run = dropped_flat(0.3, DVec3::ZERO, 0.0);
    let (t1, v1) = first_impact();
    let bounces = Bounces { t1, v1, e: E, g: G };
    // Flat all along, no turn.
    let flat = &mut |run: &TableMotion| assert_eq!(run.state().world_from_body, DQuat::IDENTITY);
    let found = bounces.assert_followed(&mut run, 20, &|n| E.powi(2 * n) * H, flat);
    for (n, &(_, approach, rebound)) in found.iter().enumerate() {
        let v = E.powi(n as i32) * v1;
        assert!((approach - v).abs() < 1e-12 * v, "{approach} vs {v}");
        assert!(
            (rebound - E * v).abs() < 1e-12 * v,
            "{rebound} vs {}",
            E * v
        );
    }
}

#[test]
fn the_face_bounces_accumulate_at_the_zeno_point_and_the_disk_rests_flat() {
    let mut run = dropped_flat(0.3, DVec3::ZERO, 0.0);
    let (t1, _) = first_impact();
    let zeno = t1 * (1.0 + E) / (1.0 - E);
    run.try_advance_to(2.0 * zeno).unwrap();
    assert!(run.is_resting());
    assert_eq!(run.lying_flat_on(), Some(0));
    let s = run.state();
    assert!(s.com_world.z.abs() < 1e-15, "{}", s.com_world.z);
    assert_eq!(s.velocity_world, DVec3::ZERO);
    assert_eq!(s.l_world, DVec3::ZERO);
    let (followed, _) = assert_accumulates_at(&run, zeno, E);
    assert!(followed > 40, "{followed} bounces followed");
}

#[test]
fn a_disk_dropped_nearly_flat_strikes_with_its_face_and_rests_flat() {
    // Tilted 5·10⁻⁷ rad (within DISK_FLAT_TILT): the rim's lowest point
    // falls h' = h − a sin θ; the face strikes there, no turn is imparted.
    // The rim's height below the centre, a (1 − n_z²)/s = a sin θ = 10⁻⁸
    // m, rounds to ~ε/θ² of itself (n_z = cos θ = 1 − 1.25·10⁻¹³): the
    // first impact is asserted to 1 % of that height's share of its time.
    let tilt = 5e-7;
    let mut run = dropped_tilted(0.3, DVec3::ZERO, 0.0, tilt);
    let drop = H - A * tilt.sin();
    let t1 = (2.0 * drop / G).sqrt();
    let zeno = t1 * (1.0 + E) / (1.0 - E);
    run.try_advance_to(2.0 * zeno).unwrap();
    let found = impacts(&run);
    let v1 = (2.0 * G * drop).sqrt();
    assert!(
        (found[0].0 - t1).abs() < 0.01 * A * tilt.sin() / v1,
        "{} vs {t1}",
        found[0].0
    );
    let (followed, _) = assert_accumulates_at(&run, zeno, E);
    assert!(followed > 40, "{followed} bounces followed");
    assert!(run.is_resting() && run.lying_flat_on() == Some(0));
    // Landed: turned flat about the rim's lowest point, on the table.
    let n = run.state().world_from_body * DVec3::Z;
    assert!(DVec3::Z.cross(n).length() < 1e-15);
    assert!(run.state().com_world.z.abs() < 1e-15);
}

/// The slip `s⁺` after a face impact from `s⁻` with `β = μ (1 + e) v_n`
/// (the module's closed form; σ by bisection).
fn slip_after(s: DVec3, beta: f64) -> DVec3 {
    let w = DVec3::new(1.0, 1.0, 8.0 / 9.0);
    let residual = |sigma: f64| {
        (0..3)
            .map(|k| (s[k] / (sigma + beta * w[k])).powi(2))
            .sum::<f64>()
            - 1.0
    };
    if residual(0.0) <= 0.0 {
        return DVec3::ZERO;
    }
    let (mut lo, mut hi) = (0.0, s.length());
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if residual(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let sigma = 0.5 * (lo + hi);
    DVec3::new(
        s.x * sigma / (sigma + beta * w.x),
        s.y * sigma / (sigma + beta * w.y),
        s.z * sigma / (sigma + beta * w.z),
    )
}

/// The run from its start to rest event by event: after each impact its
/// slip `(v_x, v_y, ε ω_z)` against [`slip_after`] from the slip before,
/// the energy never rising; the impacts that slid and stuck.
fn follow_the_friction(mu: f64, velocity: DVec3, omega_z: f64) -> (usize, usize) {
    let mut run = dropped_flat(mu, velocity, omega_z);
    let lever = 2.0 * A / 3.0;
    let slip_of = |run: &TableMotion| {
        let s = run.state();
        let omega_z = s.l_world.z / (0.5 * M * A * A);
        DVec3::new(s.velocity_world.x, s.velocity_world.y, lever * omega_z)
    };
    let e0 = run.body().energy(run.state());
    let mut energy = e0;
    let mut slip = slip_of(&run);
    let (t1, v1) = first_impact();
    let mut seen = 0;
    let (mut slid, mut stuck) = (0, 0);
    while run
        .try_advance_until_event(2.0 * t1 * (1.0 + E) / (1.0 - E))
        .unwrap()
    {
        let now = run.body().energy(run.state());
        assert!(now <= energy + 1e-12 * e0, "energy rose at {}", run.time());
        energy = now;
        let found = impacts(&run);
        if found.len() == seen {
            continue;
        }
        assert_eq!(found.len(), seen + 1);
        let (t, approach, rebound) = found[seen];
        let v_n = E.powi(seen as i32) * v1;
        assert!((approach - v_n).abs() < 1e-12 * v1, "{approach} vs {v_n}");
        // The last impact is summed (plastic): e = 0 there.
        let e = if rebound == 0.0 { 0.0 } else { E };
        let expected = slip_after(slip, mu * (1.0 + e) * v_n);
        let got = slip_of(&run);
        assert!(
            (got - expected).length() < 1e-12 * v1,
            "impact {seen} at {t}: {got} vs {expected}"
        );
        if expected == DVec3::ZERO {
            // Stopped, to the rounding of the sticking impulse.
            assert!(got.length() < 1e-15 * v1, "sticks at impact {seen}: {got}");
            stuck += 1;
        } else {
            slid += 1;
        }
        slip = got;
        seen += 1;
    }
    assert!(run.is_resting() && run.lying_flat_on() == Some(0));
    assert_eq!(run.state().velocity_world, DVec3::ZERO);
    (slid, stuck)
}

#[test]
fn sliding_through_the_impacts_loses_mu_one_plus_e_v_n_per_bounce() {
    // No spin: Δv = −μ (1 + e) v_n along v while it slides; it sticks at
    // the third impact (0.3 − 0.126 (1 + 0.8) = 0.073 < 0.126 · 0.64).
    let (mu, v0) = (0.05, 0.3);
    let (_, v1) = first_impact();
    let beta = mu * (1.0 + E) * v1;
    assert!(v0 > beta * (1.0 + E) && v0 < beta * (1.0 + E + E * E));
    let (slid, stuck) = follow_the_friction(mu, DVec3::new(v0, 0.0, 0.0), 0.0);
    assert_eq!(slid, 2);
    assert!(stuck > 40, "{stuck}");
}

#[test]
fn sliding_and_spinning_through_the_impacts_follow_contensous_lever() {
    // Sliding and spinning at once: the slip's direction turns at each
    // impact (the spin's weight 8/9 differs), both stop together.
    let (slid, stuck) = follow_the_friction(0.05, DVec3::new(0.3, 0.1, 0.0), 20.0);
    assert!(slid >= 2, "{slid}");
    assert!(stuck > 40, "{stuck}");
}

#[test]
fn pure_spin_loses_four_thirds_mu_one_plus_e_v_n_over_a_per_bounce() {
    // Δω_z = −(4/3) μ (1 + e) v_n/a, by hand, at the first impact.
    let (mu, omega0) = (0.05, 40.0);
    let mut run = dropped_flat(mu, DVec3::ZERO, omega0);
    let (t1, v1) = first_impact();
    run.try_advance_to(t1 + 0.5 * E * v1 / G).unwrap();
    let omega = run.state().l_world.z / (0.5 * M * A * A);
    let expected = omega0 - 4.0 / 3.0 * mu * (1.0 + E) * v1 / A;
    assert!(
        (omega - expected).abs() < 1e-12 * omega0,
        "{omega} vs {expected}"
    );
    assert_eq!(run.state().velocity_world.truncate(), glam::DVec2::ZERO);
}
