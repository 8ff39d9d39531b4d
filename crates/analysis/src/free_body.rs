//! [`FreeBodyRotation`]: a torque-free body's steady rotations — about each
//! principal axis — in Euler's equations for `ω` in principal axes (the
//! attitude reduced away by the rotations of space), notes §3.5–3.7.

use glam::DVec3;
use kreisel_dynamics::RigidBody;

use crate::{AnalysisError, Scalar, VectorField, ZeroMode, ZeroModeKind};

/// The free rigid body in principal axes: Euler's equations.
///
/// ```text
/// I₁ ω̇₁ = (I₂ − I₃) ω₂ ω₃   (and cyclically)
/// conserved: |L|² = Σ I_i² ω_i²  (Casimir),   2T = Σ I_i ω_i²  (energy)
/// steady: ω = Ω e_a,  λ² = Ω² (I_a − I_b)(I_c − I_a)/(I_b I_c)
/// ```
///
/// At `ω = Ω e_a` the two gradients are parallel: one zero eigenvalue
/// (`|L|²`, a steady spin at another rate), and the pair `±λ` decides
/// (notes §3.7, Example 3).
///
/// ```
/// use glam::DVec3;
/// use kreisel_analysis::{FreeBodyRotation, Linearisation, Verdict};
/// let family = FreeBodyRotation::try_new(DVec3::new(1.0, 2.0, 3.0))?;
/// let lin = Linearisation::try_new(&family, &family.about_axis(2, 4.0)?)?;
/// // About the largest axis: a wobble at 4 √((3−1)(3−2)/(1·2)) = 4 rad/s.
/// assert!(matches!(lin.verdict, Verdict::Stable { .. }));
/// assert!((lin.modes[0].eigenvalue.frequency() - 4.0).abs() < 1e-13);
/// # Ok::<(), kreisel_analysis::AnalysisError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FreeBodyRotation {
    moments: DVec3,
}

impl FreeBodyRotation {
    /// The family for principal moments `I₁, I₂, I₃` (kg m²).
    ///
    /// # Errors
    /// [`AnalysisError::Body`] if the moments are not positive, finite and
    /// within the triangle inequality
    /// ([`RigidBody::try_from_principal_moments`]).
    pub fn try_new(moments: DVec3) -> Result<Self, AnalysisError> {
        RigidBody::try_from_principal_moments(moments)?;
        Ok(Self { moments })
    }

    /// The family of a body: its principal moments (the state is `ω` in
    /// its principal axes, [`RigidBody::body_from_principal`]).
    pub fn of(body: &RigidBody) -> Self {
        Self {
            moments: body.principal_moments(),
        }
    }

    /// The principal moments.
    pub fn moments(&self) -> DVec3 {
        self.moments
    }

    /// The steady rotation at `rate` (rad/s) about principal axis `axis`
    /// (0, 1 or 2): the state `Ω e_a`.
    ///
    /// # Errors
    /// [`AnalysisError::Parameter`] for an axis above 2 or a rate that is
    /// not finite.
    pub fn about_axis(&self, axis: usize, rate: f64) -> Result<Vec<f64>, AnalysisError> {
        if axis > 2 {
            return Err(AnalysisError::Parameter {
                name: "axis",
                value: axis as f64,
                must: "0, 1 or 2",
            });
        }
        if !rate.is_finite() {
            return Err(AnalysisError::Parameter {
                name: "rate",
                value: rate,
                must: "finite (rad/s)",
            });
        }
        let mut x = vec![0.0; 3];
        x[axis] = rate;
        Ok(x)
    }
}

impl VectorField for FreeBodyRotation {
    fn dim(&self) -> usize {
        3
    }

    fn state_names(&self) -> Vec<String> {
        ["ω₁ (rad/s)", "ω₂ (rad/s)", "ω₃ (rad/s)"]
            .map(String::from)
            .to_vec()
    }

    fn rates<D: Scalar>(&self, x: &[D], dx: &mut [D]) {
        let i = self.moments.to_array();
        for a in 0..3 {
            let (b, c) = ((a + 1) % 3, (a + 2) % 3);
            dx[a] = x[b] * x[c] * ((i[b] - i[c]) / i[a]);
        }
    }

    fn conserved<D: Scalar>(&self, x: &[D]) -> Vec<(ZeroMode, D)> {
        let i = self.moments.to_array();
        let l2 = (0..3).map(|a| x[a] * x[a] * (i[a] * i[a])).sum::<D>();
        let two_t = (0..3).map(|a| x[a] * x[a] * i[a]).sum::<D>();
        vec![
            (ZeroMode::new(ZeroModeKind::Casimir, "|L|²"), l2),
            (ZeroMode::new(ZeroModeKind::Energy, "T"), two_t),
        ]
    }

    fn reduced_by(&self) -> Vec<String> {
        vec!["the rotations of space (the attitude: three directions)".into()]
    }

    fn is_conservative(&self) -> bool {
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Linearisation, Verdict};

    #[test]
    fn bad_moments_and_axes_are_refused() {
        assert!(matches!(
            FreeBodyRotation::try_new(DVec3::new(1.0, 1.0, 3.0)),
            Err(AnalysisError::Body(_))
        ));
        let f = FreeBodyRotation::try_new(DVec3::new(1.0, 2.0, 3.0)).unwrap();
        assert!(matches!(
            f.about_axis(3, 1.0),
            Err(AnalysisError::Parameter { name: "axis", .. })
        ));
        assert!(matches!(
            f.about_axis(0, f64::NAN),
            Err(AnalysisError::Parameter { name: "rate", .. })
        ));
    }

    #[test]
    fn a_body_at_rest_or_symmetric_is_neutral() {
        let f = FreeBodyRotation::try_new(DVec3::new(1.0, 2.0, 3.0)).unwrap();
        let lin = Linearisation::try_new(&f, &[0.0; 3]).unwrap();
        assert!(
            matches!(lin.verdict, Verdict::Neutral { .. }),
            "{:?}",
            lin.verdict
        );
        // Two equal moments, spun about one of them: any axis in their
        // plane is steady, λ = 0 twice.
        let f = FreeBodyRotation::try_new(DVec3::new(1.0, 1.0, 1.5)).unwrap();
        let lin = Linearisation::try_new(&f, &f.about_axis(0, 2.0).unwrap()).unwrap();
        assert!(
            matches!(lin.verdict, Verdict::Neutral { .. }),
            "{:?}",
            lin.verdict
        );
        // About the symmetry axis it is stable.
        let lin = Linearisation::try_new(&f, &f.about_axis(2, 2.0).unwrap()).unwrap();
        assert!(matches!(lin.verdict, Verdict::Stable { asymptotic: false }));
    }

    #[test]
    fn a_state_off_every_axis_is_not_steady() {
        let f = FreeBodyRotation::try_new(DVec3::new(1.0, 2.0, 3.0)).unwrap();
        let e = Linearisation::try_new(&f, &[1.0, 1.0, 1.0]).unwrap_err();
        assert!(matches!(e, AnalysisError::NotSteady { residual, .. } if residual > 0.1));
    }
}
