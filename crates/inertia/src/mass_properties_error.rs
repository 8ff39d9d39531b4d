//! What makes a mass and an inertia tensor unphysical
//! ([`MassPropertiesError`]): typed and `Copy`, so that the engine carries
//! it in its own errors (`kreisel_dynamics::DynamicsError::InertiaTensor`)
//! as it is, not as a sentence.

use glam::DVec3;

/// Why [`crate::MassProperties::validate`] (or
/// [`crate::PrincipalAxes::try_from_tensor`]) refuses a mass and tensor.
///
/// ```text
/// m > 0 and finite,  c finite,  I finite,  I = Iᵀ,  I₁ ≥ 0,  I₁ + I₂ ≥ I₃   (to 1e-12 of max |I_ab|)
/// ```
///
/// The messages are those of [`crate::InertiaError`], which wraps this
/// type where a mesh or a file is involved too.
///
/// ```
/// use glam::{DMat3, DVec3};
/// use kreisel_inertia::{MassProperties, MassPropertiesError};
/// let e = MassProperties::try_new(1.0, DVec3::ZERO, DMat3::from_diagonal(DVec3::new(1.0, 1.0, 3.0))).unwrap_err();
/// assert_eq!(e, MassPropertiesError::TriangleInequality { moments: DVec3::new(1.0, 1.0, 3.0) });
/// assert!(e.to_string().contains("triangle inequality"), "{e}");
/// assert_eq!(MassProperties::try_new(-2.0, DVec3::ZERO, DMat3::IDENTITY).unwrap_err(), MassPropertiesError::Mass { value: -2.0 });
/// ```
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum MassPropertiesError {
    /// The mass is not positive and finite.
    #[error("mass must be positive and finite, got {value}")]
    Mass {
        /// The mass given, kg.
        value: f64,
    },
    /// The centre of mass has a non-finite coordinate.
    #[error("inertia tensor is not physical: centre of mass is not finite")]
    CentreOfMassNotFinite,
    /// The tensor has a non-finite element.
    #[error("inertia tensor is not physical: tensor has a non-finite element")]
    TensorNotFinite,
    /// The principal moments of a finite tensor overflow `f64`.
    #[error("inertia tensor is not physical: principal moments {moments} exceed the range of f64")]
    MomentsOverflow {
        /// The moments computed, kg·m².
        moments: DVec3,
    },
    /// `I ≠ Iᵀ` beyond 1e-12 of the largest element.
    #[error("inertia tensor is not physical: tensor is not symmetric (asymmetry {asymmetry:e})")]
    NotSymmetric {
        /// The largest `|I_ab − I_ba|`, kg·m².
        asymmetry: f64,
    },
    /// The smallest principal moment is negative beyond the tolerance.
    #[error(
        "inertia tensor is not physical: principal moment {moment:e} is negative (not positive semi-definite)"
    )]
    NegativeMoment {
        /// The smallest principal moment, kg·m².
        moment: f64,
    },
    /// `I₁ + I₂ < I₃` beyond the tolerance (moments ascending).
    #[error(
        "inertia tensor is not physical: principal moments {:e}, {:e}, {:e} break the triangle inequality I₁ + I₂ ≥ I₃",
        moments.x, moments.y, moments.z
    )]
    TriangleInequality {
        /// The principal moments, ascending, kg·m².
        moments: DVec3,
    },
}
