//! The tippe top spinning upright and inverted on its ball, with each
//! friction law: the thresholds of the literature (bisection on the
//! library's spectrum against the closed forms), the inversion window,
//! every conserved quantity's rate zero to rounding, every zero
//! eigenvalue named (the engine's runs: `ground_tippe_top_engine.rs`).

use glam::DVec3;
use kreisel_analysis::{
    LEINE_GLOCKER, Linearisation, Scalar, TippeTop, TippeTopParameters, VectorField, Verdict,
    ZeroMode,
};
use kreisel_dynamics::Friction;
use num_dual::Dual64;

fn viscous() -> Friction {
    Friction::try_viscous(0.3).unwrap()
}

fn sliding() -> Friction {
    Friction::try_sliding(0.3, 1e-3).unwrap()
}

/// A family in turned coordinates `x' = Q x` (`Q` a fixed Householder
/// reflection): the same motion, eigenvalues and zeros. The frictionless
/// top's reduced matrix `B` below its threshold (inverted at 17 rad/s) has
/// the exact zeros of its decoupled blocks, on which nalgebra's
/// `Schur::new` (no iteration limit) never returns — a hang of the core's
/// `eigen_pairs`, reported with the matrix; turned, `B` has none.
struct Turned<'a, F: VectorField>(&'a F);

impl<F: VectorField> Turned<'_, F> {
    /// `Q = 𝟙 − 2 u uᵀ/|u|²` with `u_k = 1 + k/7`.
    fn apply<D: Scalar>(x: &[D]) -> Vec<D> {
        let n = x.len();
        let u: Vec<f64> = (0..n).map(|k| 1.0 + k as f64 / 7.0).collect();
        let uu: f64 = u.iter().map(|v| v * v).sum();
        let ux = x
            .iter()
            .zip(&u)
            .fold(D::from(0.0), |a, (xi, ui)| a + *xi * *ui);
        x.iter()
            .zip(&u)
            .map(|(xi, ui)| *xi - ux * (2.0 * ui / uu))
            .collect()
    }
}

impl<F: VectorField> VectorField for Turned<'_, F> {
    fn dim(&self) -> usize {
        self.0.dim()
    }
    fn state_names(&self) -> Vec<String> {
        (0..self.dim()).map(|k| format!("x'_{k}")).collect()
    }
    fn rates<D: Scalar>(&self, x: &[D], dx: &mut [D]) {
        let mut f = vec![D::from(0.0); x.len()];
        self.0.rates(&Self::apply(x), &mut f);
        dx.copy_from_slice(&Self::apply(&f));
    }
    fn conserved<D: Scalar>(&self, x: &[D]) -> Vec<(ZeroMode, D)> {
        self.0.conserved(&Self::apply(x))
    }
    /// None: the rotation about the axis moves nothing at the upright and
    /// inverted spins, and turned, its rounding-sized direction would be
    /// counted by the core's independence test (relative to the vector's
    /// own length).
    fn symmetry_directions(&self, _x: &[f64]) -> Vec<(ZeroMode, Vec<f64>)> {
        Vec::new()
    }
    fn reduced_by(&self) -> Vec<String> {
        self.0.reduced_by()
    }
    fn is_conservative(&self) -> bool {
        self.0.is_conservative()
    }
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

/// Without friction spinning upright is stable at every spin (the centre
/// of mass hangs below the sphere's centre), and inverted it needs
/// `I₃² Ω² > 4 I₁ m g a` — the sleeping top's condition about the centre
/// of mass, which the frictionless plane lets move only vertically.
/// Bisection on the verdict finds it to 1e-12 relative (measured −2.8e-14
/// for Leine & Glocker's top): the two wobbles collide there and the
/// growth rises like a square root. Every zero is named: `|γ|²`, `γ·v_P`
/// and Jellett's λ (the energy, `L·γ` and `|v_h|²` depend on them here).
#[test]
fn frictionless_inverted_needs_the_sleeping_tops_spin() {
    let top = TippeTop::try_new(LEINE_GLOCKER, Friction::None).unwrap();
    let closed = top.frictionless_inverted_threshold();
    let turned = Turned(&top);
    let unstable = |spin: f64| {
        let x = Turned::<TippeTop>::apply(&top.spinning_inverted(spin).unwrap());
        let lin = Linearisation::try_new(&turned, &x).unwrap();
        matches!(lin.verdict, Verdict::Unstable { .. })
    };
    let found = boundary(0.5 * closed, 2.0 * closed, unstable);
    let error = found / closed - 1.0;
    eprintln!("frictionless inverted: Ω_c = {closed:.12} rad/s, bisected {error:.1e}");
    assert!(error.abs() <= 1e-12, "{error:e}");
    for spin in [0.0, 10.0, 180.0, 1000.0] {
        let x = Turned::<TippeTop>::apply(&top.spinning_upright(spin).unwrap());
        let lin = Linearisation::try_new(&turned, &x).unwrap();
        assert!(
            !matches!(lin.verdict, Verdict::Unstable { .. }),
            "{spin}: {}",
            lin.verdict
        );
    }
    let lin = Linearisation::try_new(&top, &top.spinning_inverted(180.0).unwrap()).unwrap();
    assert_eq!(lin.zero_modes.len() + lin.modes.len(), top.dim());
    assert_eq!(lin.zero_modes.len(), 3, "{:?}", lin.zero_modes);
    assert!(matches!(lin.verdict, Verdict::Stable { asymptotic: false }));
    // The frequencies: the sleeping top's `ω_s = (I₃Ω ± √(I₃²Ω² − 4 I₁ m g l))/(2 I₁)`
    // in space (`l = −a` upright, `+a` inverted), seen in the body axes
    // turning at `Ω` as `|ω_s − Ω|`, and the horizontal velocity (a fixed
    // vector in space) at `Ω`. Measured: ≤ 1.8e-15 relative; the space
    // frequencies the modes report are `|ω_s|` (and 0 for the velocity).
    let p = LEINE_GLOCKER;
    let spin = 180.0;
    for (x, l) in [
        (top.spinning_upright(spin).unwrap(), -p.offset),
        (top.spinning_inverted(spin).unwrap(), p.offset),
    ] {
        let lin = Linearisation::try_new(&top, &x).unwrap();
        let (i1, i3) = (p.transverse_moment, p.axial_moment);
        let root = ((i3 * spin).powi(2) - 4.0 * i1 * p.mass * p.gravity * l).sqrt();
        let mut expected: Vec<f64> = [i3 * spin + root, i3 * spin - root]
            .iter()
            .map(|w| (w / (2.0 * i1) - spin).abs())
            .chain([spin])
            .collect();
        expected.sort_by(f64::total_cmp);
        let mut found: Vec<f64> = lin
            .modes
            .iter()
            .filter(|m| m.eigenvalue.im > 0.0)
            .map(|m| m.eigenvalue.im)
            .collect();
        found.sort_by(f64::total_cmp);
        for (f, e) in found.iter().zip(&expected) {
            eprintln!(
                "frequency {f:.12} rad/s, closed form relative {:.1e}",
                f / e - 1.0
            );
            assert!((f / e - 1.0).abs() <= 1e-13, "{found:?} vs {expected:?}");
        }
        assert_eq!(found.len(), 3);
        // In space: the nutation and the precession `|ω_s|`, and the
        // velocity standing still (0).
        let mut space: Vec<f64> = lin
            .modes
            .iter()
            .filter(|m| m.eigenvalue.im > 0.0)
            .map(|m| m.space_frequency.expect("circular"))
            .collect();
        space.sort_by(f64::total_cmp);
        let mut closed: Vec<f64> = [i3 * spin + root, i3 * spin - root]
            .iter()
            .map(|w| (w / (2.0 * i1)).abs())
            .chain([0.0])
            .collect();
        closed.sort_by(f64::total_cmp);
        for (f, e) in space.iter().zip(&closed) {
            assert!((f - e).abs() <= 1e-12 * spin, "{space:?} vs {closed:?}");
        }
    }
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

/// A steady motion found by Newton's method from a tilted start (0.5 rad,
/// spinning 150 rad/s about the vertical and 30 about the axis) lands on a
/// spin about the vertical only to the search's tolerance (the tilt and
/// the sliding velocity at rounding, not zero); its zeros are still
/// named, none left over, and the wobbles are those of the exact state.
#[test]
fn a_found_steady_spin_is_accounted_for() {
    use kreisel_analysis::find_steady_motion;
    for (friction, zeros) in [(Friction::None, 3), (Friction::Rolling, 2)] {
        let top = TippeTop::try_new(LEINE_GLOCKER, friction).unwrap();
        let (s, c) = 0.5f64.sin_cos();
        let mut x = vec![0.0, s, c, 0.0, 150.0 * s, 150.0 * c + 30.0];
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

/// Rolling without slipping: inverted spinning is stable above
/// `Ω_c = √(4 (I₁ + m h²) m g a)/(I₃ + m h R)`, `h = R + a` (bisection on
/// the verdict, measured relative difference printed, ≤ 1e-12), upright at
/// every spin; the space frequencies of the wobbles are the closed form's
/// `|ν|` (`TippeTop::rolling_inverted_threshold`), ≤ 1e-12 relative.
#[test]
fn rolling_inverted_needs_the_rolling_tops_spin() {
    let top = TippeTop::try_new(LEINE_GLOCKER, Friction::Rolling).unwrap();
    let closed = top.rolling_inverted_threshold();
    let turned = Turned(&top);
    let unstable = |spin: f64| {
        let x = Turned::<TippeTop>::apply(&top.spinning_inverted(spin).unwrap());
        let lin = Linearisation::try_new(&turned, &x).unwrap();
        matches!(lin.verdict, Verdict::Unstable { .. })
    };
    let found = boundary(0.5 * closed, 2.0 * closed, unstable);
    let error = found / closed - 1.0;
    eprintln!("rolling inverted: Ω_c = {closed:.12} rad/s, bisected {error:.1e}");
    assert!(error.abs() <= 1e-12, "{error:e}");
    let p = LEINE_GLOCKER;
    let (i1, i3, m, g, r, a) = (
        p.transverse_moment,
        p.axial_moment,
        p.mass,
        p.gravity,
        p.radius,
        p.offset,
    );
    for spin in [5.0, 60.0, 180.0] {
        for sigma in [1.0, -1.0] {
            let x = if sigma > 0.0 {
                top.spinning_upright(spin).unwrap()
            } else {
                top.spinning_inverted(spin).unwrap()
            };
            let h = r - sigma * a;
            let (big, small) = (i1 + m * h * h, i3 + m * h * r);
            let disc = (spin * small).powi(2) + 4.0 * sigma * big * m * g * a;
            if disc < 0.0 {
                continue;
            }
            let mut closed: Vec<f64> = [spin * small + disc.sqrt(), spin * small - disc.sqrt()]
                .iter()
                .map(|n| (n / (2.0 * big)).abs())
                .collect();
            closed.sort_by(f64::total_cmp);
            let lin = Linearisation::try_new(&top, &x).unwrap();
            assert!(
                !matches!(lin.verdict, Verdict::Unstable { .. }),
                "{}",
                lin.verdict
            );
            let mut space: Vec<f64> = lin
                .modes
                .iter()
                .filter(|m| m.eigenvalue.im > 0.0)
                .map(|m| m.space_frequency.expect("circular"))
                .collect();
            space.sort_by(f64::total_cmp);
            for (f, e) in space.iter().zip(&closed) {
                eprintln!("σ = {sigma}, Ω = {spin}: ν = {f:.12} rad/s, closed form {e:.12}");
                assert!(
                    (f - e).abs() <= 1e-12 * e.max(spin),
                    "{space:?} vs {closed:?}"
                );
            }
        }
    }
}
