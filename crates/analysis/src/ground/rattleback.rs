//! [`Rattleback`]: an ellipsoid rolling without slipping whose inertia
//! axes are turned about the vertical against its geometric axes — it
//! spins steadily one way and turns over the other.

use glam::{DMat3, DVec3};
use kreisel_dynamics::{Body, ContactShape, EllipsoidContact, Friction, GroundTop};

use super::body_on_ground::BodyOnGround;
use super::contact_equations::ground_top_of;
use super::surface::Surface;
use crate::{AnalysisError, Eigenvalue, Scalar, VectorField, ZeroMode};

/// A rattleback rolling on the plane: a [`BodyOnGround`] with an
/// ellipsoid hull and [`Friction::Rolling`], the hull's lowest axis
/// (body `z`) up at rest.
///
/// ```text
/// x = (γ, ω) ∈ ℝ⁶,   spinning upright:  γ = ẑ_b, ω = Ω ẑ_b
/// conserved: |γ|² (Casimir), E (energy);  the spin rate's family is E's level
/// ```
///
/// Kane & Levinson's body (Int. J. Non-Linear Mech. 17:175 (1982)):
/// semi-axes `0.20, 0.03, 0.02` m, the centre of mass `0.01` m below the
/// hull's centre, `m = 1` kg, `I = [[2, 0.2, 0], [0.2, 16, 0], [0, 0, 17]]·10⁻⁴`
/// kg m² in z-up axes (their `D = −2·10⁻⁵` is `−I_xy`; the sign argument
/// is in `kreisel-dynamics/tests/contact_rattleback.rs`). Spinning
/// upright, at `Ω = +5` rad/s the pitch-like wobble grows at 2.1207 /s,
/// at `−5` rad/s the roll-like one at 0.2025 /s: the spin reverses one way
/// within seconds and the other way much later (Garcia & Hubbard, Proc. R.
/// Soc. A 418:165 (1988) for this linear analysis).
///
/// ```
/// use kreisel_analysis::{Linearisation, Rattleback, Verdict};
/// let body = Rattleback::kane_levinson()?;
/// let lin = Linearisation::try_new(&body, &body.spinning_upright(5.0)?)?;
/// let Verdict::Unstable { growth_rate } = lin.verdict else { panic!() };
/// assert!((growth_rate - 2.1206924).abs() < 1e-7);
/// # Ok::<(), kreisel_analysis::AnalysisError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rattleback {
    field: BodyOnGround,
}

impl Rattleback {
    /// Kane & Levinson's rattleback under `g = 9.81` m/s².
    ///
    /// # Errors
    /// Never for these numbers; as [`Rattleback::try_new`].
    pub fn kane_levinson() -> Result<Self, AnalysisError> {
        let inertia = DMat3::from_cols(
            DVec3::new(2e-4, 2e-5, 0.0),
            DVec3::new(2e-5, 16e-4, 0.0),
            DVec3::new(0.0, 0.0, 17e-4),
        );
        Self::try_new(DVec3::new(0.20, 0.03, 0.02), 0.01, 1.0, inertia, 9.81)
    }

    /// An ellipsoid with `semi_axes` (m) along the body axes, the centre of
    /// mass `drop` m below its centre along body `z`, `mass` kg, inertia
    /// tensor `inertia` about the centre of mass (body axes), gravity `g`.
    ///
    /// # Errors
    /// [`AnalysisError::Body`] for numbers the engine refuses.
    pub fn try_new(
        semi_axes: DVec3,
        drop: f64,
        mass: f64,
        inertia: DMat3,
        gravity: f64,
    ) -> Result<Self, AnalysisError> {
        let hull = EllipsoidContact::try_new(semi_axes, DVec3::new(0.0, 0.0, drop))?;
        let top = GroundTop::try_with_shape(
            mass,
            inertia,
            ContactShape::Ellipsoid(hull),
            Friction::Rolling,
            gravity,
        )?;
        Self::try_from_ground_top(&top)
    }

    /// The engine's body, if it is an ellipsoid rolling without slipping.
    ///
    /// # Errors
    /// [`AnalysisError::Parameter`] (`shape`, `friction`) otherwise; as
    /// [`BodyOnGround::try_from_ground_top`].
    pub fn try_from_ground_top(top: &GroundTop) -> Result<Self, AnalysisError> {
        let field = BodyOnGround::try_from_ground_top(top)?;
        if !matches!(field.contact_body().surface, Surface::Ellipsoid { .. }) {
            return Err(AnalysisError::Parameter {
                name: "shape",
                value: f64::NAN,
                must: "an ellipsoid",
            });
        }
        if !field.rolls() {
            return Err(AnalysisError::Parameter {
                name: "friction",
                value: f64::NAN,
                must: "rolling (Friction::Rolling)",
            });
        }
        Ok(Self { field })
    }

    /// A scene's body on the ground in a world of gravity `gravity`.
    ///
    /// # Errors
    /// As [`BodyOnGround::try_from_body`] and
    /// [`Rattleback::try_from_ground_top`].
    pub fn try_from_body(body: &Body, gravity: DVec3) -> Result<Self, AnalysisError> {
        Self::try_from_ground_top(&ground_top_of(body, gravity)?)
    }

    /// The general field it is.
    pub fn field(&self) -> &BodyOnGround {
        &self.field
    }

    /// Spinning upright (body `z` up) at `spin` rad/s about the vertical
    /// (positive: counter-clockwise seen from above).
    ///
    /// # Errors
    /// [`AnalysisError::NoSuchMotion`] if body `z` is not a principal axis
    /// or the centre of mass is not above the contact there;
    /// [`AnalysisError::Parameter`] for a spin that is not finite.
    pub fn spinning_upright(&self, spin: f64) -> Result<Vec<f64>, AnalysisError> {
        self.field.spinning_about_vertical(DVec3::Z, spin)
    }
}

super::delegate_vector_field!(Rattleback, field);

#[cfg(test)]
mod tests {
    use super::*;
    use kreisel_dynamics::SphereContact;

    #[test]
    fn only_a_rolling_ellipsoid_is_a_rattleback() {
        let body = Rattleback::kane_levinson().unwrap();
        assert_eq!(body.dim(), 6);
        let i = DMat3::from_diagonal(DVec3::new(2e-4, 16e-4, 17e-4));
        let ball = SphereContact::try_new(0.02, DVec3::ZERO).unwrap();
        let top = GroundTop::try_new(1.0, i, ball, Friction::Rolling, 9.81).unwrap();
        assert!(matches!(
            Rattleback::try_from_ground_top(&top),
            Err(AnalysisError::Parameter { name: "shape", .. })
        ));
        let hull = EllipsoidContact::try_new(DVec3::new(0.2, 0.03, 0.02), DVec3::ZERO).unwrap();
        let sliding =
            GroundTop::try_with_shape(1.0, i, ContactShape::Ellipsoid(hull), Friction::None, 9.81)
                .unwrap();
        assert!(matches!(
            Rattleback::try_from_ground_top(&sliding),
            Err(AnalysisError::Parameter {
                name: "friction",
                ..
            })
        ));
    }
}
