//! Bodies that two sticking contacts overconstrain: a dumbbell on its two
//! spheres has six force components and five degrees of freedom fixed, so
//! its contact forces are not unique (an internal pull along the line
//! between the feet changes nothing), while its motion is. Regressions of
//! the scan of random throws (issue 26), where such states stopped with
//! `ContactIndeterminate` or `ContactUnsolved`; checked against statics
//! and rolling without slipping in closed form.

use glam::{DMat3, DQuat, DVec3};
use kreisel_dynamics::{
    AdaptiveTolerance, ContactLaw, ContactMode, ContactShape, GroundTopState, SphereContact,
    TableBody, TableContact, TableEventKind, TableMotion,
};

const G: f64 = 9.81;
const MASS: f64 = 1.3;
const RADIUS: f64 = 0.05;
/// The feet's distances from the centre of mass along the body's x axis.
const FRONT: f64 = 0.1;
const BACK: f64 = 0.06;

/// The dumbbell: two spheres on the body's x axis, μ = 0.4, plastic.
fn dumbbell() -> TableBody {
    let foot = |x: f64| TableContact {
        shape: ContactShape::Sphere(
            SphereContact::try_new(RADIUS, DVec3::new(x, 0.0, 0.0)).unwrap(),
        ),
        law: ContactLaw::new(0.4),
    };
    let inertia = DMat3::from_diagonal(DVec3::new(0.002, 0.011, 0.012));
    TableBody::try_new(MASS, inertia, vec![foot(FRONT), foot(-BACK)], G).unwrap()
}

/// The normal forces statics gives the feet: `N_f + N_b = m g` and no
/// torque about the centre of mass, `N_f FRONT = N_b BACK`.
fn statics() -> (f64, f64) {
    let w = MASS * G;
    (w * BACK / (FRONT + BACK), w * FRONT / (FRONT + BACK))
}

#[test]
fn a_dumbbell_rolls_on_both_feet_at_constant_speed() {
    // Rolling about its x axis without slipping: v = −ω r ŷ.
    let omega = 12.0;
    let body = dumbbell();
    let start = GroundTopState {
        com_world: DVec3::new(0.0, 0.0, RADIUS),
        velocity_world: DVec3::new(0.0, -omega * RADIUS, 0.0),
        world_from_body: DQuat::IDENTITY,
        l_world: DVec3::new(0.002 * omega, 0.0, 0.0),
    };
    let e0 = body.energy(&start);
    let mut run = TableMotion::try_new(body, start, AdaptiveTolerance::new(1e-10, 1e-10)).unwrap();
    let (front, back) = statics();
    for frame in 1..=120 {
        let t = f64::from(frame) / 60.0;
        run.try_advance_to(t).unwrap();
        assert_eq!(
            run.modes(),
            vec![ContactMode::Sticking, ContactMode::Sticking],
            "t = {t}"
        );
        let s = run.state();
        let want = DVec3::new(0.0, -omega * RADIUS * t, RADIUS);
        assert!(
            (s.com_world - want).length() < 1e-11,
            "t = {t}: {:?}",
            s.com_world
        );
        assert!((run.body().energy(s) - e0).abs() < 1e-12 * e0, "t = {t}");
        let n = run.normal_forces();
        assert!(
            (n[0] - front).abs() < 1e-10 * front && (n[1] - back).abs() < 1e-10 * back,
            "t = {t}: {n:?} vs ({front}, {back})"
        );
    }
    // Touching down where it starts, then no event.
    assert!(
        run.events()
            .iter()
            .all(|e| e.time == 0.0 && e.kind == TableEventKind::Touchdown),
        "{:?}",
        run.events()
    );
    let steps = run.stats().accepted;
    assert!(steps < 400, "{steps} steps for 2 s of rolling");
}

#[test]
fn a_dumbbell_dropped_level_comes_to_rest_on_both_feet() {
    let body = dumbbell();
    let start = GroundTopState {
        com_world: DVec3::new(0.0, 0.0, RADIUS + 0.02),
        velocity_world: DVec3::new(0.1, 0.0, 0.0),
        world_from_body: DQuat::IDENTITY,
        l_world: DVec3::ZERO,
    };
    let mut run = TableMotion::try_new(body, start, AdaptiveTolerance::new(1e-10, 1e-10)).unwrap();
    run.try_advance_to(1.0).unwrap();
    // The plastic landing's friction impulse could stop μ √(2 g h) =
    // 0.25 m/s of slide: it stops the 0.1 m/s, the dumbbell rests where it
    // lands.
    assert!(run.is_resting(), "{:?}", run.events());
    let landing = (2.0 * 0.02 / G).sqrt();
    let x_rest = 0.1 * landing;
    assert!(
        (run.state().com_world.x - x_rest).abs() < 1e-9,
        "{} vs {x_rest}",
        run.state().com_world.x
    );
    let (front, back) = statics();
    let n = run.normal_forces();
    assert!(
        (n[0] - front).abs() < 1e-10 * front && (n[1] - back).abs() < 1e-10 * back,
        "{n:?} vs ({front}, {back})"
    );
}
