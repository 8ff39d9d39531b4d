//! Rolling without slipping (`Friction::Rolling`) for a body on the ground
//! plane with a spherical contact, against references the model does not
//! compute itself: the energy and Jellett's integral (both conserved by
//! the exact flow, derived in the `contact` module docs), the rolling
//! constraint `v_P = 0` itself, the tilted steady state of a ball-ended top
//! (derived below by hand), a homogeneous ball rolling straight, a
//! lift-off time from the closed form of planar rocking, and the measured
//! order of the integrator.

mod common;

use glam::{DMat3, DQuat, DVec2, DVec3};
use kreisel_dynamics::{
    ContactShape, DiskContact, DynamicsError, Friction, FrictionModel, GroundTop, GroundTopState,
    SphereContact,
};

use common::tippe_top::{A, G, I1, I3, M, R, distance, flat};

/// The tippe top rolling (the centre of mass moves with `v_G = −ω × ρ`).
fn leine_glocker() -> (GroundTop, GroundTopState) {
    common::tippe_top::leine_glocker(Friction::Rolling)
}

fn tippe_top() -> GroundTop {
    leine_glocker().0
}

/// The tilt of the symmetry axis from the vertical, rad.
fn tilt(s: &GroundTopState) -> f64 {
    (s.world_from_body.normalize() * DVec3::Z).z.acos()
}

/// What one run measured: the largest relative changes of E and λ, the
/// largest |v_P| (m/s) and |gap| (m), the smallest normal force (N).
#[derive(Debug)]
struct Run {
    energy: f64,
    jellett: f64,
    slip: f64,
    gap: f64,
    normal_min: f64,
    end: GroundTopState,
}

fn run(top: &GroundTop, mut s: GroundTopState, h: f64, duration: f64) -> Run {
    let (e0, l0) = (top.energy(&s), top.jellett(&s));
    let mut r = Run {
        energy: 0.0,
        jellett: 0.0,
        slip: top.slip_velocity(&s).length(),
        gap: 0.0,
        normal_min: f64::INFINITY,
        end: s,
    };
    top.try_advance(&mut s, 0.0, h, (duration / h).round() as usize, |_, s| {
        r.energy = r.energy.max((top.energy(s) - e0).abs() / e0);
        r.jellett = r.jellett.max((top.jellett(s) - l0).abs() / l0.abs());
        r.slip = r.slip.max(top.slip_velocity(s).length());
        r.gap = r.gap.max(top.gap(s).abs());
        r.normal_min = r.normal_min.min(top.normal_force(s).unwrap());
    })
    .unwrap();
    r.end = s;
    r
}

// Measured (h = 1e-5 s, 2 s, debug build on x86-64): |ΔE|/E 8.1e-14,
// |Δλ|/λ 4.5e-14, |v_P| 8.3e-15 m/s, |gap| 4.3e-16 m, N ≥ 0.0588 N; the
// centre of mass rolls 0.51 m away. Bounds: the issue's 1e-10 for E, λ.
#[test]
fn rolling_tippe_top_conserves_energy_jellett_and_the_constraint() {
    let (top, s) = leine_glocker();
    assert!(top.slip_velocity(&s).length() < 1e-15);
    let r = run(&top, s, 1e-5, 2.0);
    eprintln!("rolling tippe top, h = 1e-5 s, 2 s: {r:?}");
    assert!(r.energy <= 1e-10, "{r:?}");
    assert!(r.jellett <= 1e-10, "{r:?}");
    assert!(r.slip <= 1e-12 && r.gap <= 1e-13, "{r:?}");
    assert!(r.normal_min > 0.0);
    // The centre of mass moved: the contact force has a horizontal part.
    assert!(r.end.com_world.truncate().length() > 1e-4, "{r:?}");
}

/// An asymmetric body (full inertia tensor, sphere centre off every
/// principal axis): λ is not an integral here, the energy still is.
/// Measured (h = 5e-5 s, 2 s): |ΔE|/E 1.2e-11 (1.9e-10 at h = 1e-4),
/// |v_P| 9.7e-13 m/s, |gap| 9.4e-13 m; λ changes by 57 %.
#[test]
fn rolling_asymmetric_body_conserves_energy() {
    let p = DMat3::from_quat(DQuat::from_euler(glam::EulerRot::ZXZ, 0.3, 1.1, -0.7));
    let inertia = p * DMat3::from_diagonal(DVec3::new(2e-4, 3e-4, 4e-4)) * p.transpose();
    let sphere = SphereContact::try_new(0.05, DVec3::new(0.01, -0.005, 0.02)).unwrap();
    let top = GroundTop::try_new(0.5, inertia, sphere, Friction::Rolling, G).unwrap();
    let s = top
        .try_rolling_state_on_ground(DQuat::from_rotation_y(0.4), DVec3::new(3.0, -2.0, 30.0))
        .unwrap();
    let r = run(&top, s, 5e-5, 2.0);
    eprintln!("asymmetric rolling body, h = 5e-5 s, 2 s: {r:?}");
    assert!(r.energy <= 1e-10, "{r:?}");
    assert!(r.slip <= 1e-10 && r.gap <= 1e-11, "{r:?}");
    // λ is not conserved for this body (a check that the run is not trivial).
    assert!(r.jellett > 1e-6, "{r:?}");
}

/// The tilted steady state of a rolling ball-ended top with its centre of
/// mass at rest (the end state of the dissipative models outside the
/// inversion window, Rauch-Wojciechowski et al., SIGMA 10 (2014) 017).
/// Derived by hand: with `ŝ` the axis, tilt `θ`, precession `φ̇` about `ẑ`
/// and spin `ψ̇` about `ŝ`, `ω = φ̇ ẑ + ψ̇ ŝ`, and `ρ = a ŝ − R ẑ`.
/// `ω ∥ ρ` needs `ψ̇ = −α φ̇` (`α = a/R`); then `v_P = v_G = 0`, the
/// centre of mass is at rest, the contact force is `m g ẑ` and its torque
/// `ρ × m g ẑ = −m g a (ẑ × ŝ)`. With `L = I₁ ω + (I₃ − I₁)(ω·ŝ) ŝ`,
/// `ω·ŝ = φ̇ (cos θ − α)`, `ŝ̇ = φ̇ ẑ × ŝ`, `ω̇ = ψ̇ ŝ̇`:
///
/// ```text
/// L̇ = φ̇² [(I₃ − I₁) cos θ − α I₃] (ẑ × ŝ) = −m g a (ẑ × ŝ)
/// φ̇² = m g R α / (α I₃ + (I₁ − I₃) cos θ)
/// ```
///
/// — the issue's formula: it is a rolling state (no slip, so the
/// dissipative models have it too, with zero friction force). A top
/// started exactly there stays there: θ constant, the centre of mass at
/// the origin, the axis turning at φ̇. Measured (h = 1e-4 s, 2 s):
/// θ = 0.6: |Δθ| 3.4e-14 rad, |r_G| 1.3e-14 m, axis 1.2e-12 after 9 turns;
/// θ = 2 (φ̇ < 0): 5.0e-13 rad, 3.1e-13 m, 2.6e-11 after 13.5 turns.
#[test]
fn a_top_started_on_the_steady_rolling_state_stays_there() {
    let top = tippe_top();
    let alpha = A / R;
    for (theta, sign) in [(0.6, 1.0), (2.0, -1.0)] {
        let denom = alpha * I3 + (I1 - I3) * f64::cos(theta);
        assert!(denom > 0.0);
        let phi_dot = sign * (M * G * R * alpha / denom).sqrt();
        let q = DQuat::from_rotation_x(theta);
        let axis = q * DVec3::Z;
        let omega = phi_dot * (DVec3::Z - alpha * axis);
        let mut s = top.try_rolling_state_on_ground(q, omega).unwrap();
        assert!(s.velocity_world.length() < 1e-15);
        let f0 = top.contact_force(&s).unwrap();
        assert!(
            (f0 - DVec3::new(0.0, 0.0, M * G)).length() < 1e-13 * M * G,
            "{f0}"
        );
        let (h, duration) = (1e-4, 2.0);
        let mut worst_theta = 0.0f64;
        let mut worst_com = 0.0f64;
        let t = top
            .try_advance(&mut s, 0.0, h, (duration / h).round() as usize, |_, s| {
                worst_theta = worst_theta.max((tilt(s) - theta).abs());
                worst_com = worst_com.max(s.com_world.truncate().length());
            })
            .unwrap();
        // The axis has turned by φ̇ t about ẑ.
        let end_axis = s.world_from_body.normalize() * DVec3::Z;
        let expected = DQuat::from_rotation_z(phi_dot * t) * axis;
        let axis_err = (end_axis - expected).length();
        eprintln!(
            "steady rolling θ = {theta}, φ̇ = {phi_dot:.6} rad/s ({:.1} turns): |Δθ| {worst_theta:.1e} rad, |r_G,xy| {worst_com:.1e} m, axis {axis_err:.1e}",
            phi_dot.abs() * t / std::f64::consts::TAU
        );
        assert!(worst_theta <= 1e-10, "θ drifts by {worst_theta}");
        assert!(worst_com <= 1e-12, "the centre of mass moves {worst_com}");
        assert!(axis_err <= 1e-9, "{axis_err}");
    }
}

/// A homogeneous ball (`a = 0`, `I = 2/5 m R²`) rolling on the plane,
/// spinning about the vertical too: `L ∥ ω`, no gyroscopic term, the
/// contact force is `m g ẑ` and the motion is uniform — the centre moves
/// at `v = −ω × (−R ẑ)` in a straight line for ever. Measured (h = 1e-3
/// s, 5 s): |Δv| 3.6e-15 m/s, |Δr| 2.1e-13 m, |Δω| 1.0e-14 rad/s.
#[test]
fn a_homogeneous_ball_rolls_straight_at_constant_velocity() {
    let (m, r0) = (0.17, 0.028);
    let ball = SphereContact::try_new(r0, DVec3::ZERO).unwrap();
    let inertia = DMat3::from_diagonal(DVec3::splat(0.4 * m * r0 * r0));
    let top = GroundTop::try_new(m, inertia, ball, Friction::Rolling, G).unwrap();
    let omega = DVec3::new(12.0, -5.0, 40.0);
    let q = DQuat::from_euler(glam::EulerRot::ZXZ, 0.2, 0.9, 1.3);
    let mut s = top.try_rolling_state_on_ground(q, omega).unwrap();
    let v = omega.cross(r0 * DVec3::Z);
    assert!((s.velocity_world - v).length() < 1e-15);
    let (h, steps) = (1e-3, 5000);
    let mut worst_v = 0.0f64;
    let t = top
        .try_advance(&mut s, 0.0, h, steps, |_, s| {
            worst_v = worst_v.max((s.velocity_world - v).length());
        })
        .unwrap();
    let dr = (s.com_world - (DVec3::new(0.0, 0.0, r0) + v * t)).length();
    let dw = (top.omega_world(&s) - omega).length();
    eprintln!("rolling ball, 5 s: |Δv| {worst_v:.1e} m/s, |Δr| {dr:.1e} m, |Δω| {dw:.1e} rad/s");
    assert!(worst_v <= 1e-14, "{worst_v}");
    // Rounding of 5000 position updates of about 1.8 m (ulp 2.2e-16).
    assert!(dr <= 5000.0 * 2.2e-16, "{dr}");
    assert!(dw <= 1e-12, "{dw}");
}

// Measured (t = 0.2 s, h = 4e-4, 2e-4, 1e-4 s): order 3.999,
// |x(h/2) − x(h/4)| 1.5e-8.
#[test]
fn rk4_has_order_four_rolling() {
    let (top, s0) = leine_glocker();
    let l0 = s0.l_world.length();
    let at = |h: f64| {
        let mut s = s0;
        top.try_advance(&mut s, 0.0, h, (0.2 / h).round() as usize, |_, _| {})
            .unwrap();
        flat(&s, l0)
    };
    let (x1, x2, x4) = (at(4e-4), at(2e-4), at(1e-4));
    let order = (distance(&x1, &x2) / distance(&x2, &x4)).log2();
    eprintln!(
        "rolling: order {order:.3}, |x(h/2) − x(h/4)| = {:.2e}",
        distance(&x2, &x4)
    );
    assert!((order - 4.0).abs() < 0.2, "order {order}");
}

/// The drift of the nonholonomic constraint and of the energy at coarse
/// steps, where it rises above rounding: both fall as `h⁴`. Measured over
/// 1 s: max |v_P| 1.9e-10 m/s at h = 2e-4 s, 1.2e-11 at 1e-4 (order 4.00;
/// 8e-15 at 1e-5, rounding); |ΔE|/E 3.4e-11, 2.1e-12 (order 4.00).
#[test]
fn constraint_drift_is_the_methods_error() {
    let (top, s) = leine_glocker();
    let a = run(&top, s, 2e-4, 1.0);
    let b = run(&top, s, 1e-4, 1.0);
    let slip_order = (a.slip / b.slip).log2();
    let energy_order = (a.energy / b.energy).log2();
    eprintln!(
        "drift over 1 s: |v_P| {:.2e} (h = 2e-4) {:.2e} (h = 1e-4) m/s, order {slip_order:.2}; |ΔE|/E {:.2e} {:.2e}, order {energy_order:.2}",
        a.slip, b.slip, a.energy, b.energy
    );
    assert!(slip_order > 3.5, "{slip_order}");
    assert!(energy_order > 3.5, "{energy_order}");
}

/// Planar rocking with rolling, by hand: a body with an isotropic inertia
/// `I`, its centre of mass at `d` above the centre of a sphere of radius
/// `R0`, tilting about x (`θ`) and rolling along y. The sphere's centre
/// stays at height `R0` and moves by `−R0 θ`; the centre of mass is at
/// `y = −R0 θ − d sin θ`, `z = R0 + d cos θ`, so with
/// `J(θ) = I + m (R0² + d² + 2 R0 d cos θ)`:
///
/// ```text
/// E  = ½ J θ̇² + m g (R0 + d cos θ)
/// θ̈  = m d sin θ (g + R0 θ̇²) / J
/// N  = m (g + z̈_G) = m (g − d (cos θ θ̇² + sin θ θ̈))
/// ```
///
/// Started over the top (θ = 0) with `θ̇² = 0.6 g/d` (`N = 0.4 m g`),
/// the body rolls down; `N` falls as `θ̇` grows and reaches zero at θ* ≈
/// 0.95 rad (bisection on the closed form), at `t* = ∫ dθ/θ̇` (Simpson):
/// there the contact must be reported lost. Measured: t = 0.0805266377543
/// s, |t − t*| 1.1e-15 s, |θ − θ*| 2.6e-14 rad, N = −8.9e-16 N.
struct Rocking {
    m: f64,
    i: f64,
    d: f64,
    r0: f64,
    e: f64,
}

impl Rocking {
    fn j(&self, th: f64) -> f64 {
        self.i + self.m * (self.r0.powi(2) + self.d.powi(2) + 2.0 * self.r0 * self.d * th.cos())
    }

    fn rate2(&self, th: f64) -> f64 {
        2.0 * (self.e - self.m * G * (self.r0 + self.d * th.cos())) / self.j(th)
    }

    fn normal_force(&self, th: f64) -> f64 {
        let (s, c) = th.sin_cos();
        let r2 = self.rate2(th);
        let acc = self.m * self.d * s * (G + self.r0 * r2) / self.j(th);
        self.m * (G - self.d * (c * r2 + s * acc))
    }
}

#[test]
fn rolling_lift_off_is_reported_at_the_hand_computed_time() {
    let (m, i, d, r0, theta_s) = (1.0, 1e-3, 0.05, 0.04, 0.0);
    let mut dof = Rocking {
        m,
        i,
        d,
        r0,
        e: 0.0,
    };
    dof.e = 0.5 * dof.j(0.0) * 0.6 * G / d + m * G * (r0 + d);
    let sphere = SphereContact::try_new(r0, DVec3::new(0.0, 0.0, -d)).unwrap();
    let top = GroundTop::try_new(
        m,
        DMat3::from_diagonal(DVec3::splat(i)),
        sphere,
        Friction::Rolling,
        G,
    )
    .unwrap();
    let q = DQuat::from_rotation_x(theta_s);
    let rate = dof.rate2(theta_s).sqrt();
    let mut s = top
        .try_rolling_state_on_ground(q, DVec3::new(rate, 0.0, 0.0))
        .unwrap();
    let centre_of =
        |s: &GroundTopState| s.com_world + s.world_from_body.normalize() * DVec3::new(0.0, 0.0, -d);
    let centre0 = centre_of(&s);
    let n0 = dof.normal_force(theta_s);
    assert!(n0 > 0.0);
    let f0 = top.contact_force(&s).unwrap();
    // Measured: 1e-16 relative.
    assert!((f0.z / n0 - 1.0).abs() < 1e-13, "{} vs {n0}", f0.z);
    assert!(f0.x.abs() < 1e-15 * n0);
    assert!(dof.normal_force(1.2) < 0.0);
    let (theta_star, t_star) = common::contact::lift_off_by_hand(
        theta_s,
        1.2,
        |th| dof.normal_force(th),
        |th| dof.rate2(th),
    );
    let err = top
        .try_advance(&mut s, 0.0, 1e-4, 1000, |_, _| {})
        .unwrap_err();
    let DynamicsError::ContactLost { time, normal_force } = err else {
        panic!("{err}");
    };
    let axis = s.world_from_body.normalize() * DVec3::Z;
    let theta = (-axis.y).atan2(axis.z);
    eprintln!(
        "rolling lift-off at {time} s (t* = {t_star}), θ {theta} vs {theta_star}, N = {normal_force:e}"
    );
    assert!((time - t_star).abs() < 1e-10, "{time} vs {t_star}");
    assert!(normal_force.abs() < 1e-9, "N = {normal_force}");
    assert!((theta - theta_star).abs() < 1e-9, "{theta} vs {theta_star}");
    // The sphere's centre rolled by −R0 (θ − θ_s) along y.
    let moved = centre_of(&s) - centre0;
    assert!(
        (moved.y + r0 * (theta - theta_s)).abs() < 1e-12 && moved.z.abs() < 1e-15,
        "{moved}"
    );
}

#[test]
fn rolling_inputs_and_names() {
    assert_eq!(
        "rolling".parse::<FrictionModel>().unwrap(),
        FrictionModel::Rolling
    );
    assert_eq!(Friction::Rolling.model(), FrictionModel::Rolling);
    let top = tippe_top();
    let q = DQuat::from_rotation_x(0.3);
    let omega = q * DVec3::new(0.0, 0.0, 100.0);
    // A rolling start with slip is refused; the consistent one is accepted
    // by both constructors.
    assert!(matches!(
        top.try_state_on_ground(q, omega, DVec2::ZERO),
        Err(DynamicsError::InvalidState { .. })
    ));
    let s = top.try_rolling_state_on_ground(q, omega).unwrap();
    let again = top
        .try_state_on_ground(q, omega, s.velocity_world.truncate())
        .unwrap();
    assert_eq!(again, s);
    assert!(matches!(
        top.try_rolling_state_on_ground(q, DVec3::new(f64::NAN, 0.0, 0.0)),
        Err(DynamicsError::InvalidState { .. })
    ));
    assert!(matches!(
        top.try_rolling_state_on_ground(DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0), omega),
        Err(DynamicsError::InvalidState { .. })
    ));
}

/// A coin (`DiskContact`: rim radius `a`, axis `e₃`, centre of mass at
/// the centre, `A = m a²/4`, `C = m a²/2`) rolling without slipping.
fn coin(m: f64, a: f64) -> GroundTop {
    let rim = DiskContact::try_new(a, DVec3::ZERO, DVec3::Z).unwrap();
    let inertia = DMat3::from_diagonal(DVec3::new(0.25, 0.25, 0.5) * m * a * a);
    GroundTop::try_with_shape(m, inertia, ContactShape::Disk(rim), Friction::Rolling, G).unwrap()
}

/// The tilt of a disk's plane from the table, rad: the angle of its axis
/// from the vertical.
fn disk_tilt(s: &GroundTopState) -> f64 {
    (s.world_from_body.normalize() * DVec3::Z).z.acos()
}

/// The rolling disk's steady circles, derived by hand. Axis `n` tilted by
/// `α` from the vertical (`q` a turn by α about x: `n = (0, −sin α,
/// cos α)`, the contact at `ρ = a (0, −cos α, −sin α)` from the centre),
/// precessing at `Ω` about `ẑ`, the centre on a horizontal circle of
/// radius `ϱ` about `O = G + ϱ ŷ` (the disk leans towards `O`). With
/// `ω = Ω ẑ + ψ̇ n`, `σ = ω·n`, `v_G = Ω ϱ x̂`: no slip (`v_G + ω × ρ = 0`,
/// `n × û = x̂`, `ẑ × û = cos α x̂`) gives `σ = −Ω ϱ/a`. The contact force
/// is `F = m (g ẑ + Ω² ϱ ŷ)` (centripetal, towards `O`), its torque about G is
/// `(−m g a cos α + m a sin α Ω² ϱ) x̂`; `L = A Ω ẑ + (C σ − A Ω cos α) n`
/// turns with `ṅ = Ω sin α x̂`:
///
/// ```text
/// Ω² sin α [A cos α + (C + m a²) ϱ/a] = m g a cos α
/// ϱ = 0 (centre at rest, Euler's disk):  Ω² sin α = 4 g/a
/// ```
///
/// (the issue's formulas). A coin started there stays there: the tilt
/// constant, the centre on its circle. Measured over 2 s (2 to 26 turns):
/// |Δα| ≤ 3.8e-14 rad, |Δϱ| ≤ 9.6e-15 m, |ΔE|/E ≤ 9.6e-12, |v_P| ≤ 1e-13
/// m/s, the axis at Ω t to ≤ 6e-13.
#[test]
fn a_rolling_coin_started_on_a_steady_circle_stays_there() {
    let (m, a) = (0.02, 0.015);
    let top = coin(m, a);
    let (i1, i3) = (0.25 * m * a * a, 0.5 * m * a * a);
    for (alpha, radius) in [(0.4, 0.0), (1.1, 0.0), (1.2, 0.05), (0.9, 0.02)] {
        let (sa, ca) = f64::sin_cos(alpha);
        let big_omega = (m * G * a * ca / (sa * (i1 * ca + (i3 + m * a * a) * radius / a))).sqrt();
        if radius == 0.0 {
            assert!((big_omega.powi(2) * sa / (4.0 * G / a) - 1.0).abs() < 1e-14);
        }
        let q = DQuat::from_rotation_x(alpha);
        let n = q * DVec3::Z;
        let sigma = -big_omega * radius / a;
        let omega = big_omega * DVec3::Z + (sigma - big_omega * ca) * n;
        let mut s = top.try_rolling_state_on_ground(q, omega).unwrap();
        let centre = s.com_world + DVec3::new(0.0, radius, 0.0);
        assert!((s.velocity_world - DVec3::new(big_omega * radius, 0.0, 0.0)).length() < 1e-15);
        let f0 = top.contact_force(&s).unwrap();
        let f_expected = m * DVec3::new(0.0, big_omega.powi(2) * radius, G);
        assert!(
            (f0 - f_expected).length() < 1e-13 * m * G,
            "{f0} vs {f_expected}"
        );
        // The fastest of the precession Ω, the rate |ω| and the rate ψ̇ at
        // which the contact runs round the rim, times h: 1/1000 (at 1/500
        // and 1/122 the energy is off by 1.9e-10 and 5.4e-8 at α = 0.4:
        // RK4's h⁴).
        let psi_dot = sigma - big_omega * ca;
        let fastest = big_omega.max(omega.length()).max(psi_dot.abs());
        let (h, duration) = (0.001 / fastest, 2.0);
        let e0 = top.energy(&s);
        let (mut worst_tilt, mut worst_circle, mut worst_energy) = (0.0f64, 0.0f64, 0.0f64);
        let t = top
            .try_advance(&mut s, 0.0, h, (duration / h).round() as usize, |_, s| {
                worst_tilt = worst_tilt.max((disk_tilt(s) - alpha).abs());
                let off = (s.com_world - centre).truncate().length();
                worst_circle = worst_circle.max((off - radius).abs());
                worst_energy = worst_energy.max((top.energy(s) / e0 - 1.0).abs());
            })
            .unwrap();
        let expected = DQuat::from_rotation_z(big_omega * t) * n;
        let axis_err = (s.world_from_body.normalize() * DVec3::Z - expected).length();
        eprintln!(
            "coin α = {alpha}, ϱ = {radius}: Ω = {big_omega:.6} rad/s ({:.1} turns), |Δα| {worst_tilt:.1e} rad, |Δϱ| {worst_circle:.1e} m, |ΔE|/E {worst_energy:.1e}, axis {axis_err:.1e}, |v_P| {:.1e} m/s",
            big_omega * t / std::f64::consts::TAU,
            top.slip_velocity(&s).length()
        );
        assert!(worst_tilt <= 1e-10, "α drifts by {worst_tilt}");
        assert!(worst_circle <= 1e-12, "{worst_circle}");
        assert!(worst_energy <= 1e-10, "{worst_energy}");
        assert!(axis_err <= 1e-8, "{axis_err}");
    }
}

#[test]
fn disk_inputs_give_typed_errors() {
    for (r, n) in [
        (0.0, DVec3::Z),
        (0.01, DVec3::ZERO),
        (0.01, DVec3::new(f64::NAN, 0.0, 1.0)),
    ] {
        assert!(matches!(
            DiskContact::try_new(r, DVec3::ZERO, n),
            Err(DynamicsError::InvalidContact { .. })
        ));
    }
    let top = coin(0.02, 0.015);
    assert!(top.sphere().is_none());
    assert!(matches!(top.shape(), ContactShape::Disk(_)));
    // Lying flat, the rim touches everywhere: no contact point to follow.
    assert!(matches!(
        top.try_rolling_state_on_ground(DQuat::IDENTITY, DVec3::new(0.0, 0.0, 5.0)),
        Err(DynamicsError::InvalidState { .. })
    ));
    // A coin falling flat from rest at the tilt α₀ is stopped with an
    // error, never a NaN state or a silent jump of the contact. It pivots
    // about its contact point (rotation about the rim's tangent there):
    // (A + m a²) α̈ = −m g a cos α, so with cos α = 1 − O(α₀²) it lands at
    // t = √(2 α₀ (A + m a²)/(m g a)) = √(2.5 α₀ a/g).
    let (a, alpha0, h) = (0.015, 1e-3, 1e-5);
    let t_flat = (2.5 * alpha0 * a / G).sqrt();
    let q = DQuat::from_rotation_x(alpha0);
    let mut s = top.try_rolling_state_on_ground(q, DVec3::ZERO).unwrap();
    let err = top
        .try_advance(&mut s, 0.0, h, 1_000_000, |_, _| {})
        .unwrap_err();
    eprintln!("coin falling flat: {err} (lands at {t_flat} s)");
    let DynamicsError::DiskFlat { time } = err else {
        panic!("{err}");
    };
    // Measured: the step [1.950, 1.960) ms holds t = 1.9553 ms.
    assert!(
        time <= t_flat && t_flat < time + h + 1e-12,
        "{time} vs {t_flat}"
    );
    assert!(s.is_valid() && disk_tilt(&s) > 0.0);
}

/// Upright straight rolling of a coin is stable only above the speed
/// `V² = g a/3` (the classical criterion for the uniform disk, quoted in
/// the issue):
/// a coin tilted by 1e-4 rad off upright, rolling at `V`, wobbles and
/// within 100 δ at 1.03 times that `V²` (measured over 3 s: 6.8e-3 rad;
/// 2.1e-3 at 1.1 times — the wobble's amplitude goes as
/// `1/(V²/V_c² − 1)`), and at 0.97 times the lean grows out of the linear
/// range, past 1000 δ (measured: 0.19 rad, 0.35 at 0.9 times; the coin
/// then swerves, leaning, without falling within 3 s). The energy holds
/// to 3e-14 in both.
#[test]
fn a_rolling_coin_stays_upright_only_above_the_critical_speed() {
    let (m, a) = (0.02, 0.015);
    let top = coin(m, a);
    let v_critical2 = G * a / 3.0;
    let (delta, h, duration) = (1e-4, 2e-5, 3.0);
    let mut worst = Vec::new();
    for factor in [1.03, 0.97] {
        let speed = (factor * v_critical2).sqrt();
        // Axis along −y when upright, tilted by δ more about x.
        let q = DQuat::from_rotation_x(std::f64::consts::FRAC_PI_2 + delta);
        let omega = (speed / a) * (q * DVec3::Z);
        let mut s = top.try_rolling_state_on_ground(q, omega).unwrap();
        let e0 = top.energy(&s);
        let mut max_lean = 0.0f64;
        let result = top.try_advance(&mut s, 0.0, h, (duration / h).round() as usize, |_, s| {
            max_lean = max_lean.max((disk_tilt(s) - std::f64::consts::FRAC_PI_2).abs());
        });
        let fell = match result {
            Ok(_) => false,
            Err(DynamicsError::DiskFlat { .. } | DynamicsError::ContactLost { .. }) => true,
            Err(e) => panic!("{e}"),
        };
        let energy = (top.energy(&s) / e0 - 1.0).abs();
        eprintln!(
            "coin at V² = {factor} g a/3: largest lean {max_lean:.3e} rad, fell {fell}, |ΔE|/E {energy:.1e}"
        );
        worst.push((max_lean, fell));
        assert!(energy <= 1e-10, "{energy}");
    }
    // Above: a bounded wobble; below: the lean leaves the linear range.
    assert!(!worst[0].1 && worst[0].0 < 100.0 * delta, "{worst:?}");
    assert!(worst[1].1 || worst[1].0 > 1000.0 * delta, "{worst:?}");
}

/// A coin on a frictionless table, the disk equations with a friction law
/// rather than the rolling constraint: the plane pushes only vertically,
/// so the horizontal velocity of the centre of mass and `L_z` (the torque
/// `ρ × N ẑ` has no vertical part) are constant, and the energy is
/// conserved; a viscous table only takes energy away. Measured (h = 1e-5
/// s, 0.5 s): frictionless |ΔE|/E 3.7e-13, v_xy and L_z unchanged to the
/// last bit, |gap| 5.8e-14 m; viscous (μ = 0.5 s/m) E never rose, 93 %
/// lost. Slowly spun (ω = (1, −2, 15) rad/s) the frictionless coin falls
/// to a tilt of 0.008 rad, where the contact runs round the rim at
/// ~ω/tilt: there RK4 at 1e-5 s loses 4e-5 of E and 5e-7 m of gap.
#[test]
fn a_coin_on_a_frictionless_table_keeps_its_horizontal_momentum_and_l_z() {
    let (m, a) = (0.02, 0.015);
    let rim = DiskContact::try_new(a, DVec3::ZERO, DVec3::Z).unwrap();
    let inertia = DMat3::from_diagonal(DVec3::new(0.25, 0.25, 0.5) * m * a * a);
    let q = DQuat::from_rotation_x(0.8);
    // Spun fast about its axis, the coin stays up (the tilt stays above
    // 0.7 rad: away from lying flat, where the contact whips round the rim).
    let omega = q * DVec3::new(0.0, 0.0, 150.0) + DVec3::new(1.0, -2.0, 5.0);
    for friction in [Friction::None, Friction::try_viscous(0.5).unwrap()] {
        let top =
            GroundTop::try_with_shape(m, inertia, ContactShape::Disk(rim), friction, G).unwrap();
        let mut s = top
            .try_state_on_ground(q, omega, DVec2::new(0.2, -0.1))
            .unwrap();
        let (e0, v0, lz0) = (top.energy(&s), s.velocity_world, s.l_world.z);
        let (mut e_max, mut rise, mut dv, mut dlz, mut gap) =
            (0.0f64, 0.0f64, 0.0f64, 0.0f64, 0.0f64);
        let mut e_prev = e0;
        let mut tilt_min = f64::INFINITY;
        let h = 1e-5;
        top.try_advance(&mut s, 0.0, h, 50_000, |_, s| {
            let e = top.energy(s);
            e_max = e_max.max((e / e0 - 1.0).abs());
            rise = rise.max((e - e_prev) / e0);
            e_prev = e;
            dv = dv.max((s.velocity_world - v0).truncate().length());
            dlz = dlz.max((s.l_world.z - lz0).abs() / lz0.abs());
            gap = gap.max(top.gap(s).abs());
            tilt_min = tilt_min.min(disk_tilt(s));
        })
        .unwrap();
        eprintln!(
            "{:?} coin, 0.5 s: |ΔE|/E {e_max:.1e} (largest rise {rise:.1e}), |Δv_xy| {dv:.1e} m/s, |ΔL_z|/L_z {dlz:.1e}, |gap| {gap:.1e} m, tilt ≥ {tilt_min:.3}",
            friction.model()
        );
        assert!(gap <= 1e-12, "{gap}");
        if friction == Friction::None {
            assert!(e_max <= 1e-10, "{e_max}");
            assert!(dv <= 1e-15 && dlz <= 1e-12, "{dv} {dlz}");
        } else {
            assert!(rise <= 0.0, "{rise}");
            assert!(e_max > 1e-3, "{e_max}");
        }
    }
}

/// The general steady rolling of a ball-ended top, by hand: the axis `ŝ`
/// at tilt θ (`q` a turn by θ about x: `ŝ = (0, −sin θ, cos θ)`),
/// precessing at `Ω` about a vertical through `O`, with the centre of mass
/// on a horizontal circle, `G − O = y ŷ`. With `ω = Ω ẑ + ψ̇ ŝ`,
/// `ρ = a ŝ − R ẑ`, `ẑ × ŝ = sin θ x̂`: `ω × ρ = (Ω a + ψ̇ R) sin θ x̂` and
/// `v_G = −Ω y x̂`, so no slip needs `ψ̇ = Ω (y/sin θ − a)/R`. The force is
/// `F = m (g ẑ − Ω² y ŷ)`, its torque about G
/// `(−m g a sin θ + m Ω² y (a cos θ − R)) x̂`, and
/// `L̇ = Ω sin θ (I₃ σ − I₁ Ω cos θ) x̂` with `σ = ω·ŝ = Ω cos θ + ψ̇`:
///
/// ```text
/// Ω² D = −m g a sin θ
/// D = sin θ [I₃ (cos θ − α) − I₁ cos θ] + I₃ y/R − m y (a cos θ − R)
/// ```
///
/// (for `y = 0` the tilted state of the previous test). Started there the
/// top stays: θ constant, G on its circle. Measured over 1 s: |Δθ| ≤ 1.8e-14
/// rad, |Δϱ| ≤ 6.4e-16 m, |ΔE|/E ≤ 1.1e-15; with Ω off by 1e-4 relative,
/// θ wobbles by 1.3e-5 rad (the check has teeth).
#[test]
fn a_rolling_top_precessing_on_a_circle_stays_there() {
    let top = tippe_top();
    let alpha = A / R;
    for (theta, y) in [(0.6, 0.0005), (0.6, -0.004), (1.3, -0.01), (2.0, -0.002)] {
        let (st, ct) = f64::sin_cos(theta);
        let d = st * (I3 * (ct - alpha) - I1 * ct) + I3 * y / R - M * y * (A * ct - R);
        assert!(d < 0.0, "no steady circle at θ = {theta}, y = {y}");
        let big_omega = (-M * G * A * st / d).sqrt();
        let psi_dot = big_omega * (y / st - A) / R;
        let q = DQuat::from_rotation_x(theta);
        let axis = q * DVec3::Z;
        let omega = big_omega * DVec3::Z + psi_dot * axis;
        let mut s = top.try_rolling_state_on_ground(q, omega).unwrap();
        assert!((s.velocity_world - DVec3::new(-big_omega * y, 0.0, 0.0)).length() < 1e-15);
        let centre = s.com_world - DVec3::new(0.0, y, 0.0);
        let fastest = big_omega.max(omega.length());
        let (h, duration) = (0.001 / fastest, 1.0);
        let e0 = top.energy(&s);
        let (mut worst_theta, mut worst_circle, mut worst_energy) = (0.0f64, 0.0f64, 0.0f64);
        top.try_advance(&mut s, 0.0, h, (duration / h).round() as usize, |_, s| {
            worst_theta = worst_theta.max((tilt(s) - theta).abs());
            let off = (s.com_world - centre).truncate().length();
            worst_circle = worst_circle.max((off - y.abs()).abs());
            worst_energy = worst_energy.max((top.energy(s) / e0 - 1.0).abs());
        })
        .unwrap();
        eprintln!(
            "rolling top on a circle θ = {theta}, y = {y}: Ω = {big_omega:.5} rad/s, ψ̇ = {psi_dot:.3} rad/s: |Δθ| {worst_theta:.1e} rad, |Δϱ| {worst_circle:.1e} m, |ΔE|/E {worst_energy:.1e}"
        );
        assert!(worst_theta <= 1e-10, "θ drifts by {worst_theta}");
        assert!(worst_circle <= 1e-12, "{worst_circle}");
        assert!(worst_energy <= 1e-10, "{worst_energy}");
    }
}
