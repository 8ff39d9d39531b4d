//! Applied torques and forces on a body on the ground
//! (`GroundTop::try_with_inputs`), against what the model does not compute
//! itself: the energy balance `E(T) − E(0) = ∫ P dt` with the inputs'
//! power (rolling: the contact does no work), a closed-form push, and
//! Moffatt's finite-time law for Euler's disk (Nature 404 (2000) 833)
//! under a dissipation of his form, derived below.

mod common;

use glam::{DMat3, DQuat, DVec2, DVec3};
use kreisel_dynamics::{
    ContactShape, DiskContact, DynamicsError, ForcedState, Friction, GroundTop, GroundTopState,
    Inputs, RigidBody, SphereContact,
};

use common::tippe_top::{G, leine_glocker};

/// A thin disk (Euler's disk) of mass `m`, radius `a`: `A = m a²/4`,
/// `C = m a²/2`, rolling without slipping on its rim.
fn euler_disk(m: f64, a: f64) -> GroundTop {
    let rim = DiskContact::try_new(a, DVec3::ZERO, DVec3::Z).unwrap();
    let inertia = DMat3::from_diagonal(DVec3::new(0.25, 0.25, 0.5) * m * a * a);
    GroundTop::try_with_shape(m, inertia, ContactShape::Disk(rim), Friction::Rolling, G).unwrap()
}

/// A rolling tippe top driven by a torque that changes with time and
/// state: `E(T) − E(0)` equals `∫₀ᵀ P dt`, `P = τ·ω + F·v_G` (the
/// rolling contact does no work), the integral by the composite Simpson
/// rule on the run's own states.
#[test]
fn the_energy_changes_by_the_work_of_the_inputs() {
    let (top, s0) = leine_glocker(Friction::Rolling);
    let inputs = Inputs::default()
        .with_torque_body(DVec3::new(0.0, 0.0, 2e-6))
        .with_load(|t, _| {
            let (s, c) = (7.0 * t).sin_cos();
            (
                DVec3::new(1e-6 * s, 0.0, 3e-7 * c),
                DVec3::new(0.0, 0.01 * s, 0.0),
            )
        })
        .with_angular_damping(1e-9);
    let top = top.try_with_inputs(inputs).unwrap();
    let (h, n) = (1e-5, 100_000);
    let mut s = s0;
    let mut power = vec![top.input_power(0.0, &s)];
    top.try_advance(&mut s, 0.0, h, n, |t, s| power.push(top.input_power(t, s)))
        .unwrap();
    let simpson = power
        .iter()
        .enumerate()
        .map(|(k, p)| {
            let w = if k == 0 || k == n {
                1.0
            } else if k % 2 == 1 {
                4.0
            } else {
                2.0
            };
            w * p
        })
        .sum::<f64>()
        * h
        / 3.0;
    let (e0, e1) = (top.energy(&s0), top.energy(&s));
    let work = e1 - e0;
    // Measured: E changes by 1.83 % of E₀; the balance closes to 3.5e-14
    // of E₀ (RK4's and Simpson's errors at h = 1e-5 s).
    eprintln!(
        "ΔE {work:e} J ({:.2} %), ∫P dt {simpson:e} J, difference {:.1e} of E₀",
        100.0 * work / e0,
        (work - simpson).abs() / e0
    );
    assert!(work.abs() > 1e-2 * e0);
    assert!((work - simpson).abs() < 1e-9 * e0);
    // Rolling holds: the contact point stays at rest.
    assert!(top.slip_velocity(&s).length() < 1e-9);
}

/// A frictionless ball pushed by a constant horizontal force through its
/// centre and spun by a constant vertical torque: by hand, `x = F t²/(2m)`,
/// `L_z = τ t`, `N = m g`.
#[test]
fn a_pushed_frictionless_ball_moves_as_newton_says() {
    let (m, r, i) = (0.3, 0.05, 3e-4);
    let ball = SphereContact::try_new(r, DVec3::ZERO).unwrap();
    let inertia = DMat3::from_diagonal(DVec3::splat(i));
    let (force, torque) = (DVec3::new(0.6, -0.3, 0.0), DVec3::new(0.0, 0.0, 0.02));
    let top = GroundTop::try_new(m, inertia, ball, Friction::None, G)
        .unwrap()
        .try_with_inputs(
            Inputs::default()
                .with_force_world(force)
                .with_torque_world(torque),
        )
        .unwrap();
    let mut s = top
        .try_state_on_ground(DQuat::IDENTITY, DVec3::ZERO, DVec2::ZERO)
        .unwrap();
    let t = top.try_advance(&mut s, 0.0, 1e-3, 2000, |_, _| {}).unwrap();
    let x = force * t * t / (2.0 * m);
    // Measured: 1.2e-13 m after 2000 steps (x = 4.5 m; rounding summed).
    let miss = (s.com_world - (x + DVec3::new(0.0, 0.0, r))).length();
    assert!(miss < 1e-12, "{} vs {}", s.com_world, x);
    let l_miss = (s.l_world - torque * t).length();
    // Measured: 1.3e-15 (L_z = 0.04; rounding summed over 2000 steps).
    assert!(l_miss < 1e-14, "{l_miss:e}");
    assert!((top.normal_force(&s).unwrap() - m * G).abs() < 1e-12);
    // The inputs are reported; free flight refuses them (it is exact and
    // torque-free).
    assert!(top.inputs().is_some());
    let mut flying = s;
    flying.com_world.z += 0.1;
    assert!(matches!(
        top.try_fly(&mut flying, t, t + 0.1),
        Err(DynamicsError::InvalidInput {
            input: "inputs",
            ..
        })
    ));
}

/// Moffatt's finite-time law. Euler's disk (`A = m a²/4`) rolling with its
/// centre of mass at rest, tilted by `α` from the table, its contact point
/// going round at `Ω`: `Ω² sin α = 4 g/a` (the issue's steady state for
/// `ϱ = 0`). There `ω ∥ ρ` (no slip with `v_G = 0`), `ω = −Ω sin α û`,
/// and by hand the energy of the family is
///
/// ```text
/// E(α) = m g a sin α + ½ A Ω² sin²α = (3/2) m g a sin α
/// ```
///
/// Moffatt's air layer dissipates `Φ ∝ Ω²/α`; here the torque
/// `τ = −k ω / sin³α` gives `P = τ·ω = −k Ω²/sin α = −4 k g/(a sin²α)`.
/// If the motion follows the steady family slowly (adiabatically),
/// `dE/dt = P` gives
///
/// ```text
/// (3/2) m g a cos α α̇ = −4 k g/(a sin²α)   ⇒   d(sin³α)/dt = −8 k/(m a²)
/// ```
///
/// so `sin α ∝ (t₀ − t)^{1/3}`: the tilt reaches zero at the finite
/// `t₀ = m a² sin³α₀/(8 k)` while `Ω ∝ (t₀ − t)^{−1/6}` diverges. The full
/// equations give `sin³α` falling on a straight line, 7 % slower than
/// this rate (measured below, with the reason).
#[test]
fn eulers_disk_follows_moffatts_finite_time_law() {
    let (m, a, alpha0) = (0.5, 0.04, 0.3f64);
    let disk = euler_disk(m, a);
    let body = RigidBody::try_from_inertia_tensor(disk.inertia_body()).unwrap();
    let moments = body.principal_moments();
    let axis_principal = body.body_from_principal().conjugate() * DVec3::Z;
    // The steady state at α₀: axis n = (sin α, 0, cos α), û = (cos α, 0, −sin α).
    let q = DQuat::from_rotation_y(alpha0);
    let omega_rate = (4.0 * G / (a * alpha0.sin())).sqrt();
    let u = DVec3::new(alpha0.cos(), 0.0, -alpha0.sin());
    let omega = -omega_rate * alpha0.sin() * u;
    let start = disk.try_rolling_state_on_ground(q, omega).unwrap();
    // Rounding: ω ∥ ρ to the last bits.
    assert!(
        start.velocity_world.length() < 1e-14,
        "{}",
        start.velocity_world
    );
    let sin_tilt = |s: &GroundTopState| {
        DVec3::Z
            .cross(s.world_from_body.normalize() * DVec3::Z)
            .length()
    };

    let mut fits = Vec::new();
    for t0 in [20.0, 40.0] {
        let k = m * a * a * alpha0.sin().powi(3) / (8.0 * t0);
        let law = move |_t: f64, s: &ForcedState| {
            let omega = s.omega_world(moments);
            let n = s.rotation.world_from_principal.normalize() * axis_principal;
            let sin = DVec3::Z.cross(n).length();
            (-k * omega / sin.powi(3), DVec3::ZERO)
        };
        let top = disk
            .clone()
            .try_with_inputs(Inputs::default().with_velocity_load(law))
            .unwrap();
        // To 0.95 t₀: sin³α every 0.01 t₀, fitted by a straight line.
        let h = 2e-4;
        let mut s = start;
        let steps_per_sample = (0.01 * t0 / h).round() as usize;
        let mut samples = vec![(0.0, alpha0.sin().powi(3))];
        for sample in 1..=95 {
            let t_from = (sample - 1) as f64 * 0.01 * t0;
            top.try_advance(&mut s, t_from, h, steps_per_sample, |_, _| {})
                .unwrap();
            samples.push((sample as f64 * 0.01 * t0, sin_tilt(&s).powi(3)));
        }
        let n = samples.len() as f64;
        let (mt, my) = samples
            .iter()
            .fold((0.0, 0.0), |(a, b), (t, y)| (a + t / n, b + y / n));
        let slope = samples
            .iter()
            .map(|(t, y)| (t - mt) * (y - my))
            .sum::<f64>()
            / samples.iter().map(|(t, _)| (t - mt).powi(2)).sum::<f64>();
        let residual = samples
            .iter()
            .map(|(t, y)| (y - (my + slope * (t - mt))).abs())
            .fold(0.0, f64::max)
            / alpha0.sin().powi(3);
        let predicted = -8.0 * k / (m * a * a);
        eprintln!(
            "t₀ = {t0} s (k = {k:.3e} N m s): sin³α falls at {slope:.4e}/s against {predicted:.4e}/s \
             ({:.3}), straight to {residual:.1e} of sin³α₀; at 0.95 t₀ |v_G| = {:.1e} m/s",
            slope / predicted,
            s.velocity_world.length()
        );
        fits.push((slope / predicted, residual));
    }
    // Measured: straight lines to 7.2e-3 of sin³α₀ — the finite-time law —
    // at 0.927 of the predicted rate for both k. The shortfall is not the
    // adiabatic error (it does not change with k): the torque along ω
    // also drives the disk off the family ϱ = 0 (|v_G| grows to 5 cm/s,
    // ϱ ≈ |v_G|/Ω ≈ 0.6 mm), where E(α) and Ω(α) differ from the
    // formulas above; the same path in units of t₀ for both k is the
    // adiabatic limit.
    for (ratio, residual) in &fits {
        assert!((ratio - 1.0).abs() < 0.1, "{fits:?}");
        assert!(*residual < 1e-2, "{fits:?}");
    }
    assert!((fits[0].0 - fits[1].0).abs() < 1e-2, "{fits:?}");
}
