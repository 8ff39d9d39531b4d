//! A rigid body's rotational inertia: principal moments and the principal frame.

use glam::{DMat3, DQuat, DVec3};
use kreisel_inertia::{MassProperties, PrincipalAxes};

use crate::DynamicsError;

/// The rotational inertia of a rigid body about its centre of mass.
///
/// Integrators work in the principal frame, where the inertia tensor is
/// `diag(I₁, I₂, I₃)`; `body_from_principal` maps principal-frame
/// coordinates to the body frame the user works in (identity when the body
/// axes are principal axes).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidBody {
    moments: DVec3,
    body_from_principal: DQuat,
}

/// Relative slack allowed in the triangle inequality `I₁ + I₂ ≥ I₃` (flat
/// bodies meet it with equality, up to rounding).
const TRIANGLE_SLACK: f64 = 1e-12;

/// The smallest ratio `I_min / I_max` accepted: beyond 100 orders of
/// magnitude between two moments, the products the methods form of the
/// nondimensional moments (`I₁I₂I₃`, its inverse powers) leave `f64`'s range.
pub const MIN_MOMENT_RATIO: f64 = 1e-100;

/// The power of two `2ᵏ` with `max(Iₖ) / 2ᵏ ∈ [1, 2)`: the unit of inertia
/// the methods work in. Dividing the moments and `L` by it is exact (a
/// change of exponent), so a method's rounding is the same whatever the
/// unit system, and bodies whose moments differ by a power of two move bit
/// for bit alike; `ω = I⁻¹L` is unchanged. (For moments that are not
/// positive normal numbers the result is 0 or ∞, and the step is NaN.)
///
/// ```text
/// Î = I / 2ᵏ,   L̂ = L / 2ᵏ,   ω̂ = Î⁻¹ L̂ = ω
/// ```
#[inline]
pub(crate) fn moment_scale(moments: DVec3) -> f64 {
    f64::from_bits(moments.max_element().to_bits() & 0x7ff0_0000_0000_0000)
}

impl RigidBody {
    /// A body whose body axes are principal axes, with moments `(I₁, I₂, I₃)`.
    ///
    /// ```text
    /// Iₖ > 0 normal,   I_min / I_max ≥ 1e-100,   Iᵢ + Iⱼ ≥ Iₖ (each pair, to 1e-12 relative)
    /// ```
    ///
    /// # Errors
    /// [`DynamicsError::UnphysicalInertia`] for a moment that is not a
    /// positive, finite, normal number (a subnormal moment such as 1e-320
    /// has lost its digits), moments more than [`MIN_MOMENT_RATIO`] apart,
    /// or moments breaking the triangle inequality.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::RigidBody;
    /// assert!(RigidBody::try_from_principal_moments(DVec3::new(1.0, 2.0, 3.0)).is_ok());
    /// assert!(RigidBody::try_from_principal_moments(DVec3::new(1.0, 1.0, 3.0)).is_err());
    /// // Any unit system: a 1 µm sphere, a planet.
    /// assert!(RigidBody::try_from_principal_moments(DVec3::splat(4e-28)).is_ok());
    /// assert!(RigidBody::try_from_principal_moments(DVec3::splat(8e37)).is_ok());
    /// // A subnormal moment cannot be represented.
    /// assert!(RigidBody::try_from_principal_moments(DVec3::splat(1e-320)).is_err());
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn try_from_principal_moments(moments: DVec3) -> Result<Self, DynamicsError> {
        let bad = |reason| DynamicsError::UnphysicalInertia {
            moments: moments.to_array(),
            reason,
        };
        if !moments.to_array().iter().all(|m| m.is_finite() && *m > 0.0) {
            return Err(bad("every principal moment must be positive and finite"));
        }
        if !moments.to_array().iter().all(|m| m.is_normal()) {
            return Err(bad(
                "a moment below 2.2e-308 kg m^2 is subnormal: it has lost its digits and cannot be represented",
            ));
        }
        if moments.min_element() / moments.max_element() < MIN_MOMENT_RATIO {
            return Err(bad("the moments span more than 100 orders of magnitude"));
        }
        // In the body's own unit (exact): no overflow for moments near f64::MAX.
        let [a, b, c] = (moments / moment_scale(moments)).to_array();
        let largest = a.max(b).max(c);
        if a + b + c - largest < largest * (1.0 - TRIANGLE_SLACK) {
            return Err(bad("the triangle inequality I₁ + I₂ ≥ I₃ is broken"));
        }
        Ok(Self {
            moments,
            body_from_principal: DQuat::IDENTITY,
        })
    }

    /// A body from its inertia tensor about the centre of mass, in body axes.
    ///
    /// ```text
    /// I = R diag(I₁, I₂, I₃) Rᵀ,   R = body_from_principal
    /// ```
    ///
    /// # Errors
    /// [`DynamicsError::InertiaTensor`] for a tensor that is not finite,
    /// symmetric and positive definite, and the checks of
    /// [`RigidBody::try_from_principal_moments`].
    ///
    /// ```
    /// use glam::{DMat3, DQuat, DVec3};
    /// use kreisel_dynamics::RigidBody;
    /// let r = DMat3::from_quat(DQuat::from_rotation_z(0.3));
    /// let tensor = r * DMat3::from_diagonal(DVec3::new(1.0, 2.0, 2.5)) * r.transpose();
    /// let body = RigidBody::try_from_inertia_tensor(tensor)?;
    /// assert!((body.principal_moments() - DVec3::new(1.0, 2.0, 2.5)).length() < 1e-14);
    /// // The reason is typed: which check, with its numbers.
    /// let mut skew = DMat3::IDENTITY;
    /// skew.x_axis.y = 0.5;
    /// let e = RigidBody::try_from_inertia_tensor(skew).unwrap_err();
    /// assert_eq!(e, kreisel_dynamics::DynamicsError::InertiaTensor {
    ///     error: kreisel_inertia::MassPropertiesError::NotSymmetric { asymmetry: 0.5 },
    /// });
    /// assert_eq!(e.to_string(), "inertia tensor: inertia tensor is not physical: tensor is not symmetric (asymmetry 5e-1)");
    /// # Ok::<(), kreisel_dynamics::DynamicsError>(())
    /// ```
    pub fn try_from_inertia_tensor(tensor: DMat3) -> Result<Self, DynamicsError> {
        let props = MassProperties::try_new(1.0, DVec3::ZERO, tensor)?;
        Self::from_mass_properties(&props)
    }

    /// A body from mass properties (the tensor about the centre of mass).
    ///
    /// ```text
    /// (I₁ ≤ I₂ ≤ I₃, R) = principal axes of props.inertia
    /// ```
    ///
    /// # Errors
    /// As [`RigidBody::try_from_principal_moments`] for the principal moments.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_dynamics::RigidBody;
    /// use kreisel_inertia::MassProperties;
    /// let brick = MassProperties::solid_box(1000.0, DVec3::new(0.1, 0.2, 0.3))?;
    /// let body = RigidBody::from_mass_properties(&brick).unwrap();
    /// assert!(body.principal_moments().x < body.principal_moments().z);
    /// # Ok::<(), kreisel_inertia::InertiaError>(())
    /// ```
    pub fn from_mass_properties(props: &MassProperties) -> Result<Self, DynamicsError> {
        let PrincipalAxes {
            moments,
            orientation,
            ..
        } = props.principal();
        let body = Self::try_from_principal_moments(moments)?;
        Ok(Self {
            body_from_principal: orientation,
            ..body
        })
    }

    /// Principal moments `(I₁, I₂, I₃)`, kg·m².
    pub fn principal_moments(&self) -> DVec3 {
        self.moments
    }

    /// The rotation from principal-frame to body-frame coordinates.
    pub fn body_from_principal(&self) -> DQuat {
        self.body_from_principal
    }
}
