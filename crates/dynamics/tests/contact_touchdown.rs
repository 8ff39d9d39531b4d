//! A second contact shape touching down (`GroundTop::try_with_other_contacts`,
//! `DynamicsError::ContactTouchdown`) against references the library does
//! not compute: the stem ball of Leine & Glocker's tippe top reaching the
//! table in a committed scipy run of its own equations
//! (`tests/data/contact/tippe_top_touchdown.csv`, `python3
//! tests/data/gen/tippe_top.py --touchdown`), and a body tipping over onto a
//! side knob whose touchdown instant follows from energy and a
//! one-degree-of-freedom quadrature; the state left at the reported time
//! (gap ≈ 0), grazes inside one step, bad inputs, and the trajectory left
//! bit for bit unchanged by watching.

mod common;

use glam::{DMat3, DQuat, DVec2, DVec3};
use kreisel_dynamics::{
    AdaptiveTolerance, ContactShape, DynamicsError, Friction, GroundTop, GroundTopState,
    MAX_OTHER_CONTACTS, SphereContact,
};

use common::tippe_top::{G, leine_glocker, stem, touchdown_reference};

/// The tippe top with `friction`, watching its stem ball.
fn tippe_top_with_stem(friction: Friction) -> (GroundTop, GroundTopState) {
    let (top, s) = leine_glocker(friction);
    (top.try_with_other_contacts(&[stem()]).unwrap(), s)
}

/// The touchdown error's fields, or a panic with what came instead.
fn touchdown(result: Result<impl std::fmt::Debug, DynamicsError>) -> (f64, usize, f64) {
    match result {
        Err(DynamicsError::ContactTouchdown {
            time,
            contact,
            approach_speed,
        }) => (time, contact, approach_speed),
        other => panic!("expected a touchdown, got {other:?}"),
    }
}

/// Checks one scenario's touchdown against the generator: the time to
/// `rel` relative, the approach speed and the state loosely (they change
/// fast there), the stem's gap at the reported state to round-off.
fn against_generator(scenario: &str, top: &GroundTop, s: &GroundTopState, time: f64, speed: f64) {
    let common::tippe_top::Touchdown {
        time: t_ref,
        time_coarse: t_coarse,
        approach_speed: speed_ref,
        state: s_ref,
    } = touchdown_reference(scenario);
    let gap = top.other_gap(s, 0).unwrap();
    eprintln!(
        "{scenario}: touchdown at {time} s, generator {t_ref} s (its rtol 1e-11 run: {t_coarse}), \
         Δt/t = {:.1e}; approach {speed} vs {speed_ref} m/s; gap there {gap:e} m; \
         |Δr_G| {:.1e} m",
        (time - t_ref).abs() / t_ref,
        (s.com_world - s_ref.com_world).length()
    );
    // The reference's own error, from its coarser run, is far below the bound.
    assert!((t_coarse - t_ref).abs() < 1e-8 * t_ref);
    assert!((time - t_ref).abs() <= 1e-6 * t_ref, "{time} vs {t_ref}");
    assert!(
        (speed / speed_ref - 1.0).abs() < 1e-5,
        "{speed} vs {speed_ref}"
    );
    // Left where the stem's ball touches: not above, and below by round-off only.
    assert!(gap <= 0.0 && gap > -1e-15, "gap {gap:e} m");
    assert!(top.gap(s).abs() < 1e-10, "the ball's own contact drifted");
    let tilt = (s.world_from_body.normalize() * DVec3::Z).z.acos();
    let tilt_ref = (s_ref.world_from_body.normalize() * DVec3::Z).z.acos();
    assert!((tilt - tilt_ref).abs() < 1e-5, "{tilt} vs {tilt_ref}");
}

// Measured (h = 1e-5 s): see the eprintln; the generator's 3.8 s run.
#[test]
fn sliding_tippe_top_stem_touches_down_at_the_generators_time() {
    let (top, mut s) = tippe_top_with_stem(Friction::try_sliding(0.3, 1e-3).unwrap());
    let h = 1e-5;
    let err = top.try_advance(&mut s, 0.0, h, 500_000, |_, _| {});
    let (time, contact, speed) = touchdown(err);
    assert_eq!(contact, 0);
    against_generator("sliding", &top, &s, time, speed);
}

#[test]
fn viscous_tippe_top_stem_touches_down_at_the_generators_time_adaptive() {
    let (top, mut s) = tippe_top_with_stem(Friction::try_viscous(0.3).unwrap());
    let tol = AdaptiveTolerance::try_new(1e-10, 1e-12).unwrap();
    let mut last = 0.0;
    let err = top.try_advance_adaptive(&mut s, 0.0, 20.0, tol, |t, _| last = t);
    let (time, contact, speed) = touchdown(err);
    assert_eq!(contact, 0);
    assert!(time > last, "{time} after the last accepted step {last}");
    against_generator("viscous", &top, &s, time, speed);
}

/// A body standing on a ball below its centre of mass, tipping over about
/// x without spin, frictionless, onto a knob on its side:
///
/// ```text
/// ball: radius R0, centre (0, 0, −B) body;   knob: radius R2, centre (0, −D, 0) body
/// z_G = R0 + B cos θ  (the centre of mass moves vertically only: no horizontal force)
/// E = ½ (I + m B² sin²θ) θ̇² + m g (R0 + B cos θ)
/// knob gap(θ) = R0 + B cos θ − D sin θ − R2
/// N(θ) = m (g + z̈_G)
/// ```
struct Tipping {
    m: f64,
    i: f64,
    e: f64,
}

const R0: f64 = 0.01;
const B: f64 = 0.04;
const D: f64 = 0.03;
const R2: f64 = 0.004;

impl Tipping {
    fn rate2(&self, th: f64) -> f64 {
        2.0 * (self.e - self.m * G * (R0 + B * th.cos()))
            / (self.i + self.m * B * B * th.sin().powi(2))
    }

    fn knob_gap(&self, th: f64) -> f64 {
        R0 + B * th.cos() - D * th.sin() - R2
    }

    /// `m (g + z̈_G)`, `z̈_G = −B (cos θ θ̇² + sin θ θ̈)`, θ̈ from `dE/dt = 0`.
    fn normal_force(&self, th: f64) -> f64 {
        let (s, c) = th.sin_cos();
        let d = self.i + self.m * B * B * s * s;
        let r2 = self.rate2(th);
        let acc = (self.m * G * B * s - self.m * B * B * s * c * r2) / d;
        self.m * (G - B * (c * r2 + s * acc))
    }

    fn top(&self, others: &[ContactShape]) -> GroundTop {
        let ball = SphereContact::try_new(R0, DVec3::new(0.0, 0.0, -B)).unwrap();
        let inertia = DMat3::from_diagonal(DVec3::new(self.i, self.i, 0.5 * self.i));
        GroundTop::try_new(self.m, inertia, ball, Friction::None, G)
            .unwrap()
            .try_with_other_contacts(others)
            .unwrap()
    }
}

fn knob() -> ContactShape {
    ContactShape::Sphere(SphereContact::try_new(R2, DVec3::new(0.0, -D, 0.0)).unwrap())
}

#[test]
fn tipping_body_touches_its_knob_down_at_the_hand_computed_time() {
    let theta_s: f64 = 0.05;
    // Falling from 0.05 rad at 2 rad/s.
    let (m, i, rate_s) = (0.1, 4e-5, 2.0);
    let dof = Tipping {
        m,
        i,
        e: m * G * (R0 + B * theta_s.cos())
            + 0.5 * (i + m * B * B * theta_s.sin().powi(2)) * rate_s * rate_s,
    };
    // θ* where the knob's gap vanishes, t* = ∫ dθ/θ̇ (Simpson).
    let (theta_star, t_star) =
        common::contact::lift_off_by_hand(theta_s, 1.5, |th| dof.knob_gap(th), |th| dof.rate2(th));
    // The ball keeps pushing all the way: no lift-off before the knob lands.
    let n_min = (0..=1000)
        .map(|k| dof.normal_force(theta_s + (theta_star - theta_s) * k as f64 / 1000.0))
        .fold(f64::INFINITY, f64::min);
    assert!(n_min > 0.1 * dof.m * G, "N falls to {n_min} N");
    let speed_star = (B * theta_star.sin() + D * theta_star.cos()) * dof.rate2(theta_star).sqrt();

    let top = dof.top(&[knob()]);
    let q = DQuat::from_rotation_x(theta_s);
    let start = top
        .try_state_on_ground(q, DVec3::new(rate_s, 0.0, 0.0), DVec2::ZERO)
        .unwrap();
    assert!((dof.rate2(theta_s) / (rate_s * rate_s) - 1.0).abs() < 1e-12);
    assert!((top.energy(&start) / dof.e - 1.0).abs() < 1e-14);
    assert!((top.other_gap(&start, 0).unwrap() - dof.knob_gap(theta_s)).abs() < 1e-16);

    let check = |s: &GroundTopState, time: f64, speed: f64, what: &str, rel: f64| {
        let axis = s.world_from_body.normalize() * DVec3::Z;
        let theta = (-axis.y).atan2(axis.z);
        let gap = top.other_gap(s, 0).unwrap();
        eprintln!(
            "{what}: touchdown at {time} s (t* = {t_star}, Δ {:.1e}), θ {theta} (θ* = {theta_star}), \
             approach {speed} (by hand {speed_star}), gap {gap:e}",
            time - t_star
        );
        assert!((time - t_star).abs() <= rel * t_star, "{time} vs {t_star}");
        assert!((theta - theta_star).abs() < 1e-8, "{theta} vs {theta_star}");
        assert!(
            (speed / speed_star - 1.0).abs() < 1e-7,
            "{speed} vs {speed_star}"
        );
        assert!(gap <= 0.0 && gap > -1e-16, "gap {gap:e} m");
    };

    let mut s = start;
    let (time, contact, speed) = touchdown(top.try_advance(&mut s, 0.0, 1e-4, 100_000, |_, _| {}));
    assert_eq!(contact, 0);
    check(&s, time, speed, "rk4 h = 1e-4", 1e-10);

    let mut s = start;
    let tol = AdaptiveTolerance::try_new(1e-12, 1e-12).unwrap();
    let (time, contact, speed) =
        touchdown(top.try_advance_adaptive(&mut s, 0.0, 10.0, tol, |_, _| {}));
    assert_eq!(contact, 0);
    check(&s, time, speed, "dopri5 1e-12", 1e-10);

    // Stepping on from the reported state reports the same touchdown at
    // once, the state unchanged: the model does not go further.
    let at = s;
    let (again, _, _) = touchdown(top.try_step(&mut s, time, 1e-4));
    assert_eq!((again, s), (time, at));
}

// A knob off the axis of the spinning top rises and falls once a turn
// (180 rad/s: 35 ms). Its radius is set so that its bottom dips 1 µm
// below the plane at the first minimum, for about 0.5 ms: steps of 2 ms
// (ω h ≈ 0.37) end above the plane on both sides of it, the check from
// the gap's values and rates at the step's ends (a cubic) finds it; the
// time agrees with a fine-step run whose steps see the sign change.
#[test]
fn a_graze_inside_one_step_is_found() {
    let (plain, s0) = leine_glocker(Friction::None);
    let c = DVec3::new(0.012, 0.0, 0.0);
    let centre_z = |s: &GroundTopState| s.com_world.z + (s.world_from_body.normalize() * c).z;
    // The first local minimum of the knob centre's height, fine steps.
    let mut heights = vec![centre_z(&s0)];
    let mut s = s0;
    plain
        .try_advance(&mut s, 0.0, 1e-6, 60_000, |_, s| heights.push(centre_z(s)))
        .unwrap();
    let k = (1..heights.len() - 1)
        .find(|&k| heights[k] < heights[k - 1] && heights[k] <= heights[k + 1])
        .expect("a minimum within 60 ms");
    let t_min = k as f64 * 1e-6;
    eprintln!("first minimum of the knob's centre at t = {t_min} s");
    let knob = SphereContact::try_new(heights[k] + 1e-6, c).unwrap();
    let top = plain
        .clone()
        .try_with_other_contacts(&[ContactShape::Sphere(knob)])
        .unwrap();
    let mut fine = s0;
    let (t_fine, _, _) = touchdown(top.try_advance(&mut fine, 0.0, 1e-6, 60_000, |_, _| {}));
    // About 2 ms, the minimum in the middle of the 13th step.
    let h = t_min / 12.5;
    let mut coarse = s0;
    let err = top.try_advance(&mut coarse, 0.0, h, 100, |_, _| {});
    let (t_coarse, _, _) = touchdown(err);
    let gap = top.other_gap(&coarse, 0).unwrap();
    eprintln!("graze: fine {t_fine} s, coarse (h = {h}) {t_coarse} s, gap {gap:e}");
    // Both ends of the step that contains it are above the plane.
    let n = (t_coarse / h).floor() as usize;
    let mut probe = s0;
    plain.try_advance(&mut probe, 0.0, h, n, |_, _| {}).unwrap();
    let g_start = top.other_gap(&probe, 0).unwrap();
    plain.try_step(&mut probe, n as f64 * h, h).unwrap();
    let g_end = top.other_gap(&probe, 0).unwrap();
    eprintln!(
        "the step from {} s: gap {g_start:e} → {g_end:e} m",
        n as f64 * h
    );
    assert!(g_start > 0.0 && g_end > 0.0);
    assert!(gap <= 0.0 && gap > -1e-15, "{gap:e}");
    // The entry into a 1 µm dip is located to the coarse method's accuracy.
    assert!((t_coarse - t_fine).abs() < 1e-5, "{t_coarse} vs {t_fine}");
}

#[test]
fn watching_a_far_contact_leaves_every_bit_unchanged() {
    for friction in [
        Friction::try_sliding(0.3, 1e-3).unwrap(),
        Friction::Rolling,
        Friction::None,
    ] {
        let (plain, s0) = leine_glocker(friction);
        let far =
            ContactShape::Sphere(SphereContact::try_new(0.001, DVec3::new(0.0, 0.0, 1.0)).unwrap());
        let watching = plain
            .clone()
            .try_with_other_contacts(&[far, stem()])
            .unwrap();
        assert_eq!(watching.other_contacts(), &[far, stem()]);
        let (mut a, mut b) = (s0, s0);
        plain
            .try_advance(&mut a, 0.0, 1e-4, 2000, |_, _| {})
            .unwrap();
        watching
            .try_advance(&mut b, 0.0, 1e-4, 2000, |_, _| {})
            .unwrap();
        assert_eq!(a, b, "{friction:?}");
        let tol = AdaptiveTolerance::try_new(1e-9, 1e-11).unwrap();
        let (mut a, mut b) = (s0, s0);
        let sa = plain
            .try_advance_adaptive(&mut a, 0.0, 0.2, tol, |_, _| {})
            .unwrap();
        let sb = watching
            .try_advance_adaptive(&mut b, 0.0, 0.2, tol, |_, _| {})
            .unwrap();
        assert_eq!((a, sa), (b, sb), "{friction:?}");
        // Emptying the list gives the plain top back.
        assert_eq!(watching.try_with_other_contacts(&[]).unwrap(), plain);
    }
}

#[test]
fn bad_inputs_are_typed_errors() {
    let (top, s0) = leine_glocker(Friction::None);
    // Too many shapes.
    let many = vec![stem(); MAX_OTHER_CONTACTS + 1];
    assert!(matches!(
        top.clone().try_with_other_contacts(&many),
        Err(DynamicsError::InvalidContact {
            parameter: "other_contacts",
            ..
        })
    ));
    assert!(top.clone().try_with_other_contacts(&many[1..]).is_ok());
    // A further sphere at or below the plane at the start: refused by both
    // start-state constructors, with its index and gap.
    let low =
        ContactShape::Sphere(SphereContact::try_new(0.02, DVec3::new(0.0, 0.0, -0.005)).unwrap());
    let top = top.try_with_other_contacts(&[stem(), low]).unwrap();
    let q = DQuat::from_rotation_x(0.1);
    let err = top
        .try_state_on_ground(q, DVec3::ZERO, DVec2::ZERO)
        .unwrap_err();
    let DynamicsError::OtherContactTouching { contact, gap } = err else {
        panic!("{err}")
    };
    assert_eq!(contact, 1);
    assert!(gap < 0.0);
    assert!(
        err.to_string()
            .contains("further contact #1 is at or below the plane")
    );
    let rolling = leine_glocker(Friction::Rolling)
        .0
        .try_with_other_contacts(&[low])
        .unwrap();
    assert!(matches!(
        rolling.try_rolling_state_on_ground(q, DVec3::ZERO),
        Err(DynamicsError::OtherContactTouching { contact: 0, .. })
    ));
    // A hand-made state with the further sphere below: the step is not
    // taken, the touchdown reported at its start.
    let mut s = s0;
    let t = 1.25;
    let (time, contact, _) = touchdown(top.try_step(&mut s, t, 1e-4));
    assert_eq!((time, contact, s), (t, 1, s0));
    let mut s = s0;
    let tol = AdaptiveTolerance::try_new(1e-9, 1e-11).unwrap();
    let (time, _, _) = touchdown(top.try_advance_adaptive(&mut s, t, 2.0, tol, |_, _| {}));
    assert_eq!((time, s), (t, s0));
    // Out-of-range indices are None, not a panic.
    assert_eq!(top.other_gap(&s0, 2), None);
    assert_eq!(top.other_gap_rate(&s0, 2), None);
}

/// After a lift-off, `try_fly` carries the body through the air until its
/// ball lands. A body with a spherical inertia tensor turns uniformly in
/// flight, so the ball's gap is a closed form of the flight time τ:
///
/// ```text
/// gap(τ) = z_L + ż_L τ − ½ g τ² − a cos(θ_L + ω τ) − R
/// ```
///
/// (ball of radius R at (0, 0, −a) body, rocking about x; its first root
/// found here by sampling and bisection, by hand). The energy and L are
/// conserved in flight.
#[test]
fn lift_off_then_flight_lands_at_the_closed_form_time() {
    let (m, i, a, r0, theta_s) = (1.0, 1e-3, 0.05, 0.04, -0.5f64);
    let ball = SphereContact::try_new(r0, DVec3::new(0.0, 0.0, -a)).unwrap();
    let top = GroundTop::try_new(
        m,
        DMat3::from_diagonal(DVec3::splat(i)),
        ball,
        Friction::None,
        G,
    )
    .unwrap();
    // Coming up from θ = −0.5 fast enough to leave the plane (the lift-off
    // case of tests/contact_sphere.rs).
    let e = 0.5 * i * 1.1 * G / a + m * G * a;
    let rate2 = 2.0 * (e - m * G * a * theta_s.cos()) / (i + m * a * a * theta_s.sin().powi(2));
    let q = DQuat::from_rotation_x(theta_s);
    let mut s = top
        .try_state_on_ground(q, DVec3::new(rate2.sqrt(), 0.0, 0.0), DVec2::ZERO)
        .unwrap();
    let err = top
        .try_advance(&mut s, 0.0, 1e-4, 1000, |_, _| {})
        .unwrap_err();
    let DynamicsError::ContactLost { time: t_lift, .. } = err else {
        panic!("{err}")
    };
    let (e_lift, lift) = (top.energy(&s), s);
    // The flight by hand from the lift-off state.
    let axis = s.world_from_body.normalize() * DVec3::Z;
    let theta_l = (-axis.y).atan2(axis.z);
    let omega = s.l_world.x / i;
    let (z_l, vz_l) = (s.com_world.z, s.velocity_world.z);
    let gap =
        |tau: f64| z_l + vz_l * tau - 0.5 * G * tau * tau - a * (theta_l + omega * tau).cos() - r0;
    let first_positive = (1..)
        .map(|k| k as f64 * 1e-6)
        .find(|&t| gap(t) > 0.0)
        .unwrap();
    let mut lo = first_positive;
    let mut hi = (1..)
        .map(|k| lo + k as f64 * 1e-5)
        .find(|&t| gap(t) <= 0.0)
        .unwrap();
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if gap(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let tau_hand = hi;

    // In the air until shortly before: None, the state on the parabola.
    let mut early = s;
    let t_mid = t_lift + 0.5 * tau_hand;
    assert_eq!(top.try_fly(&mut early, t_lift, t_mid).unwrap(), None);
    let tau = t_mid - t_lift;
    let z_mid = z_l + vz_l * tau - 0.5 * G * tau * tau;
    assert!(
        (early.com_world.z - z_mid).abs() < 1e-15,
        "{}",
        early.com_world.z - z_mid
    );
    assert_eq!(early.l_world, lift.l_world);

    let landing = top
        .try_fly(&mut s, t_lift, t_lift + 10.0)
        .unwrap()
        .expect("it lands");
    let flown = landing.time - t_lift;
    eprintln!(
        "lift-off at {t_lift} s; lands at {} s after {flown} s in the air (by hand {tau_hand} s, Δ {:.1e}); \
         approach {} m/s; gap {:e}; ΔE/E {:.1e}",
        landing.time,
        flown - tau_hand,
        landing.approach_speed,
        top.gap(&s),
        top.energy(&s) / e_lift - 1.0
    );
    assert_eq!(landing.contact, None);
    assert!((flown - tau_hand).abs() < 1e-12, "{flown} vs {tau_hand}");
    let speed_hand = -(vz_l - G * tau_hand + a * omega * (theta_l + omega * tau_hand).sin());
    assert!((landing.approach_speed / speed_hand - 1.0).abs() < 1e-9);
    assert!(landing.approach_speed > 0.0);
    let g_end = top.gap(&s);
    assert!(g_end <= 0.0 && g_end > -1e-15, "{g_end:e}");
    assert!((top.energy(&s) / e_lift - 1.0).abs() < 1e-13);
    assert_eq!(s.l_world, lift.l_world);
}

#[test]
fn flight_bad_inputs_are_typed_errors() {
    let (top, s0) = leine_glocker(Friction::None);
    for (t0, t_end) in [(1.0, 0.5), (0.0, f64::NAN), (f64::INFINITY, 1.0)] {
        let mut s = s0;
        assert!(matches!(
            top.try_fly(&mut s, t0, t_end),
            Err(DynamicsError::InvalidInterval { .. })
        ));
        assert_eq!(s, s0);
    }
    let mut s = s0;
    s.l_world.x = f64::NAN;
    assert!(matches!(
        top.try_fly(&mut s, 0.0, 1.0),
        Err(DynamicsError::InvalidState { .. })
    ));
    // Resting on the plane with nothing to lift it: lands at once.
    let (top, s0) = leine_glocker(Friction::None);
    let mut rest = top
        .try_state_on_ground(DQuat::IDENTITY, DVec3::ZERO, DVec2::ZERO)
        .unwrap();
    let landing = top.try_fly(&mut rest, 2.0, 3.0).unwrap().unwrap();
    assert_eq!((landing.time, landing.contact), (2.0, None));
    let _ = s0;
}

/// A tippe top tossed up spinning comes down on its ball or, tossed
/// upside down, on its stem: the landing shape is the one whose gap
/// reaches zero first, checked against fine samples of the same flight
/// (every gap positive before the landing), the centre of mass on its
/// parabola.
#[test]
fn tossed_top_lands_on_the_first_shape_to_reach_the_plane() {
    let (top, s0) = tippe_top_with_stem(Friction::None);
    for (tilt, expected) in [(0.1, None), (2.8, Some(0))] {
        let q = DQuat::from_rotation_x(tilt);
        let start = GroundTopState {
            com_world: DVec3::new(0.0, 0.0, 0.05),
            velocity_world: DVec3::new(0.1, 0.0, 0.5),
            world_from_body: q,
            l_world: s0.l_world.length() * (q * DVec3::Z) + q * DVec3::new(2e-5, 0.0, 0.0),
        };
        let mut s = start;
        let landing = top.try_fly(&mut s, 0.0, 5.0).unwrap().expect("it lands");
        let n = 2000;
        for k in 1..n {
            let t = landing.time * k as f64 / n as f64;
            let mut probe = start;
            assert_eq!(
                top.try_fly(&mut probe, 0.0, t).unwrap(),
                None,
                "landed before {t}"
            );
            assert!(top.gap(&probe) > 0.0 && top.other_gap(&probe, 0).unwrap() > 0.0);
        }
        let gap = match landing.contact {
            None => top.gap(&s),
            Some(i) => top.other_gap(&s, i).unwrap(),
        };
        eprintln!(
            "tossed at tilt {tilt}: lands at {} s on {:?}, gap {gap:e}, approach {} m/s",
            landing.time, landing.contact, landing.approach_speed
        );
        assert_eq!(landing.contact, expected);
        assert!(gap <= 0.0 && gap > -1e-15);
        assert!(landing.approach_speed > 0.0);
        let t = landing.time;
        let z = 0.05 + 0.5 * t - 0.5 * G * t * t;
        assert!((s.com_world.z - z).abs() < 1e-15);
        assert_eq!(s.l_world, start.l_world);
        // Torque-free about the centre of mass: the energy and the axis'
        // angle to L (L₃ = L·e₃ of a symmetric body) are conserved.
        assert!((top.energy(&s) / top.energy(&start) - 1.0).abs() < 1e-13);
        let l3 = |s: &GroundTopState| s.l_world.dot(s.world_from_body.normalize() * DVec3::Z);
        assert!(
            (l3(&s) / l3(&start) - 1.0).abs() < 1e-13,
            "{} vs {}",
            l3(&s),
            l3(&start)
        );
    }
}

/// One step that holds both a lift-off and a touchdown reports the earlier
/// one. The rocking body of `tests/contact_sphere.rs` (ball R = 4 cm at
/// 5 cm below the centre of mass, swinging up from θ = −0.5 fast enough
/// to lift off at θ_L, by hand) with a knob at (0, −3 cm, 0) body whose
/// radius puts its touchdown at θ_L ∓ 0.02 (the knob's gap
/// `R + a cos θ − D sin θ − r_k`): one RK4 step of 10 ms spans both
/// (lift-off at 7.1 ms); each instant is located along the same step.
#[test]
fn lift_off_and_touchdown_in_one_step_report_the_earlier() {
    let (m, i, a, r0, theta_s, d) = (1.0, 1e-3, 0.05, 0.04, -0.5f64, 0.03);
    let e = 0.5 * i * 1.1 * G / a + m * G * a;
    let rate2 = |th: f64| 2.0 * (e - m * G * a * th.cos()) / (i + m * a * a * th.sin().powi(2));
    let normal_force = |th: f64| {
        let (s, c) = th.sin_cos();
        let den = i + m * a * a * s * s;
        let acc = m * a * s * (G - a * c * rate2(th)) / den;
        m * (G - a * (c * rate2(th) + s * acc))
    };
    let (theta_lift, t_lift) = common::contact::lift_off_by_hand(theta_s, 0.0, normal_force, rate2);
    let ball = SphereContact::try_new(r0, DVec3::new(0.0, 0.0, -a)).unwrap();
    let plain = GroundTop::try_new(
        m,
        DMat3::from_diagonal(DVec3::splat(i)),
        ball,
        Friction::None,
        G,
    )
    .unwrap();
    let q = DQuat::from_rotation_x(theta_s);
    for offset in [-0.02, 0.02] {
        let theta_k = theta_lift + offset;
        let r_k = r0 + a * theta_k.cos() - d * theta_k.sin();
        let knob = SphereContact::try_new(r_k, DVec3::new(0.0, -d, 0.0)).unwrap();
        let top = plain
            .clone()
            .try_with_other_contacts(&[ContactShape::Sphere(knob)])
            .unwrap();
        let knob_gap = |th: f64| r0 + a * th.cos() - d * th.sin() - r_k;
        let (_, t_knob) =
            common::contact::lift_off_by_hand(theta_s, theta_lift + 0.1, knob_gap, rate2);
        let mut s = top
            .try_state_on_ground(q, DVec3::new(rate2(theta_s).sqrt(), 0.0, 0.0), DVec2::ZERO)
            .unwrap();
        // Measured: 3.6e-6 (touchdown) and 9.3e-6 (lift-off) relative to the
        // hand times: the RK4 continuation's own error over up to 8.5 ms.
        let err = top.try_step(&mut s, 0.0, 1e-2).unwrap_err();
        eprintln!("knob at θ_L {offset:+}: {err} (lift-off by hand {t_lift} s, knob {t_knob} s)");
        if offset < 0.0 {
            assert!(t_knob < t_lift);
            let (time, contact, _) = touchdown(Err::<(), _>(err));
            assert_eq!(contact, 0);
            assert!((time - t_knob).abs() < 1e-5 * t_knob, "{time} vs {t_knob}");
            let gap = top.other_gap(&s, 0).unwrap();
            assert!(gap <= 0.0 && gap > -1e-15, "{gap:e}");
        } else {
            assert!(t_knob > t_lift);
            let DynamicsError::ContactLost { time, normal_force } = err else {
                panic!("{err}")
            };
            assert!((time - t_lift).abs() < 1e-5 * t_lift, "{time} vs {t_lift}");
            assert!(normal_force.abs() < 1e-6, "N = {normal_force}");
            assert!(top.other_gap(&s, 0).unwrap() > 0.0);
        }
    }
}

/// A disk rim as a further contact: its gap is the height of its lowest
/// rim point, and lying flat (no single lowest point) the height of the
/// whole rim, by hand.
#[test]
fn a_disk_rim_as_a_further_contact_has_its_gap_by_hand() {
    use kreisel_dynamics::DiskContact;
    let (rim_r, c) = (0.01, 0.02);
    let rim = DiskContact::try_new(rim_r, DVec3::new(0.0, 0.0, c), DVec3::Z).unwrap();
    let (top, _) = leine_glocker(Friction::None);
    let top = top
        .try_with_other_contacts(&[ContactShape::Disk(rim)])
        .unwrap();
    for tilt in [0.0f64, 0.3] {
        let q = DQuat::from_rotation_x(tilt);
        let s = top
            .try_state_on_ground(q, DVec3::new(1.0, 0.0, 0.0), DVec2::ZERO)
            .unwrap();
        let hand = s.com_world.z + c * tilt.cos() - rim_r * tilt.sin();
        let gap = top.other_gap(&s, 0).unwrap();
        // A few ulps of 3 cm.
        assert!((gap - hand).abs() < 1e-16, "{tilt}: {gap} vs {hand}");
        let rate = top.other_gap_rate(&s, 0).unwrap();
        assert!(rate.is_finite(), "{rate}");
    }
}
