//! [`HeavyTopPivot`]: a top on a fixed pivot in Euler–Poisson variables —
//! the up vertical `γ` and `ω`, both in principal axes about the pivot —
//! whose steady motions are the permanent rotations about the vertical:
//! the sleeping top (notes §3.11) and, centre of mass below, the spinning
//! pendulum.

use glam::DVec3;
use kreisel_dynamics::HeavyTop;

use crate::{AnalysisError, Eigenvalue, Scalar, VectorField, ZeroMode, ZeroModeKind};

/// A heavy top on a pivot: any principal moments about the pivot `J`, any
/// centre of mass `c` (principal axes, seen from the pivot), weight `M g`.
///
/// ```text
/// J ω̇ = (J ω) × ω + M g γ × c,   γ̇ = γ × ω        (γ: the up vertical in body axes)
/// conserved: |γ|² (Casimir),  J ω·γ (momentum about the vertical),  ½ ωᵀJω + M g c·γ (energy)
/// steady:    γ = ±c/|c|,  ω = Ω γ                 (c along a principal axis)
/// ```
///
/// The rotation about the vertical is reduced away (`γ` does not see it).
/// At a sleeping top the gradients of `|γ|²` and `J ω·γ` are independent
/// and the energy's depends on them: two zero eigenvalues, four that
/// decide. For a symmetric top (`J₁ = J₂`, `c = l e₃`) the notes' result
/// follows:
///
/// ```text
/// in space: precession rates p = (J₃Ω ± √(J₃²Ω² − 4 J₁ M g l))/(2 J₁)
/// stable iff J₃² Ω² > 4 J₁ M g l;  below, growth rate √(4 J₁ M g l − J₃² Ω²)/(2 J₁)
/// in body axes the same modes turn at p − Ω
/// ```
///
/// (Notes §3.11; Routh, *Advanced Rigid Dynamics*; Landau & Lifshitz §35,
/// problem 1.)
///
/// ```
/// use glam::DVec3;
/// use kreisel_analysis::{HeavyTopPivot, Linearisation, Verdict};
/// // J = (2, 2, 1) kg m² about the pivot, centre of mass 0.1 m up e₃, M g = 10 N.
/// let top = HeavyTopPivot::try_new(DVec3::new(2.0, 2.0, 1.0), DVec3::new(0.0, 0.0, 0.1), 10.0)?;
/// // Threshold: Ω² = 4 J₁ M g l / J₃² = 8 (rad/s)².
/// let fast = Linearisation::try_new(&top, &top.sleeping(3.0)?)?;
/// let slow = Linearisation::try_new(&top, &top.sleeping(2.5)?)?;
/// assert_eq!((fast.verdict.name(), slow.verdict.name()), ("stable", "unstable"));
/// # Ok::<(), kreisel_analysis::AnalysisError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HeavyTopPivot {
    moments_about_pivot: DVec3,
    com_principal: DVec3,
    weight: f64,
}

impl HeavyTopPivot {
    /// The top with principal moments about the pivot `J` (kg m²), centre
    /// of mass `c` seen from the pivot in those axes (m) and weight `M g`
    /// (N).
    ///
    /// # Errors
    /// [`AnalysisError::Body`] for moments that no body has;
    /// [`AnalysisError::Parameter`] for a weight that is negative or not
    /// finite, or a centre of mass that is not finite.
    pub fn try_new(
        moments_about_pivot: DVec3,
        com_principal: DVec3,
        weight: f64,
    ) -> Result<Self, AnalysisError> {
        kreisel_dynamics::RigidBody::try_from_principal_moments(moments_about_pivot)?;
        if !(weight >= 0.0 && weight.is_finite()) {
            return Err(AnalysisError::Parameter {
                name: "weight",
                value: weight,
                must: "zero or positive and finite (N)",
            });
        }
        if let Some(&bad) = com_principal.to_array().iter().find(|v| !v.is_finite()) {
            return Err(AnalysisError::Parameter {
                name: "centre of mass",
                value: bad,
                must: "finite (m)",
            });
        }
        Ok(Self {
            moments_about_pivot,
            com_principal,
            weight,
        })
    }

    /// The engine's heavy top: its moments about the pivot, its centre of
    /// mass in their axes and its weight `|M g|`.
    pub fn of(top: &HeavyTop) -> Self {
        Self {
            moments_about_pivot: top.body().principal_moments(),
            com_principal: top.com_principal(),
            weight: top.weight_world().length(),
        }
    }

    /// The principal moments about the pivot, kg m².
    pub fn moments_about_pivot(&self) -> DVec3 {
        self.moments_about_pivot
    }

    /// The centre of mass seen from the pivot, principal axes, m.
    pub fn com_principal(&self) -> DVec3 {
        self.com_principal
    }

    /// The weight `M g`, N.
    pub fn weight(&self) -> f64 {
        self.weight
    }

    /// The sleeping top spinning at `spin` (rad/s, about the up vertical):
    /// the centre of mass straight above the pivot.
    ///
    /// ```text
    /// γ = c/|c|,   ω = Ω γ
    /// ```
    ///
    /// # Errors
    /// [`AnalysisError::NoSuchMotion`] if the centre of mass is at the
    /// pivot or off the principal axes (no permanent rotation about the
    /// vertical through it); [`AnalysisError::Parameter`] for a spin that
    /// is not finite.
    pub fn sleeping(&self, spin: f64) -> Result<Vec<f64>, AnalysisError> {
        self.permanent_rotation(spin, 1.0, "sleeping top")
    }

    /// The spinning pendulum: the centre of mass straight below the pivot,
    /// spinning at `spin` (rad/s, about the up vertical).
    ///
    /// ```text
    /// γ = −c/|c|,   ω = Ω γ
    /// ```
    ///
    /// # Errors
    /// As [`HeavyTopPivot::sleeping`].
    pub fn hanging(&self, spin: f64) -> Result<Vec<f64>, AnalysisError> {
        self.permanent_rotation(spin, -1.0, "hanging top")
    }

    fn permanent_rotation(
        &self,
        spin: f64,
        side: f64,
        kind: &'static str,
    ) -> Result<Vec<f64>, AnalysisError> {
        if !spin.is_finite() {
            return Err(AnalysisError::Parameter {
                name: "spin",
                value: spin,
                must: "finite (rad/s)",
            });
        }
        let c = self.com_principal;
        let axis = (0..3)
            .find(|&k| c[k] != 0.0 && (0..3).all(|j| j == k || c[j].abs() <= 1e-12 * c.length()))
            .ok_or_else(|| AnalysisError::NoSuchMotion {
                kind,
                why: format!(
                    "the centre of mass {c} (principal axes about the pivot, m) is not on a principal axis"
                ),
            })?;
        let mut x = vec![0.0; 6];
        x[axis] = side * c[axis].signum();
        x[3 + axis] = spin * x[axis];
        Ok(x)
    }
}

impl VectorField for HeavyTopPivot {
    fn dim(&self) -> usize {
        6
    }

    fn state_names(&self) -> Vec<String> {
        ["γ₁", "γ₂", "γ₃", "ω₁ (rad/s)", "ω₂ (rad/s)", "ω₃ (rad/s)"]
            .map(String::from)
            .to_vec()
    }

    fn rates<D: Scalar>(&self, x: &[D], dx: &mut [D]) {
        let j = self.moments_about_pivot.to_array();
        let c = self.com_principal.to_array();
        let (g, w) = (&x[..3], &x[3..]);
        for a in 0..3 {
            let (b, k) = ((a + 1) % 3, (a + 2) % 3);
            // (Jω × ω)_a + M g (γ × c)_a, over J_a.
            let gyro = w[b] * w[k] * (j[b] - j[k]);
            let gravity = (g[b] * c[k] - g[k] * c[b]) * self.weight;
            dx[3 + a] = (gyro + gravity) / j[a];
            dx[a] = g[b] * w[k] - g[k] * w[b];
        }
    }

    fn conserved<D: Scalar>(&self, x: &[D]) -> Vec<(ZeroMode, D)> {
        let j = self.moments_about_pivot.to_array();
        let c = self.com_principal.to_array();
        let (g, w) = (&x[..3], &x[3..]);
        let g2 = (0..3).map(|a| g[a] * g[a]).sum::<D>();
        let l_up = (0..3).map(|a| w[a] * g[a] * j[a]).sum::<D>();
        let energy = (0..3)
            .map(|a| w[a] * w[a] * (0.5 * j[a]) + g[a] * (self.weight * c[a]))
            .sum::<D>();
        vec![
            (ZeroMode::new(ZeroModeKind::Casimir, "|γ|²"), g2),
            (
                ZeroMode::new(ZeroModeKind::Momentum, "L·γ (about the vertical)"),
                l_up,
            ),
            (ZeroMode::new(ZeroModeKind::Energy, "E"), energy),
        ]
    }

    fn reduced_by(&self) -> Vec<String> {
        vec!["rotation about the vertical (the azimuth of the attitude)".into()]
    }

    fn is_conservative(&self) -> bool {
        true
    }

    /// `γ` is a unit vector (size 1), `ω` in units of its size.
    fn state_scales(&self, x: &[f64]) -> Vec<f64> {
        let rate = x[3..].iter().map(|v| v * v).sum::<f64>().sqrt();
        vec![1.0, 1.0, 1.0, rate, rate, rate]
    }

    /// At a permanent rotation `ω = Ω γ` about principal axis `k`, a mode
    /// whose transverse `γ` turns circularly at the signed rate `ν` about
    /// `γ` turns in space at `ν + Ω` (the body turns at `Ω` about the
    /// vertical): the frequency `|ν + Ω|`.
    fn space_frequency(
        &self,
        x: &[f64],
        eigenvalue: Eigenvalue,
        shape: &[Eigenvalue],
    ) -> Option<f64> {
        let k = (0..3).find(|&k| (x[k].abs() - 1.0).abs() <= 1e-12)?;
        let spin = x[3 + k] * x[k];
        // Right-handed about γ: (e_{k+1}, e_{k+2}) if γ = +e_k, swapped if −e_k.
        let (p, q) = if x[k] > 0.0 {
            ((k + 1) % 3, (k + 2) % 3)
        } else {
            ((k + 2) % 3, (k + 1) % 3)
        };
        let (a, b) = (shape[p], shape[q]);
        // x + i y = ½(a + i b) e^{λt} + ½(ā + i b̄) e^{λ̄t}: which term is there.
        let plus = (a.re - b.im).hypot(a.im + b.re);
        let minus = (a.re + b.im).hypot(a.im - b.re);
        if plus.min(minus) > 1e-6 * plus.max(minus) {
            return None;
        }
        let signed = if plus > minus {
            eigenvalue.im
        } else {
            -eigenvalue.im
        };
        Some((signed + spin).abs())
    }
}
