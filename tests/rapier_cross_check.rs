//! Cross-check against rapier3d-f64 (dev-dependency): the same scenarios
//! in rapier's full pipeline (`tests/common/rapier.rs`) and in kreisel.
//!
//! ```text
//! cargo test --test rapier_cross_check -- --nocapture
//! ```
//!
//! prints every measured number (errors, drifts, the flip period); the
//! assertions check only what follows from the two methods' mathematics:
//!
//! - **Where rapier is exact** — a sphere, and spin about a principal
//!   axis — its angular velocity is exact (the gyroscopic term `w × I w`
//!   vanishes), so its attitude is a uniform rotation about the fixed axis
//!   ω. Its quaternion update `q ← normalize((1, ω h/2) ⊗ q)` (per substep
//!   `h = dt/4`) rotates by `2 atan(|ω| h/2)` instead of `|ω| h`, so its
//!   attitude is the exact motion with a phase lag of `n (|ω|h − 2
//!   atan(|ω|h/2)) ≈ n (|ω|h)³/12` after `n` substeps. The test checks rapier
//!   against that closed form of its own map, and against kreisel's
//!   default method and the exact solution up to exactly that lag, to
//!   rounding.
//! - **Elsewhere** (the asymmetric reference trajectories) rapier is a
//!   first-order method; the test records its attitude error at dt = 1/60
//!   next to kreisel's, and checks: kreisel's error ≤ 1e-9 rad, rapier's
//!   error halves when dt halves (first order), rapier keeps |L| to
//!   rounding (its gyroscopic step rescales L to the old norm), and on
//!   rapier's own scenario its Dzhanibekov flip period, measured from the
//!   sign changes of ω₂ over 100 s, misses the exact period by an amount
//!   that halves with dt.
//!
//! Runtime in debug mode: about 20 000 rapier steps in all (≈ 4 s on one
//! core; the longest run is rapier's scenario, 6000 steps of 1/60 over
//! 100 s, the issue's measurement).

use kreisel::dynamics::{FreeBodyMethod, PrincipalState, integrate};
use kreisel::kinematics::glam::{DQuat, DVec3};
use kreisel::kinematics::rotation_angle_between;

#[path = "../crates/dynamics/tests/common/free_body.rs"]
mod free_body;
#[path = "common/rapier.rs"]
mod rapier;

use free_body::{Reference, load};
use rapier::RapierBodies;

/// rapier's substeps per step (`IntegrationParameters::num_solver_iterations`,
/// default 4, which `tests/common/rapier.rs` keeps).
const SUBSTEPS: usize = 4;

const EPS: f64 = f64::EPSILON;

/// Kinetic energy ½ Σ Lₖ²/Iₖ.
fn energy(moments: DVec3, l: DVec3) -> f64 {
    0.5 * (l * l / moments).element_sum()
}

/// kreisel's default method from (q0, L0) for `steps` steps of `dt`.
fn kreisel_run(moments: DVec3, q0: DQuat, l0: DVec3, dt: f64, steps: usize) -> PrincipalState {
    let m = FreeBodyMethod::Auto.integrator();
    let mut s = PrincipalState {
        world_from_principal: q0,
        l_principal: l0,
    };
    integrate(m, moments, &mut s, dt, steps).unwrap();
    s
}

/// The samples of `r` that fall on whole steps of `dt`, with their step index.
fn samples_on_grid(r: &Reference, dt: f64) -> Vec<(usize, f64, DQuat, DVec3)> {
    r.samples
        .iter()
        .filter_map(|&(t, q, l)| {
            let k = (t / dt).round();
            ((k * dt - t).abs() < 1e-9).then_some((k as usize, t, q, l))
        })
        .collect()
}

/// The rounding bound used for rapier's map in the exact cases: after `n`
/// substeps, each of which multiplies and normalises a quaternion and
/// rotates ω into the body frame and back (about 8 roundings of relative
/// size ε on the attitude, accumulated linearly in the worst case), plus
/// the same on ω itself, whose relative error δ shifts the phase by
/// δ·|ω|·T over the run.
fn rounding_bound(n_substeps: usize, omega_t: f64) -> f64 {
    8.0 * n_substeps as f64 * EPS * (1.0 + omega_t)
}

/// rapier's mass properties are the ones asked for, exactly: unit mass,
/// principal moments as given, principal frame = body frame.
#[test]
fn rapier_uses_the_given_principal_moments_and_frame() {
    for name in ["sphere", "rapier", "hlw", "near_separatrix_7", "ratio_1000"] {
        let r = load(name);
        let (_, q0, l0) = r.samples[0];
        let mut b = RapierBodies::single(r.moments, q0, l0, 1.0 / 60.0);
        b.step();
        let (moments, frame) = b.rapier_inertia(0);
        eprintln!(
            "{name}: rapier's moments {moments} (asked {}), frame {frame}",
            r.moments
        );
        // rapier stores 1/I and returns 1/(1/I): at most 1 ulp from I.
        assert!(
            ((moments - r.moments) / r.moments).abs().max_element() <= EPS,
            "{name}: moments {moments} vs {}",
            r.moments
        );
        assert_eq!(frame, DQuat::IDENTITY, "{name}");
    }
}

/// A body whose angular velocity is constant in the exact solution (sphere
/// or principal-axis spin): compares rapier with the closed form of its
/// own map, with the exact motion (closed form `exact(t)`) and with
/// kreisel's default method, at the given times.
fn uniform_rotation_case(
    label: &str,
    moments: DVec3,
    q0: DQuat,
    l0: DVec3,
    dt: f64,
    checkpoints: &[(usize, DQuat)],
) {
    let omega_p = l0 / moments;
    let omega_world = q0 * omega_p;
    let w = omega_world.length();
    let axis = omega_world / w;
    let h = dt / SUBSTEPS as f64;
    // rapier's per-substep rotation angle: normalize((1, ωh/2)) is a
    // rotation by 2 atan(|ω|h/2) about ω.
    let rapier_angle_per_substep = 2.0 * (0.5 * w * h).atan();
    let lag_per_substep = w * h - rapier_angle_per_substep;

    let mut b = RapierBodies::single(moments, q0, l0, dt);
    let mut done = 0;
    let mut worst_own = 0.0f64;
    let mut worst_lag = 0.0f64;
    let mut worst_l = 0.0f64;
    let mut worst_kreisel = 0.0f64;
    for &(k, q_exact) in checkpoints {
        b.steps(k - done);
        done = k;
        let n = k * SUBSTEPS;
        let t = k as f64 * dt;
        let (q, l) = b.state(0);
        // 1. rapier against the closed form of its own map.
        let q_own = DQuat::from_axis_angle(axis, n as f64 * rapier_angle_per_substep) * q0;
        let own = rotation_angle_between(q, q_own);
        // 2. rapier against the exact motion: the predicted lag, to rounding.
        let lag = rotation_angle_between(q, q_exact);
        let predicted_lag = n as f64 * lag_per_substep;
        // 3. rapier's angular momentum is exact.
        let dl = (l - l0).length() / l0.length();
        // 4. kreisel's default method against the exact motion.
        let s = kreisel_run(moments, q0, l0, dt, k);
        let kreisel_err = rotation_angle_between(s.world_from_principal, q_exact);
        // 5. kreisel and rapier agree once rapier's lag is removed.
        let q_rapier_unlagged = DQuat::from_axis_angle(axis, n as f64 * lag_per_substep) * q;
        let agree = rotation_angle_between(s.world_from_principal, q_rapier_unlagged);

        let bound = rounding_bound(n, w * t);
        assert!(
            own <= bound,
            "{label} t = {t}: rapier vs its closed form {own:e} > {bound:e}"
        );
        assert!(
            (lag - predicted_lag).abs() <= bound,
            "{label} t = {t}: rapier's lag {lag:e} vs predicted {predicted_lag:e}"
        );
        assert!(dl <= bound, "{label} t = {t}: rapier's L changed by {dl:e}");
        assert!(
            kreisel_err <= bound,
            "{label} t = {t}: kreisel error {kreisel_err:e}"
        );
        assert!(
            agree <= 2.0 * bound,
            "{label} t = {t}: kreisel vs unlagged rapier {agree:e}"
        );
        worst_own = worst_own.max(own);
        worst_lag = worst_lag.max((lag - predicted_lag).abs());
        worst_l = worst_l.max(dl);
        worst_kreisel = worst_kreisel.max(kreisel_err.max(agree));
        if k == checkpoints.last().unwrap().0 {
            eprintln!(
                "{label}: t = {t} s, dt = {dt:.4}: rapier's phase lag {lag:.3e} rad \
                 (predicted n(|ω|h − 2 atan(|ω|h/2)) = {predicted_lag:.3e}); \
                 kreisel (auto) error {kreisel_err:.1e} rad"
            );
            eprintln!(
                "{label}: worst over {} checkpoints: rapier vs own closed form {worst_own:.1e}, \
                 |lag − predicted| {worst_lag:.1e}, rapier ΔL/L {worst_l:.1e}, \
                 kreisel vs exact / unlagged rapier {worst_kreisel:.1e} \
                 (rounding bound at the end {bound:.1e})",
                checkpoints.len()
            );
        }
    }
}

/// Sphere (I = 2): ω constant; `tests/data/free_body/sphere.csv` to 20 s.
#[test]
fn sphere_rapier_is_exact_up_to_its_phase_lag() {
    let r = load("sphere");
    let dt = 1.0 / 60.0;
    let (_, q0, l0) = r.samples[0];
    let checkpoints: Vec<(usize, DQuat)> = samples_on_grid(&r, dt)
        .into_iter()
        .filter(|s| s.0 > 0)
        .map(|(k, _, q, _)| (k, q))
        .collect();
    assert!(checkpoints.len() >= 10);
    uniform_rotation_case("sphere", r.moments, q0, l0, dt, &checkpoints);
}

/// Spin about the major axis e₃ of I = (1, 2, 3) at 1 rad/s from a
/// general attitude, 100 s: q(t) = q₀ ⊗ exp(e₃ ω t/2).
#[test]
fn principal_axis_spin_rapier_is_exact_up_to_its_phase_lag() {
    let moments = DVec3::new(1.0, 2.0, 3.0);
    let q0 = DQuat::from_xyzw(0.1, -0.3, 0.2, 0.9).normalize();
    let omega = 1.0;
    let l0 = DVec3::new(0.0, 0.0, moments.z * omega);
    let dt = 1.0 / 60.0;
    let checkpoints: Vec<(usize, DQuat)> = (1..=10)
        .map(|i| {
            let k = 600 * i;
            (k, q0 * DQuat::from_rotation_z(omega * k as f64 * dt))
        })
        .collect();
    uniform_rotation_case("spin about e3", moments, q0, l0, dt, &checkpoints);
}

/// rapier's end state on reference `r` at step `dt` to the last sample.
struct RapierEnd {
    /// Time of the last sample, s.
    t: f64,
    /// Steps taken.
    steps: usize,
    attitude_error: f64,
    norm_l_drift: f64,
    energy_drift: f64,
    /// Angle between L_world at the end and at the start, rad.
    l_world_angle: f64,
    /// Times of the sign changes of ω₂ (linear interpolation between steps).
    omega2_sign_changes: Vec<f64>,
}

/// Times where `prev → w` changes sign between steps `k − 1` and `k`.
fn sign_change(prev: f64, w: f64, k: usize, dt: f64) -> Option<f64> {
    ((w > 0.0) != (prev > 0.0)).then(|| (k as f64 - 1.0 + prev / (prev - w)) * dt)
}

fn rapier_end(r: &Reference, dt: f64) -> RapierEnd {
    let (_, q0, l0) = r.samples[0];
    let &(steps, t, q_ref, _) = samples_on_grid(r, dt).last().unwrap();
    let mut b = RapierBodies::single(r.moments, q0, l0, dt);
    let mut prev = b.omega_principal(0).y;
    let mut omega2_sign_changes = Vec::new();
    for k in 1..=steps {
        b.step();
        let w = b.omega_principal(0).y;
        omega2_sign_changes.extend(sign_change(prev, w, k, dt));
        prev = w;
    }
    let (q, l) = b.state(0);
    RapierEnd {
        t,
        steps,
        attitude_error: rotation_angle_between(q, q_ref),
        norm_l_drift: (l.length() - l0.length()) / l0.length(),
        energy_drift: (energy(r.moments, l) - energy(r.moments, l0)) / energy(r.moments, l0),
        l_world_angle: (q * l).angle_between(q0 * l0),
        omega2_sign_changes,
    }
}

/// The period of ω(t) from its sign changes: twice the mean time between
/// successive ones.
fn period_from_sign_changes(t: &[f64]) -> f64 {
    assert!(t.len() >= 3, "too few flips: {t:?}");
    2.0 * (t[t.len() - 1] - t[0]) / (t.len() - 1) as f64
}

/// rapier at dt = 1/30 and 1/60 and kreisel's default at dt = 1/60 to the
/// last sample of reference `name`: prints one table row, checks
/// kreisel ≤ 1e-9 rad, rapier first order and |L| kept; returns rapier's
/// runs.
fn asymmetric_row(name: &str) -> (RapierEnd, RapierEnd) {
    let r = load(name);
    let (_, q0, l0) = r.samples[0];
    let coarse = rapier_end(&r, 1.0 / 30.0);
    let fine = rapier_end(&r, 1.0 / 60.0);
    let order = (coarse.attitude_error / fine.attitude_error).log2();
    let s = kreisel_run(r.moments, q0, l0, 1.0 / 60.0, fine.steps);
    let q_ref = samples_on_grid(&r, 1.0 / 60.0).last().unwrap().2;
    let kreisel_err = rotation_angle_between(s.world_from_principal, q_ref);
    eprintln!(
        "| {name} | {} | {:.2e} | {:.2e} | {order:.2} | {:+.1e} | {:+.1e} | {:.1e} | {kreisel_err:.1e} |",
        fine.t,
        coarse.attitude_error,
        fine.attitude_error,
        fine.energy_drift,
        fine.norm_l_drift,
        fine.l_world_angle,
    );
    assert!(kreisel_err <= 1e-9, "{name}: kreisel error {kreisel_err:e}");
    // First order: the error halves with the step, log₂ ratio ≈ 1 (the
    // band [0.7, 1.3] tells order 1 from 2 and allows for errors that are
    // not yet small, e.g. ~1 rad on ratio_1000).
    assert!(
        (0.7..=1.3).contains(&order),
        "{name}: measured order {order}"
    );
    // |L| is rescaled to its old value every substep: rounding only.
    let bound = rounding_bound(fine.steps * SUBSTEPS, 0.0);
    assert!(
        fine.norm_l_drift.abs() <= bound,
        "{name}: |L| drift {:e} > {bound:e}",
        fine.norm_l_drift
    );
    (coarse, fine)
}

const TABLE_HEADER: &str = "| scenario | t (s) | rapier error dt=1/30 (rad) | rapier error dt=1/60 (rad) | \
     order | rapier ΔE/E | rapier Δ|L|/|L| | rapier L_world drift (rad) | kreisel auto error dt=1/60 (rad) |\n\
     |---|---|---|---|---|---|---|---|---|";

/// The asymmetric references (short runs): rapier's error next to kreisel's.
#[test]
fn asymmetric_references_rapier_error_next_to_kreisel() {
    eprintln!("{TABLE_HEADER}");
    for name in ["hlw", "near_separatrix_7", "ratio_1000"] {
        asymmetric_row(name);
    }
}

/// The exact period of ω(t) from `tests/data/free_body/periods.csv`.
fn exact_period(name: &str) -> f64 {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/free_body/periods.csv"
    );
    let text = std::fs::read_to_string(path).unwrap();
    text.lines()
        .find_map(|line| {
            let mut f = line.split(',');
            (f.next() == Some(name)).then(|| f.next().unwrap().parse().unwrap())
        })
        .unwrap_or_else(|| panic!("no period for {name}"))
}

/// rapier's scenario (I = (1, 2, 3), ω₀ = (0.01, 1, 0)), 100 s (two
/// Dzhanibekov flips per period): the table row as above, and the flip
/// period from the sign changes of ω₂ at dt = 1/30 and 1/60; kreisel's
/// period measured the same way validates the measurement.
#[test]
fn rapier_scenario_error_and_flip_period() {
    eprintln!("{TABLE_HEADER}");
    let (coarse, fine) = asymmetric_row("rapier");
    let r = load("rapier");
    let exact = exact_period("rapier");
    let mut errors = Vec::new();
    for (run, steps_per_second) in [(&coarse, 30), (&fine, 60)] {
        let period = period_from_sign_changes(&run.omega2_sign_changes);
        eprintln!(
            "rapier, dt = 1/{steps_per_second}, {} s: flip period {period:.4} s (exact {exact} s, \
             error {:+.3e} s = {:+.2e} relative; ω₂ changes sign at {:.3?} s)",
            run.t,
            period - exact,
            (period - exact) / exact,
            run.omega2_sign_changes,
        );
        errors.push(period - exact);
    }
    // The measurement itself on kreisel's trajectory at dt = 1/60.
    let dt = 1.0 / 60.0;
    let m = FreeBodyMethod::Auto.integrator();
    let (_, q0, l0) = r.samples[0];
    let mut s = PrincipalState {
        world_from_principal: q0,
        l_principal: l0,
    };
    let mut prev = l0.y;
    let mut changes = Vec::new();
    for k in 1..=fine.steps {
        m.step(r.moments, &mut s, dt);
        changes.extend(sign_change(prev, s.l_principal.y, k, dt));
        prev = s.l_principal.y;
    }
    let kreisel_period = period_from_sign_changes(&changes);
    let resolution = (kreisel_period - exact).abs();
    eprintln!(
        "kreisel (auto), dt = 1/60: flip period {kreisel_period:.9} s, error {resolution:.1e} s \
         (the measurement's resolution)"
    );
    assert!(
        resolution < 1e-4,
        "period measurement error {resolution:e} s"
    );
    // rapier's period error is far above the measurement's resolution…
    assert!(
        errors[1].abs() > 100.0 * resolution,
        "rapier's period error {:e} s",
        errors[1]
    );
    // …and first order: it halves with dt, with the same sign.
    let ratio = errors[0] / errors[1];
    assert!((1.7..=2.3).contains(&ratio), "period error ratio {ratio}");
}
