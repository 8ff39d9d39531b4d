//! Friction at the contact point: the force per unit normal force as a
//! function of the slip velocity.

use std::fmt;
use std::str::FromStr;

use glam::DVec3;

use crate::DynamicsError;

/// The name of a friction model, as a scene or command line writes it.
///
/// ```
/// use kreisel_dynamics::FrictionModel;
/// assert_eq!("sliding".parse::<FrictionModel>()?, FrictionModel::Sliding);
/// assert_eq!(FrictionModel::Viscous.to_string(), "viscous");
/// assert_eq!("rolling".parse::<FrictionModel>()?, FrictionModel::Rolling);
/// assert!("coulomb".parse::<FrictionModel>().is_err());
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FrictionModel {
    /// Frictionless contact (`"none"`).
    None,
    /// Viscous friction (`"viscous"`).
    Viscous,
    /// Regularised Coulomb friction (`"sliding"`).
    Sliding,
    /// Rolling without slipping (`"rolling"`).
    Rolling,
}

impl FrictionModel {
    /// Every model, in the order the docs list them.
    pub const ALL: [FrictionModel; 4] = [Self::None, Self::Viscous, Self::Sliding, Self::Rolling];

    /// The model's name (`"none"`, `"viscous"`, `"sliding"`, `"rolling"`).
    pub fn name(self) -> &'static str {
        match self {
            Self::None => "none",
            Self::Viscous => "viscous",
            Self::Sliding => "sliding",
            Self::Rolling => "rolling",
        }
    }
}

impl fmt::Display for FrictionModel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for FrictionModel {
    type Err = DynamicsError;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Self::ALL
            .into_iter()
            .find(|m| m.name() == s)
            .ok_or_else(|| DynamicsError::UnknownFriction {
                name: s.to_string(),
                known: Self::ALL.map(Self::name).join(", "),
            })
    }
}

/// The tangential force at the contact point.
///
/// ```text
/// none:     F = 0
/// viscous:  F = −μ N v          (μ in s/m)
/// sliding:  F = −μ N v / √(|v|² + ε²)   (μ the Coulomb coefficient, ε = slip_velocity in m/s)
/// rolling:  v_P = 0 held by a constraint force (no parameter)
/// ```
///
/// `rolling` is not a law of the slip: the whole contact force (normal
/// and tangential) is the reaction that keeps the contact point at rest,
/// solved from `d v_P/dt = 0` (module docs, [`crate::contact`]); it does
/// no work, so the motion conserves the energy.
///
/// `v` is the horizontal slip velocity of the material point of the body
/// at the contact. `sliding` is Coulomb's law regularised: `|F| → μ N` for
/// `|v| ≫ ε`, a steep viscous law `F ≈ −(μ N/ε) v` for `|v| ≪ ε`. It is
/// not exact stick–slip; answers depend on `ε` (Leine & Glocker's tippe
/// top inverts in ≈ 2.7 s at ε = 1 mm/s, ≈ 20 s at 0.1 mm/s). Each model
/// but `rolling` dissipates: `F·v ≤ 0`.
///
/// ```
/// use glam::DVec3;
/// use kreisel_dynamics::Friction;
/// let f = Friction::try_sliding(0.3, 1e-3)?;
/// let per_n = f.force_per_normal(DVec3::new(1.0, 0.0, 0.0));
/// assert!((per_n.x + 0.3 / (1.0f64 + 1e-6).sqrt()).abs() < 1e-15);
/// # Ok::<(), kreisel_dynamics::DynamicsError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Friction {
    /// No tangential force.
    None,
    /// `F = −μ N v`.
    Viscous {
        /// The viscous coefficient, s/m (≥ 0).
        mu: f64,
    },
    /// `F = −μ N v/√(|v|² + ε²)`.
    Sliding {
        /// The Coulomb coefficient (≥ 0).
        mu: f64,
        /// The regularisation `ε`, m/s (> 0).
        slip_velocity: f64,
    },
    /// Rolling without slipping: `v_P = 0`, nonholonomic, conservative.
    Rolling,
}

/// A typed error for a bad friction parameter.
fn invalid(parameter: &'static str, value: f64, reason: &'static str) -> DynamicsError {
    DynamicsError::InvalidContact {
        parameter,
        value,
        reason,
    }
}

impl Friction {
    /// The usual `slip_velocity` ε of [`Friction::Sliding`], m/s: 1 mm/s,
    /// the ε at which Leine & Glocker (2003) report their tippe top's
    /// inversion at 2.7 s. The regularised law is stiff for small ε (the
    /// inversion takes ≈ 20 s at 0.1 mm/s), so this is the published
    /// value, not a guess at "exact" Coulomb friction.
    ///
    /// ```text
    /// F = −μ N v/√(|v|² + ε²),   ε = 1e-3 m/s
    /// ```
    ///
    /// ```
    /// use kreisel_dynamics::contact::Friction;
    /// let f = Friction::try_sliding(0.3, Friction::DEFAULT_SLIP_VELOCITY).unwrap();
    /// assert_eq!(f, Friction::Sliding { mu: 0.3, slip_velocity: 1e-3 });
    /// ```
    pub const DEFAULT_SLIP_VELOCITY: f64 = 1e-3;

    /// Viscous friction `F = −μ N v`.
    ///
    /// # Errors
    /// [`DynamicsError::InvalidContact`] for `μ` negative or not finite.
    ///
    /// ```
    /// use kreisel_dynamics::Friction;
    /// assert!(Friction::try_viscous(0.3).is_ok());
    /// assert!(Friction::try_viscous(-0.3).is_err());
    /// ```
    pub fn try_viscous(mu: f64) -> Result<Self, DynamicsError> {
        let f = Self::Viscous { mu };
        f.validate()?;
        Ok(f)
    }

    /// Regularised Coulomb friction `F = −μ N v/√(|v|² + ε²)`.
    ///
    /// # Errors
    /// [`DynamicsError::InvalidContact`] for `μ` negative or not finite, or
    /// `ε` not positive and finite.
    ///
    /// ```
    /// use kreisel_dynamics::Friction;
    /// assert!(Friction::try_sliding(0.3, 1e-3).is_ok());
    /// assert!(Friction::try_sliding(0.3, 0.0).is_err());
    /// ```
    pub fn try_sliding(mu: f64, slip_velocity: f64) -> Result<Self, DynamicsError> {
        let f = Self::Sliding { mu, slip_velocity };
        f.validate()?;
        Ok(f)
    }

    /// The model's name.
    pub fn model(&self) -> FrictionModel {
        match self {
            Self::None => FrictionModel::None,
            Self::Viscous { .. } => FrictionModel::Viscous,
            Self::Sliding { .. } => FrictionModel::Sliding,
            Self::Rolling => FrictionModel::Rolling,
        }
    }

    /// Checks the parameters (the fields are public, so a [`Friction`]
    /// built by hand is checked again where it is used).
    ///
    /// # Errors
    /// As [`Friction::try_viscous`] and [`Friction::try_sliding`].
    pub fn validate(&self) -> Result<(), DynamicsError> {
        let check_mu = |mu: f64| {
            if mu.is_finite() && mu >= 0.0 {
                Ok(())
            } else {
                Err(invalid("mu", mu, "must be finite and ≥ 0"))
            }
        };
        match *self {
            Self::None | Self::Rolling => Ok(()),
            Self::Viscous { mu } => check_mu(mu),
            Self::Sliding { mu, slip_velocity } => {
                check_mu(mu)?;
                if slip_velocity.is_finite() && slip_velocity > 0.0 {
                    Ok(())
                } else {
                    Err(invalid(
                        "slip_velocity",
                        slip_velocity,
                        "must be positive and finite",
                    ))
                }
            }
        }
    }

    /// The tangential force per unit normal force for the slip velocity
    /// `slip` (horizontal, world axes).
    ///
    /// ```text
    /// f(v) = F / N = 0,  −μ v,  or  −μ v/√(|v|² + ε²)
    /// ```
    ///
    /// For [`Friction::Rolling`] the force is no function of the slip (it
    /// is the constraint's reaction, [`crate::GroundTop::contact_force`]):
    /// the answer is NaN in every component, never a plausible number.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::Friction;
    /// assert!(Friction::Rolling.force_per_normal(DVec3::X).x.is_nan());
    /// assert_eq!(Friction::None.force_per_normal(DVec3::X), DVec3::ZERO);
    /// ```
    pub fn force_per_normal(&self, slip: DVec3) -> DVec3 {
        match *self {
            Self::None => DVec3::ZERO,
            Self::Rolling => DVec3::NAN,
            Self::Viscous { mu } => -mu * slip,
            Self::Sliding { mu, slip_velocity } => {
                -mu * slip / (slip.length_squared() + slip_velocity * slip_velocity).sqrt()
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for m in FrictionModel::ALL {
            assert_eq!(m.name().parse::<FrictionModel>().unwrap(), m);
        }
        let err = "coulomb".parse::<FrictionModel>().unwrap_err();
        assert!(
            err.to_string().contains("none, viscous, sliding, rolling"),
            "{err}"
        );
    }

    #[test]
    fn bad_parameters_are_typed_errors() {
        for f in [
            Friction::Viscous { mu: -1.0 },
            Friction::Viscous { mu: f64::NAN },
            Friction::Sliding {
                mu: 0.3,
                slip_velocity: -1e-3,
            },
            Friction::Sliding {
                mu: f64::INFINITY,
                slip_velocity: 1e-3,
            },
        ] {
            assert!(matches!(
                f.validate(),
                Err(DynamicsError::InvalidContact { .. })
            ));
        }
    }

    #[test]
    fn friction_opposes_slip() {
        let v = DVec3::new(0.3, -0.2, 0.0);
        for f in [
            Friction::None,
            Friction::try_viscous(0.5).unwrap(),
            Friction::try_sliding(0.5, 1e-3).unwrap(),
        ] {
            assert!(f.force_per_normal(v).dot(v) <= 0.0);
        }
        // Far above ε, sliding friction is Coulomb's μ.
        let f = Friction::try_sliding(0.5, 1e-9).unwrap();
        assert!((f.force_per_normal(v).length() - 0.5).abs() < 1e-15);
    }
}
