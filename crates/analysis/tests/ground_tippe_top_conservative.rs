//! The tippe top without dissipation — frictionless and rolling — spinning
//! upright and inverted: the thresholds by bisection on the library's
//! verdict against the closed forms, the frequencies in body axes and in
//! space against the sleeping top's.

use kreisel_analysis::{
    LEINE_GLOCKER, Linearisation, Scalar, TippeTop, VectorField, Verdict, ZeroMode,
};
use kreisel_dynamics::Friction;

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
