//! [`ContactLaw`]: what happens where a body meets the table — the
//! set-valued Coulomb–Contensou friction, the set-valued rolling
//! resistance, Newton's restitution at an impact, Garwin's tangential
//! restitution.

use super::AirLayer;
use crate::DynamicsError;

/// Friction and restitution of one contact with the table.
///
/// ```text
/// slip:      γ = (v_Px, v_Py, ε ω_z),   ε = (3π/16) r_c     (r_c = contensou_radius)
/// friction:  Λ = (F_x, F_y, M_z/ε),     |Λ| ≤ μ N,   Λ = −μ N γ/|γ| when γ ≠ 0
/// rolling:   γ_R = δ (ω_x, ω_y),        M_R = δ Λ_R,  |Λ_R| ≤ N,  Λ_R = −N γ_R/|γ_R| when γ_R ≠ 0
/// impact:    ξ_N = γ_N⁺ + e γ_N⁻ ≥ 0,  P_N ≥ 0,  ξ_N P_N = 0
///            ξ_T = γ_T⁺ + e_T γ_T⁻,    P_T = −μ P_N ξ_T/|ξ_T| (|P_T| ≤ μ P_N when ξ_T = 0)
/// ```
///
/// `v_P` is the velocity of the body's material point at the contact, `ω_z`
/// the spin about the table's normal (drilling), `N` the normal force and
/// `P` the impulses of an impact. With `r_c = 0` the law is Coulomb's
/// point contact (stick while `|F| < μ N`, slip against `v_P`); with
/// `r_c > 0` it is Contensou's friction of a circular patch of radius `r_c`
/// under Hertz's pressure, whose pure-spin torque is `(3π/16) μ N r_c` (so
/// `ε = (3π/16) r_c`; uniform pressure would give `⅔ r_c`) — Leine &
/// Glocker's ellipsoidal approximation of the exact Contensou integrals
/// (Eur. J. Mech. A/Solids 22 (2003) 193, §4, as cardillo's tippe-top
/// example writes it): one friction cone in the three slip rates
/// `(v_Px, v_Py, ε ω_z)`, the admissible set the ellipsoid
/// `F_x² + F_y² + (M_z/ε)² ≤ (μ N)²`.
/// The rolling resistance `δ` (`rolling_resistance`, m) is a law of its
/// own, beside the friction cone (Tasora & Anitescu, Meccanica 48 (2013)
/// 1643; Le Saux, Leine & Glocker, J. Nonlinear Sci. 15 (2005) 27): a
/// torque `M_R` about the table's horizontal axes opposing the body's
/// rolling rate `ω_h = (ω_x, ω_y)`, at most `δ N` — the shift of the
/// normal force's line of action ahead of the contact point. While
/// `|M_R| < δ N` the rolling holds (`ω_h` stays zero); it rolls with
/// `M_R = −δ N ω_h/|ω_h|` otherwise. A ball on the table then stops rolling
/// in finite time, as real balls do.
/// The impact law is Newton's in Glocker's form (*Set-Valued Force Laws*,
/// 2001, ch. 7): `e` the normal restitution (0 plastic, 1 elastic), `e_T`
/// the tangential one (0: the slip after the impact is the one friction
/// allows; Garwin's superball, Am. J. Phys. 37 (1969) 88, has `e_T > 0`,
/// the contact point's tangential velocity reversed while it sticks).
/// Newton's law with `e_T ≠ e` can raise the energy (Kane's paradox: an
/// impact that reverses the slip, its friction impulse working along the
/// slip before it); with `e_T = e` at every contact it cannot (Glocker,
/// Multibody Syst. Dyn. 2013). Where the law as given would gain, that
/// impact takes `e_T = e`.
/// A disk rim's law also rules its face striking flat: `e` reverses the
/// face's normal velocities (its centre's and both tilting rates), `μ`
/// bounds its friction impulse with the face's own drilling lever `⅔ a`
/// (the patch radius `r_c` is the rim's).
///
/// ```
/// use kreisel_dynamics::ContactLaw;
/// let law = ContactLaw::try_new(0.3)?.try_with_restitution(0.5)?.try_with_contensou_radius(5e-4)?;
/// assert_eq!(law.mu(), 0.3);
/// assert!((law.drilling_arm() - 3.0 * std::f64::consts::PI / 16.0 * 5e-4).abs() < 1e-20);
/// assert!(ContactLaw::try_new(-0.1).is_err());
/// assert!(ContactLaw::try_new(0.3)?.try_with_restitution(1.5).is_err());
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactLaw {
    mu: f64,
    restitution: f64,
    tangential_restitution: f64,
    contensou_radius: f64,
    rolling_resistance: f64,
    air_layer: Option<AirLayer>,
}

/// A typed error for a law's parameter outside its domain.
fn invalid(parameter: &'static str, value: f64, reason: &'static str) -> DynamicsError {
    DynamicsError::InvalidContact {
        parameter,
        value,
        reason,
    }
}

/// `value` itself when it lies in `[low, high]`, else the typed error.
fn within(
    parameter: &'static str,
    value: f64,
    low: f64,
    high: f64,
    reason: &'static str,
) -> Result<f64, DynamicsError> {
    if value >= low && value <= high {
        Ok(value)
    } else {
        Err(invalid(parameter, value, reason))
    }
}

impl ContactLaw {
    /// Coulomb friction `mu` at a point contact, plastic impacts (`e = 0`,
    /// `e_T = 0`).
    ///
    /// # Panics
    /// For `mu` negative or not finite ([`ContactLaw::try_new`] returns
    /// the error instead).
    pub fn new(mu: f64) -> Self {
        // The documented panic of the `new` half of the `new`/`try_new`
        // pair, for coefficients written in code; no input path (scene,
        // World) calls `new`.
        Self::try_new(mu).expect("friction coefficient must be finite and ≥ 0")
    }

    /// [`ContactLaw::new`] with the error returned.
    ///
    /// # Errors
    /// [`DynamicsError::InvalidContact`] (`"mu"`) for a coefficient that is
    /// negative or not finite.
    pub fn try_new(mu: f64) -> Result<Self, DynamicsError> {
        let mu = within("mu", mu, 0.0, f64::MAX, "must be finite and ≥ 0")?;
        Ok(Self {
            mu,
            restitution: 0.0,
            tangential_restitution: 0.0,
            contensou_radius: 0.0,
            rolling_resistance: 0.0,
            air_layer: None,
        })
    }

    /// The law with Newton's normal restitution `e`.
    ///
    /// # Errors
    /// [`DynamicsError::InvalidContact`] (`"restitution"`) outside `[0, 1]`.
    pub fn try_with_restitution(self, e: f64) -> Result<Self, DynamicsError> {
        let restitution = within("restitution", e, 0.0, 1.0, "must lie in [0, 1]")?;
        Ok(Self {
            restitution,
            ..self
        })
    }

    /// The law with Garwin's tangential restitution `e_T`.
    ///
    /// # Errors
    /// [`DynamicsError::InvalidContact`] (`"tangential_restitution"`)
    /// outside `[0, 1]`.
    pub fn try_with_tangential_restitution(self, e_t: f64) -> Result<Self, DynamicsError> {
        let tangential_restitution = within(
            "tangential_restitution",
            e_t,
            0.0,
            1.0,
            "must lie in [0, 1]",
        )?;
        Ok(Self {
            tangential_restitution,
            ..self
        })
    }

    /// The law with Contensou's drilling friction of a patch of radius
    /// `r_c` m (0: a point contact).
    ///
    /// # Errors
    /// [`DynamicsError::InvalidContact`] (`"contensou_radius"`) for a
    /// radius negative or not finite.
    pub fn try_with_contensou_radius(self, r_c: f64) -> Result<Self, DynamicsError> {
        let contensou_radius = within(
            "contensou_radius",
            r_c,
            0.0,
            f64::MAX,
            "must be finite and ≥ 0",
        )?;
        Ok(Self {
            contensou_radius,
            ..self
        })
    }

    /// The law with the rolling resistance `δ` m (0: none): the rolling
    /// torque is at most `δ N`.
    ///
    /// ```
    /// use kreisel_dynamics::ContactLaw;
    /// let law = ContactLaw::try_new(0.5)?.try_with_rolling_resistance(1e-3)?;
    /// assert_eq!(law.rolling_resistance(), 1e-3);
    /// assert!(ContactLaw::new(0.5).try_with_rolling_resistance(-1e-3).is_err());
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    ///
    /// # Errors
    /// [`DynamicsError::InvalidContact`] (`"rolling_resistance"`) for a
    /// length negative or not finite.
    pub fn try_with_rolling_resistance(self, delta: f64) -> Result<Self, DynamicsError> {
        let rolling_resistance = within(
            "rolling_resistance",
            delta,
            0.0,
            f64::MAX,
            "must be finite and ≥ 0",
        )?;
        Ok(Self {
            rolling_resistance,
            ..self
        })
    }

    /// The law with Moffatt's air layer under the shape, which must be a
    /// disk rim ([`super::TableBody::try_new`] checks).
    ///
    /// ```
    /// use kreisel_dynamics::{AirLayer, ContactLaw};
    /// let air = AirLayer::try_new(1.8e-5, 1e-6)?;
    /// assert_eq!(ContactLaw::new(0.5).with_air_layer(air).air_layer(), Some(air));
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn with_air_layer(self, air_layer: AirLayer) -> Self {
        Self {
            air_layer: Some(air_layer),
            ..self
        }
    }

    /// The air layer under the shape, if any.
    pub fn air_layer(&self) -> Option<AirLayer> {
        self.air_layer
    }

    /// The friction coefficient `μ`.
    pub fn mu(&self) -> f64 {
        self.mu
    }

    /// Newton's normal restitution `e`.
    pub fn restitution(&self) -> f64 {
        self.restitution
    }

    /// The tangential restitution `e_T`.
    pub fn tangential_restitution(&self) -> f64 {
        self.tangential_restitution
    }

    /// The Contensou patch radius `r_c`, m.
    pub fn contensou_radius(&self) -> f64 {
        self.contensou_radius
    }

    /// The rolling resistance `δ`, m: the rolling torque is at most `δ N`.
    pub fn rolling_resistance(&self) -> f64 {
        self.rolling_resistance
    }

    /// The drilling lever `ε = (3π/16) r_c`, m: the pure-spin friction
    /// torque of the patch per newton of friction, `M_z = −ε μ N sgn ω_z`.
    pub fn drilling_arm(&self) -> f64 {
        3.0 * std::f64::consts::PI / 16.0 * self.contensou_radius
    }

    /// How many friction directions the law has: 0 (frictionless), 2
    /// (Coulomb at a point), 3 (with Contensou's drilling).
    pub(crate) fn friction_dimensions(&self) -> usize {
        if self.mu == 0.0 {
            0
        } else if self.contensou_radius == 0.0 {
            2
        } else {
            3
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_parameter_outside_its_domain_is_named() {
        let name = |e: DynamicsError| match e {
            DynamicsError::InvalidContact { parameter, .. } => parameter,
            other => panic!("unexpected {other:?}"),
        };
        assert_eq!(name(ContactLaw::try_new(f64::NAN).unwrap_err()), "mu");
        let law = ContactLaw::new(0.3);
        assert_eq!(
            name(law.try_with_restitution(-0.1).unwrap_err()),
            "restitution"
        );
        assert_eq!(
            name(law.try_with_tangential_restitution(1.1).unwrap_err()),
            "tangential_restitution"
        );
        assert_eq!(
            name(law.try_with_contensou_radius(f64::INFINITY).unwrap_err()),
            "contensou_radius"
        );
        assert_eq!(
            name(law.try_with_rolling_resistance(f64::NAN).unwrap_err()),
            "rolling_resistance"
        );
    }

    #[test]
    fn friction_dimensions_follow_the_parameters() {
        assert_eq!(ContactLaw::new(0.0).friction_dimensions(), 0);
        assert_eq!(ContactLaw::new(0.3).friction_dimensions(), 2);
        let c = ContactLaw::new(0.3)
            .try_with_contensou_radius(5e-4)
            .unwrap();
        assert_eq!(c.friction_dimensions(), 3);
    }
}
