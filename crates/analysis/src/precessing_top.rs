//! [`PrecessingTop`]: the heavy symmetric top in the notes' reduced
//! variables — the tilt `θ` and its momentum, with `p_φ` and `p_ψ` (the
//! angles `φ`, `ψ` are cyclic) — whose steady motions are the steady
//! precessions at any tilt, slow and fast (notes §3.10–3.11).

use kreisel_dynamics::{HeavyTop, LagrangeTop};

use crate::{AnalysisError, Frame, Scalar, VectorField, ZeroMode, ZeroModeKind};

/// Which of the two steady precessions at a tilt.
///
/// ```
/// use kreisel_analysis::Precession;
/// assert_eq!("fast".parse::<Precession>(), Ok(Precession::Fast));
/// assert!("medium".parse::<Precession>().is_err());
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Precession {
    /// The smaller rate `φ̇` (gravity balanced mostly by the spin).
    Slow,
    /// The larger one (the gyroscopic term balanced by the precession's
    /// own centrifugal term).
    Fast,
}

impl std::str::FromStr for Precession {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s {
            "slow" => Ok(Self::Slow),
            "fast" => Ok(Self::Fast),
            other => Err(format!("unknown precession {other:?} (slow, fast)")),
        }
    }
}

/// The heavy symmetric top reduced by its two cyclic angles: Hamilton's
/// equations for `(θ, p_θ, p_φ, p_ψ)` (Euler angles intrinsic ZXZ, θ from
/// the upward vertical; `I₁` about the pivot).
///
/// ```text
/// H = p_θ²/(2I₁) + (p_φ − p_ψ cos θ)²/(2 I₁ sin²θ) + p_ψ²/(2I₃) + M g l cos θ
/// θ̇ = p_θ/I₁,   ṗ_θ = −∂H/∂θ,   ṗ_φ = ṗ_ψ = 0
/// steady at θ₀: p_θ = 0, I₁ cos θ₀ φ̇² − I₃ω₃ φ̇ + M g l = 0
/// ```
///
/// `p_φ` and `p_ψ` are conserved (two zero eigenvalues, named); the
/// energy's gradient depends on theirs at a steady precession; the pair
/// `±iω` of the `(θ, p_θ)` block is the small nutation. The effective
/// potential gives its frequency in closed form (derived from the notes'
/// `V_eff`, with `k = I₃ω₃/I₁`):
///
/// ```text
/// ω_nut² = V_eff''(θ₀)/I₁ = (k − 2 φ̇ cos θ₀)² + φ̇² sin²θ₀
/// ```
///
/// ```
/// use kreisel_analysis::{Linearisation, Precession, PrecessingTop, Verdict};
/// let top = PrecessingTop::try_new(2.0, 1.0, 5.0)?; // I₁, I₃ (kg m²), M g l (J)
/// let x = top.steady(0.4, 20.0, Precession::Slow)?; // θ₀ = 0.4 rad, ω₃ = 20 rad/s
/// let lin = Linearisation::try_new(&top, &x)?;
/// assert!(matches!(lin.verdict, Verdict::Stable { .. }));
/// assert_eq!(lin.zero_modes.len(), 2); // p_φ, p_ψ
/// # Ok::<(), kreisel_analysis::AnalysisError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrecessingTop {
    top: LagrangeTop,
}

impl PrecessingTop {
    /// The symmetric top with `I₁` about the pivot, `I₃` about the axis
    /// (kg m²) and `M g l` (J; negative: centre of mass below the pivot).
    ///
    /// # Errors
    /// [`AnalysisError::Body`] as [`LagrangeTop::try_new`].
    pub fn try_new(i1: f64, i3: f64, mgl: f64) -> Result<Self, AnalysisError> {
        Ok(Self {
            top: LagrangeTop::try_new(i1, i3, mgl)?,
        })
    }

    /// The engine's heavy top, if it is symmetric with its centre of mass
    /// on the axis (which then points from the pivot to the centre of mass:
    /// `M g l ≥ 0`, `ω₃` about that direction).
    ///
    /// # Errors
    /// [`AnalysisError::NoSuchMotion`] for a top without a symmetry axis
    /// through the centre of mass (no cyclic `ψ`).
    pub fn of(top: &HeavyTop) -> Result<Self, AnalysisError> {
        let not_symmetric = |why: String| AnalysisError::NoSuchMotion {
            kind: "steady precession",
            why,
        };
        let k = top.symmetry_axis().ok_or_else(|| {
            not_symmetric(format!(
                "no two principal moments about the pivot are equal ({}): ψ is not cyclic",
                top.body().principal_moments()
            ))
        })?;
        let c = top.com_principal();
        let off_axis = (c - c[k]
            * glam::DVec3::from_array(std::array::from_fn(|n| f64::from(n == k))))
        .length();
        if off_axis > 1e-12 * c.length() {
            return Err(not_symmetric(format!(
                "the centre of mass is {off_axis:.3e} m off the symmetry axis"
            )));
        }
        let j = top.body().principal_moments().to_array();
        let lagrange =
            LagrangeTop::try_new(j[(k + 1) % 3], j[k], top.weight_world().length() * c[k])?;
        Ok(Self { top: lagrange })
    }

    /// `I₁` about the pivot, `I₃`, `M g l`.
    pub fn parameters(&self) -> (f64, f64, f64) {
        (self.top.i1(), self.top.i3(), self.top.mgl())
    }

    /// The precession rate `φ̇` of the steady precession at tilt `theta`
    /// with spin `omega3` (rad/s).
    ///
    /// # Errors
    /// [`AnalysisError::NoSuchMotion`] when the spin is too slow for a
    /// steady precession at this tilt (the discriminant
    /// `I₃²ω₃² − 4 I₁ M g l cos θ₀` is negative), or the fast one is
    /// infinite (`cos θ₀ = 0`); [`AnalysisError::Parameter`] for a tilt
    /// outside `(0, π)` (sleeping: [`crate::HeavyTopPivot::sleeping`]).
    pub fn precession_rate(
        &self,
        theta: f64,
        omega3: f64,
        which: Precession,
    ) -> Result<f64, AnalysisError> {
        if !(theta > 0.0 && theta < std::f64::consts::PI) {
            return Err(AnalysisError::Parameter {
                name: "tilt",
                value: theta,
                must: "strictly between 0 and π rad (upright: the sleeping top)",
            });
        }
        if !omega3.is_finite() {
            return Err(AnalysisError::Parameter {
                name: "spin",
                value: omega3,
                must: "finite (rad/s)",
            });
        }
        let (i1, i3, mgl) = self.parameters();
        let rates = self.top.steady_precession_rates(omega3, theta).ok_or_else(|| {
            AnalysisError::NoSuchMotion {
                kind: "steady precession",
                why: format!(
                    "I₃²ω₃² − 4 I₁ M g l cos θ = {:.6e} < 0 at θ = {theta} rad, ω₃ = {omega3} rad/s",
                    (i3 * omega3).powi(2) - 4.0 * i1 * mgl * theta.cos()
                ),
            }
        })?;
        let rate = match which {
            Precession::Slow => rates.slow,
            Precession::Fast => rates.fast,
        };
        if !rate.is_finite() {
            return Err(AnalysisError::NoSuchMotion {
                kind: "fast steady precession",
                why: format!("at θ = {theta} rad (cos θ = 0) its rate is infinite"),
            });
        }
        Ok(rate)
    }

    /// The steady precession at tilt `theta` with spin `omega3`: the state
    /// `(θ₀, 0, p_φ, p_ψ)`.
    ///
    /// ```text
    /// p_ψ = I₃ω₃,   p_φ = I₁ sin²θ₀ φ̇ + I₃ω₃ cos θ₀
    /// ```
    ///
    /// # Errors
    /// As [`PrecessingTop::precession_rate`].
    pub fn steady(
        &self,
        theta: f64,
        omega3: f64,
        which: Precession,
    ) -> Result<Vec<f64>, AnalysisError> {
        let phi_dot = self.precession_rate(theta, omega3, which)?;
        let (i1, i3, _) = self.parameters();
        let p_psi = i3 * omega3;
        let p_phi = i1 * theta.sin().powi(2) * phi_dot + p_psi * theta.cos();
        Ok(vec![theta, 0.0, p_phi, p_psi])
    }
}

impl VectorField for PrecessingTop {
    fn dim(&self) -> usize {
        4
    }

    fn state_names(&self) -> Vec<String> {
        ["θ (rad)", "p_θ (kg m²/s)", "p_φ (kg m²/s)", "p_ψ (kg m²/s)"]
            .map(String::from)
            .to_vec()
    }

    fn rates<D: Scalar>(&self, x: &[D], dx: &mut [D]) {
        let (i1, _, mgl) = self.parameters();
        let (theta, p_theta, p_phi, p_psi) = (x[0], x[1], x[2], x[3]);
        let (s, c) = (theta.sin(), theta.cos());
        // ∂/∂θ of (p_φ − p_ψ c)²/(2 I₁ s²) + M g l c.
        let u = p_phi - p_psi * c;
        let d_kinetic = u * p_psi * s / (s * s * i1) - u * u * c / (s * s * s * i1);
        dx[0] = p_theta / i1;
        dx[1] = -(d_kinetic - s * mgl);
        dx[2] = D::from(0.0);
        dx[3] = D::from(0.0);
    }

    fn conserved<D: Scalar>(&self, x: &[D]) -> Vec<(ZeroMode, D)> {
        let (i1, i3, mgl) = self.parameters();
        let (theta, p_theta, p_phi, p_psi) = (x[0], x[1], x[2], x[3]);
        let (s, c) = (theta.sin(), theta.cos());
        let u = p_phi - p_psi * c;
        let energy = p_theta * p_theta / (2.0 * i1)
            + u * u / (s * s * (2.0 * i1))
            + p_psi * p_psi / (2.0 * i3)
            + c * mgl;
        vec![
            (
                ZeroMode::new(ZeroModeKind::Momentum, "p_φ = L·ẑ (about the vertical)"),
                p_phi,
            ),
            (
                ZeroMode::new(ZeroModeKind::Momentum, "p_ψ = I₃ω₃ (the spin)"),
                p_psi,
            ),
            (ZeroMode::new(ZeroModeKind::Energy, "E"), energy),
        ]
    }

    fn reduced_by(&self) -> Vec<String> {
        vec![
            "rotation about the vertical (φ cyclic)".into(),
            "rotation about the symmetry axis (ψ cyclic)".into(),
        ]
    }

    fn is_conservative(&self) -> bool {
        true
    }

    /// The tilt in radians (size 1), the momenta in units of their size.
    fn state_scales(&self, x: &[f64]) -> Vec<f64> {
        let momenta = x[1..].iter().map(|v| v * v).sum::<f64>().sqrt();
        vec![1.0, momenta, momenta, momenta]
    }

    /// The tilt `θ` oscillates the same in any frame turning about the
    /// vertical: its frequencies are those seen in space.
    fn frame(&self) -> Frame {
        Frame::Space
    }
}
