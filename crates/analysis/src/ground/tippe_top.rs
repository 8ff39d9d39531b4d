//! [`TippeTop`]: a sphere whose centre lies `a` from the centre of mass
//! on the axis of symmetry, spinning upright (centre of mass below the
//! sphere's centre) or inverted (above it), with each of the engine's
//! friction laws, and the thresholds the literature gives for it.

use glam::{DMat3, DVec3};
use kreisel_dynamics::{Body, Friction, GroundTop, SphereContact};

use super::body_on_ground::BodyOnGround;
use super::contact_equations::ground_top_of;
use super::surface::Surface;
use crate::{AnalysisError, Eigenvalue, Scalar, VectorField, ZeroMode};

/// Leine & Glocker's tippe top (Eur. J. Mech. A/Solids 22:193 (2003)):
/// `R = 15 mm`, `a = 3 mm`, `m = 6 g`, `I = diag(8, 8, 7)·10⁻⁷ kg m²`.
pub const LEINE_GLOCKER: TippeTopParameters = TippeTopParameters {
    radius: 0.015,
    offset: 0.003,
    mass: 0.006,
    transverse_moment: 8e-7,
    axial_moment: 7e-7,
    gravity: 9.81,
};

/// The numbers of a tippe top (SI units): sphere radius `R`, the sphere's
/// centre `a` above the centre of mass along the axis `e₃` (stem up),
/// mass, moments `I₁ = I₂` (across) and `I₃` (along) about the centre of
/// mass, gravity `g`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TippeTopParameters {
    /// `R`, m.
    pub radius: f64,
    /// `a`, m (`0 < a < R`).
    pub offset: f64,
    /// `m`, kg.
    pub mass: f64,
    /// `I₁`, kg m².
    pub transverse_moment: f64,
    /// `I₃`, kg m².
    pub axial_moment: f64,
    /// `g`, m/s².
    pub gravity: f64,
}

/// A tippe top on the plane: a [`BodyOnGround`] whose sphere is centred
/// on the axis of symmetry, with its steady spins and thresholds.
///
/// ```text
/// upright:   γ = ĉ,  ω = Ω γ   (centre of mass at R − a; Ω the spin about the vertical)
/// inverted:  γ = −ĉ, ω = Ω γ   (centre of mass at R + a)
/// window:    1 − α < I₁/I₃ < 1 + α,  α = a/R            (inversion possible)
/// frictionless, inverted:   stable iff I₃² Ω² > 4 I₁ m g a
/// rolling, inverted:        stable iff (I₃ + m h R)² Ω² > 4 (I₁ + m h²) m g a,  h = R + a
/// dissipative friction:     upright unstable iff Ω² > m g a (R − a)² / (R² (I₁ − (1 − α) I₃))
///                           inverted stable  iff Ω² > m g a (R + a)² / (R² ((1 + α) I₃ − I₁))
/// ```
///
/// The frictionless condition is the sleeping top's (the notes' §3.11)
/// about the centre of mass, which a frictionless plane lets move only
/// vertically, with the sphere's centre as pivot `a` below it. The
/// dissipative ones are where `E` stops being a minimum on Jellett's level
/// set `λ = const` (λ survives every force at the contact, `E` falls under
/// any dissipative law): the amended potential
/// `V_λ(θ) = λ²/(2 rᵀIr) + m g (R − a cos θ)` of the tilt `θ`, whose
/// curvature changes sign there — the energy–momentum argument of
/// Bou-Rabee, Marsden & Romero, SIAM J. Appl. Dyn. Syst. 3:352 (2004),
/// worked out here for the sphere (derived in this file's terms, not
/// copied; Ueda, Sasaki & Watanabe, arXiv:physics/0507198 (2005), give
/// spin thresholds for a sliding law that vanishes at zero slip, not
/// compared digit by digit). So they do not depend on the law or its
/// coefficient — only the growth rates do: the tests find them, by
/// bisection on the spectrum, for viscous friction at two coefficients and
/// for regularised Coulomb friction, to 2e-10. Their large-spin limits
/// are the window. Rolling without slipping conserves the energy: its
/// inverted spin is stable above the rolling top's threshold
/// ([`TippeTop::rolling_inverted_threshold`], derived there), its upright
/// spin always, and friction is not what turns it over.
///
/// ```
/// use kreisel_analysis::{Linearisation, TippeTop, Verdict, LEINE_GLOCKER};
/// use kreisel_dynamics::Friction;
/// let top = TippeTop::try_new(LEINE_GLOCKER, Friction::try_viscous(0.3)?)?;
/// // I₁/I₃ = 8/7 lies in the window (0.8, 1.2): upright grows …
/// let up = Linearisation::try_new(&top, &top.spinning_upright(180.0)?)?;
/// assert!(matches!(up.verdict, Verdict::Unstable { .. }));
/// // … inverted, above its threshold, decays.
/// let down = Linearisation::try_new(&top, &top.spinning_inverted(180.0)?)?;
/// assert!(matches!(down.verdict, Verdict::Stable { asymptotic: true }));
/// assert!(top.dissipative_threshold_inverted().unwrap() < 180.0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TippeTop {
    field: BodyOnGround,
    parameters: TippeTopParameters,
}

impl TippeTop {
    /// The tippe top of `parameters` with `friction`.
    ///
    /// # Errors
    /// [`AnalysisError::Parameter`] for an offset not in `(0, R)`;
    /// [`AnalysisError::Body`] for numbers the engine refuses.
    pub fn try_new(
        parameters: TippeTopParameters,
        friction: Friction,
    ) -> Result<Self, AnalysisError> {
        let p = parameters;
        if !(p.offset > 0.0 && p.offset < p.radius) {
            return Err(AnalysisError::Parameter {
                name: "offset",
                value: p.offset,
                must: "between 0 and the radius (the sphere's centre above the centre of mass)",
            });
        }
        let sphere = SphereContact::try_new(p.radius, DVec3::new(0.0, 0.0, p.offset))?;
        let i = DMat3::from_diagonal(DVec3::new(
            p.transverse_moment,
            p.transverse_moment,
            p.axial_moment,
        ));
        let top = GroundTop::try_new(p.mass, i, sphere, friction, p.gravity)?;
        Self::try_from_ground_top(&top)
    }

    /// The engine's body on the ground, if it is a tippe top: a sphere
    /// centred off the centre of mass on an axis of symmetry of `I`.
    ///
    /// # Errors
    /// [`AnalysisError::Parameter`] (`shape`) for another surface, a sphere
    /// centred at the centre of mass or off every axis of symmetry, or an
    /// offset not below the radius; as
    /// [`BodyOnGround::try_from_ground_top`].
    pub fn try_from_ground_top(top: &GroundTop) -> Result<Self, AnalysisError> {
        let field = BodyOnGround::try_from_ground_top(top)?;
        let body = field.contact_body();
        let not_a_tippe_top = |value| AnalysisError::Parameter {
            name: "shape",
            value,
            must: "a sphere centred 0 < a < R from the centre of mass on an axis of symmetry of I",
        };
        let Surface::Sphere { radius, .. } = body.surface else {
            return Err(not_a_tippe_top(f64::NAN));
        };
        let c = body.surface.center();
        let a = c.length();
        if !(a > 0.0 && a < radius && body.symmetric_about(c / a)) {
            return Err(not_a_tippe_top(a));
        }
        let axis = c / a;
        let i = body.inertia_matrix();
        let across = axis.any_orthonormal_vector();
        let parameters = TippeTopParameters {
            radius,
            offset: a,
            mass: body.mass,
            transverse_moment: across.dot(i * across),
            axial_moment: axis.dot(i * axis),
            gravity: body.gravity,
        };
        Ok(Self { field, parameters })
    }

    /// A scene's body on the ground in a world of gravity `gravity`.
    ///
    /// # Errors
    /// As [`BodyOnGround::try_from_body`] and
    /// [`TippeTop::try_from_ground_top`].
    pub fn try_from_body(body: &Body, gravity: DVec3) -> Result<Self, AnalysisError> {
        Self::try_from_ground_top(&ground_top_of(body, gravity)?)
    }

    /// Its numbers.
    pub fn parameters(&self) -> TippeTopParameters {
        self.parameters
    }

    /// The general field it is.
    pub fn field(&self) -> &BodyOnGround {
        &self.field
    }

    /// The axis of symmetry towards the sphere's centre, body axes.
    fn axis(&self) -> DVec3 {
        self.field.contact_body().surface.center().normalize()
    }

    /// Spinning at `spin` rad/s about the vertical on the ball, stem up
    /// (`γ = ĉ`, centre of mass at `R − a`).
    ///
    /// # Errors
    /// [`AnalysisError::Parameter`] for a spin that is not finite.
    pub fn spinning_upright(&self, spin: f64) -> Result<Vec<f64>, AnalysisError> {
        self.field.spinning_about_vertical(self.axis(), spin)
    }

    /// Spinning at `spin` rad/s about the vertical on the ball, stem down
    /// (`γ = −ĉ`, centre of mass at `R + a`; the single sphere still
    /// touches — no stem in this model).
    ///
    /// # Errors
    /// As [`TippeTop::spinning_upright`].
    pub fn spinning_inverted(&self, spin: f64) -> Result<Vec<f64>, AnalysisError> {
        self.field.spinning_about_vertical(-self.axis(), spin)
    }

    /// The window `(1 − α, 1 + α)`, `α = a/R`, in which `I₁/I₃` must lie
    /// for friction to turn the top over.
    pub fn inversion_window(&self) -> (f64, f64) {
        let alpha = self.parameters.offset / self.parameters.radius;
        (1.0 - alpha, 1.0 + alpha)
    }

    /// Without friction, the spin (rad/s) above which spinning inverted is
    /// stable: `Ω_c = √(4 I₁ m g a)/I₃` (spinning upright is always stable).
    pub fn frictionless_inverted_threshold(&self) -> f64 {
        let p = self.parameters;
        (4.0 * p.transverse_moment * p.mass * p.gravity * p.offset).sqrt() / p.axial_moment
    }

    /// Rolling without slipping, the spin (rad/s) above which spinning
    /// inverted is stable (spinning upright always is).
    ///
    /// ```text
    /// Ω_c = √(4 (I₁ + m h²) m g a) / (I₃ + m h R),   h = R + a
    /// ```
    ///
    /// Linearised about the spin, the axis's horizontal excursion `U`
    /// (complex) obeys `(I₁ + m h²) Ü − iΩ (I₃ + m h R) U̇ + σ m g a U = 0`
    /// (`σ = +1` upright, `−1` inverted, `h = R − σ a` the centre of mass's
    /// height): the sleeping top's equation about the contact, with
    /// `I₃ + m h R` for `I₃`; at `R = 0` the sleeping top itself (derived
    /// here: Euler about the centre of mass with `v_G = ω × (R ẑ − a k)`;
    /// the space frequencies are `ν = (Ω(I₃ + m h R) ± √(Ω²(I₃ + m h R)² +
    /// 4σ(I₁ + m h²) m g a))/(2(I₁ + m h²))`).
    pub fn rolling_inverted_threshold(&self) -> f64 {
        let p = self.parameters;
        let h = p.radius + p.offset;
        (4.0 * (p.transverse_moment + p.mass * h * h) * p.mass * p.gravity * p.offset).sqrt()
            / (p.axial_moment + p.mass * h * p.radius)
    }

    /// With a dissipative law (viscous, regularised Coulomb), the spin
    /// above which spinning upright is unstable (`None`: stable at every
    /// spin, `I₁/I₃ ≤ 1 − α`).
    ///
    /// ```text
    /// Ω_c² = m g a (R − a)² / (R² (I₁ − (1 − α) I₃))
    /// ```
    pub fn dissipative_threshold_upright(&self) -> Option<f64> {
        let p = self.parameters;
        let (r, a) = (p.radius, p.offset);
        let margin = p.transverse_moment - (1.0 - a / r) * p.axial_moment;
        (margin > 0.0).then(|| (p.mass * p.gravity * a * (r - a).powi(2) / (r * r * margin)).sqrt())
    }

    /// With a dissipative law, the spin above which spinning inverted is
    /// stable (`None`: unstable at every spin, `I₁/I₃ ≥ 1 + α`).
    ///
    /// ```text
    /// Ω_c² = m g a (R + a)² / (R² ((1 + α) I₃ − I₁))
    /// ```
    pub fn dissipative_threshold_inverted(&self) -> Option<f64> {
        let p = self.parameters;
        let (r, a) = (p.radius, p.offset);
        let margin = (1.0 + a / r) * p.axial_moment - p.transverse_moment;
        (margin > 0.0).then(|| (p.mass * p.gravity * a * (r + a).powi(2) / (r * r * margin)).sqrt())
    }
}

super::delegate_vector_field!(TippeTop, field);

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Linearisation, Verdict};
    use kreisel_dynamics::{ContactShape, EllipsoidContact};

    /// A scene's body gives the same family as the parameters; other
    /// bodies are refused with the reason.
    #[test]
    fn a_scenes_body_is_the_same_top_and_others_are_refused() {
        let p = LEINE_GLOCKER;
        let ball = ContactShape::Sphere(
            SphereContact::try_new(p.radius, DVec3::new(0.0, 0.0, p.offset)).unwrap(),
        );
        let body = Body::from_principal_moments(p.mass, DVec3::new(8e-7, 8e-7, 7e-7))
            .on_ground(ball, Friction::None)
            .try_build()
            .unwrap();
        let from_body = TippeTop::try_from_body(&body, DVec3::new(0.0, 0.0, -9.81)).unwrap();
        let direct = TippeTop::try_new(p, Friction::None).unwrap();
        assert_eq!(from_body.parameters(), direct.parameters());
        let x = from_body.spinning_inverted(180.0).unwrap();
        assert_eq!(
            Linearisation::try_new(&from_body, &x).unwrap(),
            Linearisation::try_new(&direct, &x).unwrap()
        );
        // Gravity sideways, a body in flight, an offset beyond the radius.
        assert!(matches!(
            TippeTop::try_from_body(&body, DVec3::new(1.0, 0.0, -9.81)),
            Err(AnalysisError::Parameter {
                name: "gravity",
                ..
            })
        ));
        let flying = Body::from_principal_moments(p.mass, DVec3::new(8e-7, 8e-7, 7e-7))
            .try_build()
            .unwrap();
        assert!(matches!(
            TippeTop::try_from_body(&flying, DVec3::new(0.0, 0.0, -9.81)),
            Err(AnalysisError::Parameter {
                name: "support",
                ..
            })
        ));
        let far = TippeTopParameters {
            offset: 0.02,
            ..LEINE_GLOCKER
        };
        assert!(matches!(
            TippeTop::try_new(far, Friction::None),
            Err(AnalysisError::Parameter { name: "offset", .. })
        ));
        // An ellipsoid, or a sphere off the axis of symmetry, is no tippe top.
        let hull = ContactShape::Ellipsoid(
            EllipsoidContact::try_new(DVec3::new(0.2, 0.03, 0.02), DVec3::ZERO).unwrap(),
        );
        let i = DMat3::from_diagonal(DVec3::new(8e-7, 8e-7, 7e-7));
        let egg = GroundTop::try_with_shape(p.mass, i, hull, Friction::None, 9.81).unwrap();
        assert!(matches!(
            TippeTop::try_from_ground_top(&egg),
            Err(AnalysisError::Parameter { name: "shape", .. })
        ));
        let side = SphereContact::try_new(p.radius, DVec3::new(p.offset, 0.0, 0.0)).unwrap();
        let lopsided = GroundTop::try_new(p.mass, i, side, Friction::None, 9.81).unwrap();
        assert!(matches!(
            TippeTop::try_from_ground_top(&lopsided),
            Err(AnalysisError::Parameter { name: "shape", .. })
        ));
    }

    /// The thresholds exist where the window says, and a tippe top with
    /// `I₁ = I₃` inverts above both.
    #[test]
    fn thresholds_exist_inside_the_window() {
        let top = TippeTop::try_new(LEINE_GLOCKER, Friction::None).unwrap();
        assert_eq!(top.inversion_window(), (0.8, 1.2));
        let up = top.dissipative_threshold_upright().unwrap();
        let down = top.dissipative_threshold_inverted().unwrap();
        assert!(up < down && down < 180.0, "{up} {down}");
        // Frictionless the top is conservative: upright stable at any spin.
        let lin = Linearisation::try_new(&top, &top.spinning_upright(5.0).unwrap()).unwrap();
        assert!(matches!(lin.verdict, Verdict::Stable { asymptotic: false }));
        assert!(top.is_conservative());
    }
}
