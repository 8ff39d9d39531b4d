//! The tippe top spinning upright and inverted on its ball with a
//! dissipative law: the thresholds (bisection on the library's spectrum
//! against the closed forms), the inversion window; every conserved
//! quantity's rate zero to rounding with each law, a found steady spin's
//! zeros named (without dissipation: `ground_tippe_top_conservative.rs`;
//! the engine's runs: `ground_tippe_top_engine.rs`).

use glam::DVec3;
use kreisel_analysis::{
    LEINE_GLOCKER, Linearisation, TippeTop, TippeTopParameters, VectorField, Verdict,
};
use kreisel_dynamics::Friction;
use num_dual::Dual64;

fn viscous() -> Friction {
    Friction::try_viscous(0.3).unwrap()
}

fn sliding() -> Friction {
    Friction::try_sliding(0.3, 1e-3).unwrap()
}

/// The spin where `unstable(spin)` flips between `low` and `high`, by 50
/// halvings.
fn boundary(mut low: f64, mut high: f64, unstable: impl Fn(f64) -> bool) -> f64 {
    let low_unstable = unstable(low);
    assert_ne!(low_unstable, unstable(high), "no flip in [{low}, {high}]");
    for _ in 0..50 {
        let mid = 0.5 * (low + high);
        if unstable(mid) == low_unstable {
            low = mid;
        } else {
            high = mid;
        }
    }
    0.5 * (low + high)
}

/// With a dissipative law the spectrum decides where `E` stops being a
/// minimum on Jellett's level: upright becomes unstable above
/// `Ω_c² = m g a (R − a)²/(R² (I₁ − (1 − α) I₃))`, inverted stable above
/// `Ω_c² = m g a (R + a)²/(R² ((1 + α) I₃ − I₁))` — for viscous friction
/// and for regularised Coulomb friction, whatever their coefficients.
/// At the boundary a real eigenvalue crosses zero (linearly in Ω), so the
/// bisection is on the sign of the largest real part (the verdict's
/// tolerance, 1e-7 of `|λ|`, would shift it). Measured relative
/// differences from the closed forms are printed; all ≤ 1e-9.
#[test]
fn dissipative_thresholds_are_the_energy_momentum_ones() {
    for friction in [viscous(), Friction::try_viscous(3.0).unwrap(), sliding()] {
        let top = TippeTop::try_new(LEINE_GLOCKER, friction).unwrap();
        let up = top.dissipative_threshold_upright().unwrap();
        let grows = |x: Vec<f64>| Linearisation::try_new(&top, &x).unwrap().max_real_part() > 0.0;
        let found_up = boundary(0.5 * up, 2.0 * up, |s| {
            grows(top.spinning_upright(s).unwrap())
        });
        let down = top.dissipative_threshold_inverted().unwrap();
        let found_down = boundary(0.5 * down, 2.0 * down, |s| {
            grows(top.spinning_inverted(s).unwrap())
        });
        let (e_up, e_down) = (found_up / up - 1.0, found_down / down - 1.0);
        eprintln!(
            "{friction:?}: upright Ω_c = {up:.10} ({e_up:.1e}), inverted Ω_c = {down:.10} ({e_down:.1e})"
        );
        assert!(
            e_up.abs() <= 1e-9 && e_down.abs() <= 1e-9,
            "{e_up:e} {e_down:e}"
        );
    }
}

/// The window `1 − α < I₁/I₃ < 1 + α` (`α = a/R = 0.2`): outside it
/// friction never destabilises upright spinning (below) or never
/// stabilises inverted spinning (above), at any spin; inside, both happen
/// at high spin.
#[test]
fn the_inversion_window() {
    let with_ratio = |ratio: f64| {
        let p = TippeTopParameters {
            transverse_moment: ratio * LEINE_GLOCKER.axial_moment,
            ..LEINE_GLOCKER
        };
        TippeTop::try_new(p, viscous()).unwrap()
    };
    let top = with_ratio(1.0);
    assert_eq!(top.inversion_window(), (0.8, 1.2));
    let growth =
        |top: &TippeTop, x: Vec<f64>| Linearisation::try_new(top, &x).unwrap().max_real_part();
    for spin in [50.0, 200.0, 1000.0, 5000.0] {
        // Below the window: upright stays stable.
        let below = with_ratio(0.79);
        assert!(below.dissipative_threshold_upright().is_none());
        assert!(
            growth(&below, below.spinning_upright(spin).unwrap()) < 0.0,
            "{spin}"
        );
        // Above it: inverted stays unstable.
        let above = with_ratio(1.21);
        assert!(above.dissipative_threshold_inverted().is_none());
        assert!(
            growth(&above, above.spinning_inverted(spin).unwrap()) > 0.0,
            "{spin}"
        );
    }
    // Inside, at 5000 rad/s: upright grows, inverted decays.
    for ratio in [0.81, 1.0, 1.19] {
        let top = with_ratio(ratio);
        assert!(
            growth(&top, top.spinning_upright(5000.0).unwrap()) > 0.0,
            "{ratio}"
        );
        assert!(
            growth(&top, top.spinning_inverted(5000.0).unwrap()) < 0.0,
            "{ratio}"
        );
    }
}

/// Each conserved quantity's rate `∇C · f` vanishes to rounding at 20
/// random states on the constraint `γ·v_P = 0` (exact gradients: dual
/// numbers), for every friction law; Jellett's λ with every law, the
/// energy only without friction and rolling.
#[test]
fn conserved_quantities_are_conserved() {
    let mut seed = 12345u64;
    let mut uniform = || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    let mut worst: f64 = 0.0;
    for friction in [Friction::None, viscous(), sliding(), Friction::Rolling] {
        let top = TippeTop::try_new(LEINE_GLOCKER, friction).unwrap();
        let n = top.dim();
        for _ in 0..20 {
            let gamma =
                DVec3::new(uniform(), uniform(), uniform()).normalize() * (1.0 + 0.1 * uniform());
            let omega = DVec3::new(uniform(), uniform(), uniform()) * 100.0;
            let mut x: Vec<f64> = gamma
                .to_array()
                .into_iter()
                .chain(omega.to_array())
                .collect();
            if n == 9 {
                // v on the constraint: γ·(v − ω × r) = 0.
                let up = gamma.normalize();
                let r = LEINE_GLOCKER.radius * up - DVec3::new(0.0, 0.0, LEINE_GLOCKER.offset);
                let v = DVec3::new(uniform(), uniform(), uniform()) * 0.3;
                let v = v - up * up.dot(v - omega.cross(r));
                x.extend(v.to_array());
            }
            let mut f = vec![0.0; n];
            top.rates(&x, &mut f);
            let scale = f.iter().map(|v| v * v).sum::<f64>().sqrt();
            for (j, (mode, _)) in top.conserved(&x).into_iter().enumerate() {
                // ∇C · f as the derivative of C along f.
                let along: Vec<Dual64> =
                    x.iter().zip(&f).map(|(a, b)| Dual64::new(*a, *b)).collect();
                let (_, c) = &top.conserved(&along)[j];
                let grad: Vec<Dual64> = (0..n)
                    .map(|k| {
                        let e: Vec<Dual64> = x
                            .iter()
                            .enumerate()
                            .map(|(i, a)| Dual64::new(*a, f64::from(i == k)))
                            .collect();
                        top.conserved(&e)[j].1
                    })
                    .collect();
                let size = grad.iter().map(|g| g.eps * g.eps).sum::<f64>().sqrt() * scale;
                let relative = c.eps.abs() / size;
                worst = worst.max(relative);
                assert!(relative <= 1e-13, "{friction:?} {mode}: {relative:e}");
            }
        }
    }
    eprintln!("largest |∇C·f|/(|∇C| |f|): {worst:.1e}");
}

/// A steady motion found by Newton's method from a tilted start (1e-6 rad,
/// spinning 150 rad/s about the vertical and 1e-3 about the axis: near
/// enough to count, `kreisel_analysis::NEARBY`) lands on a
/// spin about the vertical only to the search's tolerance (the tilt and
/// the sliding velocity at rounding, not zero); its zeros are still
/// named, none left over, and the wobbles are those of the exact state.
#[test]
fn a_found_steady_spin_is_accounted_for() {
    use kreisel_analysis::find_steady_motion;
    for (friction, zeros) in [(Friction::None, 3), (Friction::Rolling, 2)] {
        let top = TippeTop::try_new(LEINE_GLOCKER, friction).unwrap();
        let (s, c) = 1e-6f64.sin_cos();
        let mut x = vec![0.0, s, c, 0.0, 150.0 * s, 150.0 * c + 1e-3];
        if top.dim() == 9 {
            x.extend([0.0; 3]);
        }
        let found = find_steady_motion(&top, &x).unwrap();
        let lin = Linearisation::try_new(&top, &found.state).unwrap();
        eprintln!(
            "{friction:?}: γ = {:?}, {} with zeros {:?}",
            &found.state[..3],
            lin.verdict,
            lin.zero_modes
        );
        assert_eq!(lin.zero_modes.len(), zeros, "{:?}", lin.zero_modes);
        assert_eq!(lin.zero_modes.len() + lin.modes.len(), top.dim());
        assert!(
            matches!(lin.verdict, Verdict::Stable { .. }),
            "{}",
            lin.verdict
        );
        // The same spectrum as the exact spin about the vertical.
        let up = DVec3::from_slice(&found.state[..3]);
        let spin = DVec3::from_slice(&found.state[3..6]).dot(up);
        let exact = if up.z > 0.0 {
            top.spinning_upright(spin).unwrap()
        } else {
            top.spinning_inverted(spin).unwrap()
        };
        let reference = Linearisation::try_new(&top, &exact).unwrap();
        // (by frequency: the real parts, ~1e-40, order them at random)
        let sorted = |l: &Linearisation| {
            let mut w: Vec<f64> = l.eigenvalues().iter().map(|e| e.im).collect();
            w.sort_by(f64::total_cmp);
            w
        };
        for (a, b) in sorted(&lin).iter().zip(sorted(&reference)) {
            assert!((a - b).abs() <= 1e-8 * b.abs(), "{a} vs {b}");
        }
    }
}
