//! A ball-ended top on the ground plane (`kreisel_dynamics::GroundTop`)
//! against references it does not compute itself: Jellett's integral and
//! the energy (conserved or dissipated by the exact flow, derived in the
//! `contact` module docs), the constraint's residual, the final spin
//! after inversion from λ (`ω_z = ω₀ (cos θ₀ − α)/(1 + α)`), Leine &
//! Glocker's published inversion time, a lift-off time from the closed
//! form of a one-degree-of-freedom reduction, and the measured order of
//! the integrator.

mod common;

use glam::{DMat3, DQuat, DVec2, DVec3};
use kreisel_dynamics::{
    DynamicsError, Friction, FrictionModel, GroundTop, GroundTopState, SphereContact,
};

use common::tippe_top::{A, G, I1, I3, M, OMEGA0, R, THETA0, distance, flat, leine_glocker};

/// The height of the unit symmetry axis' tip (towards the stem): cos θ.
fn axis_z(s: &GroundTopState) -> f64 {
    (s.world_from_body.normalize() * DVec3::Z).z
}

/// What one run measured.
#[derive(Debug)]
struct Run {
    /// max |λ − λ₀|/|λ₀|.
    jellett: f64,
    /// max |E − E₀|/E₀.
    energy: f64,
    /// The largest one-step rise of E, relative to E₀ (≤ 0: never rose).
    energy_rise: f64,
    /// max |gap| (m) and max |ġap| (m/s).
    gap: f64,
    gap_rate: f64,
    /// The first time the axis passes the horizontal going down (linear
    /// interpolation between steps), s.
    inverted_at: Option<f64>,
    end: GroundTopState,
}

fn run(top: &GroundTop, mut s: GroundTopState, h: f64, duration: f64) -> Run {
    let (e0, l0) = (top.energy(&s), top.jellett(&s));
    let mut r = Run {
        jellett: 0.0,
        energy: 0.0,
        energy_rise: f64::NEG_INFINITY,
        gap: 0.0,
        gap_rate: 0.0,
        inverted_at: None,
        end: s,
    };
    let (mut e_prev, mut z_prev) = (e0, axis_z(&s));
    let steps = (duration / h).round() as usize;
    top.try_advance(&mut s, 0.0, h, steps, |t, s| {
        let e = top.energy(s);
        r.energy = r.energy.max((e - e0).abs() / e0);
        r.energy_rise = r.energy_rise.max((e - e_prev) / e0);
        e_prev = e;
        r.jellett = r.jellett.max((top.jellett(s) - l0).abs() / l0.abs());
        r.gap = r.gap.max(top.gap(s).abs());
        r.gap_rate = r.gap_rate.max(top.gap_rate(s).abs());
        let z = axis_z(s);
        if r.inverted_at.is_none() && z_prev > 0.0 && z <= 0.0 {
            r.inverted_at = Some(t - h * z / (z - z_prev));
        }
        z_prev = z;
    })
    .unwrap();
    r.end = s;
    r
}

/// The spin after a full inversion, from Jellett's integral.
fn final_spin_formula() -> f64 {
    let alpha = A / R;
    OMEGA0 * (THETA0.cos() - alpha) / (1.0 + alpha)
}

// Measured (h = 1e-5 s, 1 s): |ΔE|/E 1.3e-15, |Δλ|/λ 4.2e-16,
// |gap| 2.1e-16 m, |ġap| 5.6e-16 m/s.
#[test]
fn frictionless_top_conserves_energy_and_jellett() {
    let (top, s) = leine_glocker(Friction::None);
    let r = run(&top, s, 1e-5, 1.0);
    eprintln!("none: {r:?}");
    assert!(r.energy <= 1e-10, "{r:?}");
    assert!(r.jellett <= 1e-10, "{r:?}");
    assert!(r.gap <= 1e-12 && r.gap_rate <= 1e-12, "{r:?}");
    // Without friction the tilt cannot rise past the horizontal.
    assert!(r.inverted_at.is_none(), "{r:?}");
}

// Measured (h = 1e-5 s, 4 s): inverted at 2.709448 s (2.709448 at
// h = 2e-5: 2e-8 s apart); |Δλ|/λ 2.6e-13; the energy fell in every step
// (largest step change −1.0e-10 E₀), 49 % lost; |gap| 1.6e-14 m,
// |ġap| 9.9e-15 m/s.
#[test]
fn sliding_tippe_top_inverts_at_leine_glockers_time() {
    let (top, s) = leine_glocker(Friction::try_sliding(0.3, 1e-3).unwrap());
    let r = run(&top, s, 1e-5, 4.0);
    eprintln!("sliding: {r:?}");
    assert!(r.jellett <= 1e-10, "{r:?}");
    assert!(r.energy_rise <= 0.0, "{r:?}");
    assert!(r.gap <= 1e-11 && r.gap_rate <= 1e-11, "{r:?}");
    // Leine & Glocker's 2.7 s (at ε = 1 mm/s, two digits published).
    let t = r.inverted_at.expect("the tippe top inverts");
    assert!((t - 2.7).abs() < 0.05, "inverted at {t} s");
    // The same time at twice the step: converged in h.
    let r2 = run(&top, s, 2e-5, 3.0);
    let t2 = r2.inverted_at.unwrap();
    eprintln!("sliding inversion at h = 1e-5: {t}, at 2e-5: {t2}");
    assert!((t2 - t).abs() < 1e-6, "{t} vs {t2}");
}

// Measured (h = 2e-5 s, 20 s): inverted at 5.14604 s, axis at cos θ =
// −0.99939 at 20 s, ω_z = 119.2447 rad/s vs 119.2506 from λ (4.9e-5
// relative, 1 + cos θ = 6.1e-4); |Δλ|/λ 5.4e-14, the energy fell in every
// step, |gap| 2.1e-12 m, |ġap| 1.5e-13 m/s.
#[test]
fn viscous_tippe_top_inverts_to_the_spin_jellett_predicts() {
    let (top, s) = leine_glocker(Friction::try_viscous(0.3).unwrap());
    let r = run(&top, s, 2e-5, 20.0);
    eprintln!("viscous: {r:?}, ω {:?}", top.omega_world(&r.end));
    assert!(r.jellett <= 1e-10, "{r:?}");
    assert!(r.energy_rise <= 0.0, "{r:?}");
    assert!(r.gap <= 1e-10 && r.gap_rate <= 1e-10, "{r:?}");
    let t = r.inverted_at.expect("the tippe top inverts");
    assert!(t > 1.0 && t < 10.0, "inverted at {t} s");
    // Nearly fully inverted: the formula's premise (θ = π, ω ∥ ẑ) holds to
    // 1 + cos θ; the spin matches it to that order.
    let cos_theta = axis_z(&r.end);
    assert!(1.0 + cos_theta < 1e-3, "cos θ = {cos_theta}");
    let w = top.omega_world(&r.end);
    let rel = (w.z / final_spin_formula() - 1.0).abs();
    assert!(
        rel < 2.0 * (1.0 + cos_theta),
        "ω_z {} vs {}",
        w.z,
        final_spin_formula()
    );
    // The body-frame spin changed sign.
    let spin_body = (r.end.world_from_body.normalize().conjugate() * w).z;
    assert!(spin_body < 0.0);
}

/// A one-degree-of-freedom check of the normal force and of lift-off: a
/// body with an isotropic inertia `I`, its centre of mass at `a` above the
/// centre of a sphere of radius `R0`, frictionless, tilting about x in the
/// plane x = 0 with its centre of mass at fixed x, y. With `θ` the tilt,
/// by hand (energy, `z_G = R0 + a cos θ`):
///
/// ```text
/// θ̇² = 2 (E − m g a cos θ)/(I + m a² sin²θ)
/// θ̈  = m a sin θ (g − a cos θ θ̇²)/(I + m a² sin²θ)
/// N  = m (g + z̈_G) = m (g − a (cos θ θ̇² + sin θ θ̈))
/// ```
///
/// `E` is set so that `θ̇² = 1.1 g/a` at the top (θ = 0), where
/// `N = −0.1 m g`: coming up from θ = −0.5 the contact must lift off at
/// the root θ* of N(θ) < 0, at `t* = ∫ dθ/θ̇` (Simpson).
struct OneDof {
    m: f64,
    i: f64,
    a: f64,
    e: f64,
}

impl OneDof {
    fn rate2(&self, th: f64) -> f64 {
        2.0 * (self.e - self.m * G * self.a * th.cos())
            / (self.i + self.m * self.a * self.a * th.sin().powi(2))
    }

    fn normal_force(&self, th: f64) -> f64 {
        let (s, c) = th.sin_cos();
        let d = self.i + self.m * self.a * self.a * s * s;
        let r2 = self.rate2(th);
        let acc = self.m * self.a * s * (G - self.a * c * r2) / d;
        self.m * (G - self.a * (c * r2 + s * acc))
    }
}

#[test]
fn lift_off_is_reported_at_the_hand_computed_time() {
    let (m, i, a, r0, theta_s) = (1.0, 1e-3, 0.05, 0.04, -0.5);
    let dof = OneDof {
        m,
        i,
        a,
        e: 0.5 * i * 1.1 * G / a + m * G * a,
    };
    let sphere = SphereContact::try_new(r0, DVec3::new(0.0, 0.0, -a)).unwrap();
    let top = GroundTop::try_new(
        m,
        DMat3::from_diagonal(DVec3::splat(i)),
        sphere,
        Friction::None,
        G,
    )
    .unwrap();
    let q = DQuat::from_rotation_x(theta_s);
    let rate = dof.rate2(theta_s).sqrt();
    let mut s = top
        .try_state_on_ground(q, DVec3::new(rate, 0.0, 0.0), DVec2::ZERO)
        .unwrap();
    // The normal force at the start, by hand.
    let n0 = dof.normal_force(theta_s);
    assert!(n0 > 0.0);
    assert!((top.normal_force(&s).unwrap() / n0 - 1.0).abs() < 1e-13);
    // θ* by bisection on the closed form, t* by Simpson's rule.
    let (theta_star, t_star) = common::contact::lift_off_by_hand(
        theta_s,
        0.0,
        |th| dof.normal_force(th),
        |th| dof.rate2(th),
    );
    let err = top
        .try_advance(&mut s, 0.0, 1e-4, 1000, |_, _| {})
        .unwrap_err();
    let DynamicsError::ContactLost { time, normal_force } = err else {
        panic!("{err}");
    };
    eprintln!("lift-off at {time} s (t* = {t_star}), N = {normal_force:e}");
    // Measured: t = 7.140174e-3 s, |t − t*| = 2.4e-15 s.
    assert!((time - t_star).abs() < 1e-10, "{time} vs {t_star}");
    assert!(normal_force.abs() < 1e-9, "N = {normal_force}");
    let axis = s.world_from_body.normalize() * DVec3::Z;
    let theta = (-axis.y).atan2(axis.z);
    assert!((theta - theta_star).abs() < 1e-9, "{theta} vs {theta_star}");
    // The state is left at lift-off, touching.
    assert!(top.gap(&s).abs() < 1e-12);
}

#[test]
fn bad_input_gives_typed_errors() {
    let sphere = SphereContact::try_new(R, DVec3::new(0.0, 0.0, A)).unwrap();
    let inertia = DMat3::from_diagonal(DVec3::new(I1, I1, I3));
    let bad = [
        GroundTop::try_new(M, inertia, sphere, Friction::Viscous { mu: -0.3 }, G),
        GroundTop::try_new(
            M,
            inertia,
            sphere,
            Friction::Sliding {
                mu: 0.3,
                slip_velocity: 0.0,
            },
            G,
        ),
        GroundTop::try_new(0.0, inertia, sphere, Friction::None, G),
        GroundTop::try_new(M, inertia, sphere, Friction::None, -G),
        GroundTop::try_new(
            M,
            DMat3::from_diagonal(DVec3::new(I1, -I1, I3)),
            sphere,
            Friction::None,
            G,
        ),
    ];
    for b in bad {
        assert!(
            matches!(b, Err(DynamicsError::InvalidContact { .. })),
            "{b:?}"
        );
    }
    for r in [0.0, -R, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            SphereContact::try_new(r, DVec3::ZERO),
            Err(DynamicsError::InvalidContact {
                parameter: "radius",
                ..
            })
        ));
    }
    assert!(matches!(
        Friction::try_viscous(-1.0),
        Err(DynamicsError::InvalidContact {
            parameter: "mu",
            ..
        })
    ));
    assert!(matches!(
        "coulomb".parse::<FrictionModel>(),
        Err(DynamicsError::UnknownFriction { .. })
    ));
    // Non-finite states and steps.
    let (top, s) = leine_glocker(Friction::None);
    assert!(matches!(
        top.try_state_on_ground(
            DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0),
            DVec3::ZERO,
            DVec2::ZERO
        ),
        Err(DynamicsError::InvalidState { .. })
    ));
    assert!(matches!(
        top.try_state_on_ground(DQuat::IDENTITY, DVec3::new(f64::NAN, 0.0, 0.0), DVec2::ZERO),
        Err(DynamicsError::InvalidState { .. })
    ));
    let mut broken = s;
    broken.l_world.x = f64::INFINITY;
    assert!(matches!(
        top.try_step(&mut broken, 0.0, 1e-4),
        Err(DynamicsError::InvalidState { .. })
    ));
    assert!(matches!(
        top.normal_force(&broken),
        Err(DynamicsError::InvalidState { .. })
    ));
    let mut ok = s;
    for h in [0.0, -1e-4, f64::NAN] {
        assert!(matches!(
            top.try_step(&mut ok, 0.0, h),
            Err(DynamicsError::InvalidStep { .. })
        ));
    }
    assert_eq!(ok, s);
    // A step far too large for the method ends non-finite or lifts off:
    // an error either way, never a silent number.
    let mut wild = s;
    let mut failed = false;
    for n in 0..10_000 {
        if top.try_step(&mut wild, n as f64, 1.0).is_err() {
            failed = true;
            break;
        }
    }
    assert!(failed);
}

// Measured (t = 0.2 s, h = 1e-4, 5e-5, 2.5e-5 s): order 4.000 (viscous),
// 4.146 (sliding, ε = 1 mm/s); |x(h/2) − x(h/4)| 5.7e-11 and 1.4e-10.
#[test]
fn rk4_has_order_four_on_the_tippe_top() {
    for friction in [
        Friction::try_viscous(0.3).unwrap(),
        Friction::try_sliding(0.3, 1e-3).unwrap(),
    ] {
        let (top, s0) = leine_glocker(friction);
        let l0 = s0.l_world.length();
        let at = |h: f64| {
            let mut s = s0;
            top.try_advance(&mut s, 0.0, h, (0.2 / h).round() as usize, |_, _| {})
                .unwrap();
            flat(&s, l0)
        };
        let (x1, x2, x4) = (at(1e-4), at(5e-5), at(2.5e-5));
        let order = (distance(&x1, &x2) / distance(&x2, &x4)).log2();
        eprintln!(
            "{:?}: order {order:.3}, |x(h/2) − x(h/4)| = {:.2e}",
            friction.model(),
            distance(&x2, &x4)
        );
        assert!((order - 4.0).abs() < 0.2, "{friction:?}: order {order}");
    }
}

/// Painlevé's paradox by hand: an isotropic body (inertia `I`), upright,
/// not turning, its sphere's centre at `c = (d, 0, 0)` from the centre of
/// mass, sliding along +x with friction `μ` far above `ε`: `e = ẑ − μ x̂`,
/// `ρ = (d, 0, −R)`, and the coefficient of `N` is
///
/// ```text
/// κ = 1/m + ((ρ × e) × c)_z / I = 1/m − (R μ − d) d / I
/// ```
///
/// negative for `μ = 2` (κ = −24 /kg): no normal force keeps the contact.
#[test]
fn painleve_contact_is_a_typed_error() {
    let (m, i, d, r0, mu) = (1.0, 1e-4, 0.05, 0.05, 2.0);
    let kappa = 1.0 / m - (r0 * mu - d) * d / i;
    let sphere = SphereContact::try_new(r0, DVec3::new(d, 0.0, 0.0)).unwrap();
    let friction = Friction::try_sliding(mu, 1e-9).unwrap();
    let top = GroundTop::try_new(
        m,
        DMat3::from_diagonal(DVec3::splat(i)),
        sphere,
        friction,
        G,
    )
    .unwrap();
    let mut s = top
        .try_state_on_ground(DQuat::IDENTITY, DVec3::ZERO, DVec2::new(1.0, 0.0))
        .unwrap();
    let Err(DynamicsError::ContactIndeterminate { compliance, .. }) = top.normal_force(&s) else {
        panic!("no Painlevé error");
    };
    assert!(
        (compliance / kappa - 1.0).abs() < 1e-12,
        "{compliance} vs {kappa}"
    );
    let start = s;
    let err = top.try_step(&mut s, 0.5, 1e-4).unwrap_err();
    assert!(
        matches!(err, DynamicsError::ContactIndeterminate { time: 0.5, .. }),
        "{err}"
    );
    assert_eq!(s, start);
    // Sliding the other way, friction helps: κ = 1/m + (R μ + d) d / I > 0.
    let back = top
        .try_state_on_ground(DQuat::IDENTITY, DVec3::ZERO, DVec2::new(-1.0, 0.0))
        .unwrap();
    assert!(top.normal_force(&back).is_ok());
}

/// The equations hold in any body frame: the symmetric top described in
/// body axes turned by `P` (inertia `P I Pᵀ`, a full tensor; sphere centre
/// `P c`; attitude `q P⁻¹`) moves the same in the world.
#[test]
fn a_full_inertia_tensor_in_turned_body_axes_moves_the_same() {
    let (top, s) = leine_glocker(Friction::try_sliding(0.3, 1e-3).unwrap());
    let p = DQuat::from_euler(glam::EulerRot::ZXZ, 0.3, 1.1, -0.7);
    let pm = DMat3::from_quat(p);
    let turned = GroundTop::try_new(
        M,
        pm * top.inertia_body() * pm.transpose(),
        SphereContact::try_new(R, p * DVec3::new(0.0, 0.0, A)).unwrap(),
        top.friction(),
        G,
    )
    .unwrap();
    let mut a = s;
    let mut b = GroundTopState {
        world_from_body: s.world_from_body * p.conjugate(),
        ..s
    };
    assert!((turned.normal_force(&b).unwrap() / top.normal_force(&a).unwrap() - 1.0).abs() < 1e-13);
    top.try_advance(&mut a, 0.0, 1e-5, 20_000, |_, _| {})
        .unwrap();
    turned
        .try_advance(&mut b, 0.0, 1e-5, 20_000, |_, _| {})
        .unwrap();
    // Measured: 6.9e-17 m and 5.6e-15 relative after 0.2 s (rounding only).
    let dr = (a.com_world - b.com_world).length();
    let dl = (a.l_world - b.l_world).length() / a.l_world.length();
    eprintln!("turned body axes: |Δr_G| {dr:.1e} m, |ΔL|/|L| {dl:.1e}");
    assert!(dr < 1e-12 && dl < 1e-10, "{dr} {dl}");
    let axis_a = a.world_from_body.normalize() * DVec3::new(0.0, 0.0, 1.0);
    let axis_b = b.world_from_body.normalize() * (p * DVec3::new(0.0, 0.0, 1.0));
    assert!((axis_a - axis_b).length() < 1e-10);
}

/// One row of `tests/data/contact/tippe_top_*.csv`
/// (`python3 tests/data/gen/tippe_top.py`: Newton–Euler in body axes with
/// `(v̇, ω̇, N)` from one linear solve, scipy's DOP853 at rtol 1e-13).
struct Reference {
    event: String,
    t: f64,
    state: GroundTopState,
}

fn references(name: &str) -> Vec<Reference> {
    let path = format!(
        "{}/../../tests/data/contact/tippe_top_{name}.csv",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    text.lines()
        .skip(1)
        .map(|line| {
            let f: Vec<&str> = line.split(',').collect();
            let x: Vec<f64> = f[1..].iter().map(|v| v.parse().unwrap()).collect();
            Reference {
                event: f[0].to_string(),
                t: x[0],
                state: GroundTopState {
                    com_world: DVec3::new(x[1], x[2], x[3]),
                    velocity_world: DVec3::new(x[4], x[5], x[6]),
                    world_from_body: DQuat::from_xyzw(x[8], x[9], x[10], x[7]),
                    l_world: DVec3::new(x[11], x[12], x[13]),
                },
            }
        })
        .collect()
}

/// The largest differences to the generator over its samples (position m,
/// velocity m/s, attitude rad, L relative) and the inversion times.
fn against_generator(name: &str, friction: Friction, h: f64) -> ([f64; 4], f64, f64) {
    let refs = references(name);
    let (top, s0) = leine_glocker(friction);
    let t_ref = refs.iter().find(|r| r.event == "inverted").unwrap().t;
    let samples: Vec<&Reference> = refs.iter().filter(|r| r.event == "sample").collect();
    let duration = samples.last().unwrap().t;
    let mut worst = [0.0f64; 4];
    let mut next = 0;
    let mut s = s0;
    let mut z_prev = axis_z(&s);
    let mut inverted = None;
    top.try_advance(&mut s, 0.0, h, (duration / h).round() as usize, |t, s| {
        let z = axis_z(s);
        if inverted.is_none() && z_prev > 0.0 && z <= 0.0 {
            inverted = Some(t - h * z / (z - z_prev));
        }
        z_prev = z;
        if next < samples.len() && (t - samples[next].t).abs() < 0.5 * h {
            let r = &samples[next].state;
            let dq = s.world_from_body.normalize().conjugate() * r.world_from_body.normalize();
            let d = [
                (s.com_world - r.com_world).length(),
                (s.velocity_world - r.velocity_world).length(),
                2.0 * dq.xyz().length().asin(),
                (s.l_world - r.l_world).length() / r.l_world.length(),
            ];
            for (w, x) in worst.iter_mut().zip(d) {
                *w = w.max(x);
            }
            next += 1;
        }
    })
    .unwrap();
    assert_eq!(next, samples.len());
    (worst, inverted.unwrap(), t_ref)
}

// Measured against the generator (its own rtol 1e-11 vs 1e-13 runs move
// the inversion by 1e-12 s): viscous, h = 2e-5 s: inverted at 5.14604380 s
// vs 5.14604379 s (1.1e-9 relative), over 0.5…6 s worst |Δr_G| 2.5e-13 m,
// |Δv_G| 2.0e-12 m/s, attitude 1.1e-10 rad, |ΔL|/|L| 1.9e-12; sliding
// (ε = 1 mm/s), h = 1e-5 s: 2.709448333 s vs 2.709448330 s (1.2e-9),
// 5.6e-12 m, 1.2e-10 m/s, 4.3e-9 rad, 1.9e-10. The state bounds below
// are the RK4 error at these steps (order 4 measured), with a margin of
// about 5 for other platforms' rounding of the trigonometry.
#[test]
fn inversion_matches_an_independent_generator() {
    for (name, friction, h) in [
        ("viscous", Friction::try_viscous(0.3).unwrap(), 2e-5),
        ("sliding", Friction::try_sliding(0.3, 1e-3).unwrap(), 1e-5),
    ] {
        let (worst, t, t_ref) = against_generator(name, friction, h);
        eprintln!(
            "{name}: inverted at {t} s vs {t_ref} s ({:.1e} relative); worst |Δr_G| {:.1e} m, |Δv_G| {:.1e} m/s, attitude {:.1e} rad, |ΔL|/|L| {:.1e}",
            (t / t_ref - 1.0).abs(),
            worst[0],
            worst[1],
            worst[2],
            worst[3]
        );
        assert!((t / t_ref - 1.0).abs() <= 1e-6, "{name}: {t} vs {t_ref}");
        assert!(
            worst[0] <= 3e-11 && worst[1] <= 1e-9 && worst[2] <= 2e-8 && worst[3] <= 1e-9,
            "{name}: {worst:?}"
        );
    }
}

/// Outside the inversion window (`I₁/I₃ = 4/3 > 1 + α = 1.2`) the viscous
/// top does not invert: it settles tilted, rolling without slip, where
/// (Rauch-Wojciechowski & co., SIGMA 10 (2014) 017) the tilt θ and the
/// precession rate φ̇ solve
///
/// ```text
/// φ̇² = m g R α / (α I₃ + (I₁ − I₃) cos θ)
/// |λ| = |φ̇| R [I₁ sin²θ + I₃ (cos θ − α)²]
/// ```
///
/// with λ the (conserved) Jellett integral of the start.
#[test]
fn outside_the_window_the_top_settles_on_the_tilted_rolling_state() {
    let i3 = 6e-7;
    let sphere = SphereContact::try_new(R, DVec3::new(0.0, 0.0, A)).unwrap();
    let inertia = DMat3::from_diagonal(DVec3::new(I1, I1, i3));
    let top =
        GroundTop::try_new(M, inertia, sphere, Friction::try_viscous(0.3).unwrap(), G).unwrap();
    let q = DQuat::from_rotation_x(THETA0);
    let mut s = top
        .try_state_on_ground(q, q * DVec3::new(0.0, 0.0, OMEGA0), DVec2::ZERO)
        .unwrap();
    let lambda = top.jellett(&s).abs();
    let alpha = A / R;
    let rate = |th: f64| (M * G * R * alpha / (alpha * i3 + (I1 - i3) * th.cos())).sqrt();
    let residual =
        |th: f64| rate(th) * R * (I1 * th.sin().powi(2) + i3 * (th.cos() - alpha).powi(2)) - lambda;
    // The root in (90°, 125°): residual < 0 at 90°, > 0 at 125° (measured).
    let (mut lo, mut hi) = (90f64.to_radians(), 125f64.to_radians());
    assert!(residual(lo) < 0.0 && residual(hi) > 0.0);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if residual(mid) < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let theta_star = lo;
    let h = 4e-5;
    top.try_advance(&mut s, 0.0, h, (60.0 / h).round() as usize, |_, _| {})
        .unwrap();
    let axis = s.world_from_body.normalize() * DVec3::Z;
    let theta = axis.z.acos();
    // φ̇: the turning rate of the axis' horizontal projection.
    let d_axis = top.omega_world(&s).cross(axis);
    let phi_dot = (axis.x * d_axis.y - axis.y * d_axis.x) / (axis.x.powi(2) + axis.y.powi(2));
    let slip = top.slip_velocity(&s).length();
    // Measured (h = 4e-5 s, 60 s): θ = 2.0993037221 vs 2.0993037229 rad
    // (7e-10 rad, 120.28°), φ̇ = 96.0229210 vs 96.0229210 rad/s (4e-10
    // relative), slip 6.8e-10 m/s, still decaying by ×4.5 every 5 s.
    eprintln!(
        "tilted end state at 60 s: θ {theta} vs {theta_star} rad, φ̇ {phi_dot} vs {} rad/s, slip {slip:.1e} m/s",
        rate(theta_star)
    );
    assert!(slip < 1e-8, "still slipping at {slip} m/s");
    assert!((theta - theta_star).abs() < 1e-6, "{theta} vs {theta_star}");
    assert!((phi_dot.abs() / rate(theta_star) - 1.0).abs() < 1e-6);
}

/// Inside the window (`I₁/I₃ = 8/7`), the threshold of full inversion:
/// `λ_thres = √(m g R³ I₃ α) (1 + α)² / √(1 + α − I₁/I₃)` (SIGMA 10 (2014)
/// 017), reached here at the spin `ω_thres = λ_thres / (I₃ (R cos θ₀ − a))`
/// (λ of a spin about the axis, by hand). At 0.9 ω_thres the top settles
/// on the tilted rolling state (the root of the equations of the previous
/// test, which has one there); at 1.1 ω_thres, where those equations have
/// no root, it turns over fully.
#[test]
fn the_inversion_threshold_separates_tilted_and_inverted_ends() {
    let alpha = A / R;
    let lambda_thres = (M * G * R.powi(3) * I3 * alpha).sqrt() * (1.0 + alpha).powi(2)
        / (1.0 + alpha - I1 / I3).sqrt();
    let omega_thres = lambda_thres / (I3 * (R * THETA0.cos() - A));
    let rate = |th: f64| (M * G * R * alpha / (alpha * I3 + (I1 - I3) * th.cos())).sqrt();
    let residual = |th: f64, lambda: f64| {
        rate(th) * R * (I1 * th.sin().powi(2) + I3 * (th.cos() - alpha).powi(2)) - lambda
    };
    let (top, _) = leine_glocker(Friction::try_viscous(0.3).unwrap());
    let q = DQuat::from_rotation_x(THETA0);
    let h = 4e-5;
    let mut ends = Vec::new();
    for (factor, duration) in [(0.9, 80.0), (1.1, 40.0)] {
        let mut s = top
            .try_state_on_ground(
                q,
                q * DVec3::new(0.0, 0.0, factor * omega_thres),
                DVec2::ZERO,
            )
            .unwrap();
        let lambda = top.jellett(&s);
        assert!((lambda / (factor * lambda_thres) - 1.0).abs() < 1e-14);
        top.try_advance(&mut s, 0.0, h, (duration / h).round() as usize, |_, _| {})
            .unwrap();
        let theta = (s.world_from_body.normalize() * DVec3::Z).z.acos();
        // Sign changes of the residual on a 0.5° grid over (0, π).
        let grid: Vec<f64> = (1..360).map(|k| (k as f64 * 0.5).to_radians()).collect();
        let roots: Vec<f64> = grid
            .windows(2)
            .filter(|w| residual(w[0], lambda).signum() != residual(w[1], lambda).signum())
            .map(|w| w[0])
            .collect();
        ends.push((factor, theta, roots));
    }
    eprintln!("ω_thres {omega_thres} rad/s, λ_thres {lambda_thres:e}; ends {ends:?}");
    let (_, theta_below, roots_below) = &ends[0];
    assert_eq!(roots_below.len(), 1, "{roots_below:?}");
    let (mut lo, mut hi) = (roots_below[0], roots_below[0] + 0.5f64.to_radians());
    let lambda_below = 0.9 * lambda_thres;
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if residual(lo, lambda_below).signum() == residual(mid, lambda_below).signum() {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    // Measured (h = 4e-5 s): ω_thres = 120.35 rad/s; at 0.9 ω_thres after
    // 80 s θ = 2.7229557 vs 2.7229562 rad (156.01°; 5e-7 rad, still
    // settling); at 1.1 ω_thres after 40 s θ = 3.1025 rad (177.8°).
    eprintln!("below: θ {theta_below} vs tilted state {lo} rad");
    assert!((theta_below - lo).abs() < 1e-4, "{theta_below} vs {lo}");
    let (_, theta_above, roots_above) = &ends[1];
    assert!(roots_above.is_empty(), "{roots_above:?}");
    assert!(*theta_above > 175f64.to_radians(), "{theta_above}");
}
