//! [`BodyOnGround`] on its own: which spins are steady, the normal
//! force there, and what is refused.

use glam::{DMat3, DVec3};
use kreisel_analysis::{AnalysisError, BodyOnGround, VectorField};
use kreisel_dynamics::{ContactShape, EllipsoidContact, Friction, GroundTop};

/// A spin about an axis that is not principal, or with the centre of
/// mass off the vertical through the contact, is no steady motion.
#[test]
fn unsteady_spins_are_refused() {
    let hull = ContactShape::Ellipsoid(
        EllipsoidContact::try_new(DVec3::new(0.2, 0.03, 0.02), DVec3::new(0.0, 0.0, 0.01)).unwrap(),
    );
    let i = DMat3::from_cols(
        DVec3::new(2e-4, 2e-5, 0.0),
        DVec3::new(2e-5, 16e-4, 0.0),
        DVec3::new(0.0, 0.0, 17e-4),
    );
    let top = GroundTop::try_with_shape(1.0, i, hull, Friction::Rolling, 9.81).unwrap();
    let field = BodyOnGround::try_from_ground_top(&top).unwrap();
    assert!(field.spinning_about_vertical(DVec3::Z, 5.0).is_ok());
    // Tilted: the centre of mass is off the contact's vertical.
    assert!(matches!(
        field.spinning_about_vertical(DVec3::new(0.1, 0.0, 1.0), 0.0),
        Err(AnalysisError::NoSuchMotion { .. })
    ));
    assert!(matches!(
        field.spinning_about_vertical(DVec3::ZERO, 1.0),
        Err(AnalysisError::Parameter {
            name: "up_body",
            ..
        })
    ));
    assert!(matches!(
        field.spinning_about_vertical(DVec3::Z, f64::NAN),
        Err(AnalysisError::Parameter { name: "spin", .. })
    ));
    assert!(field.normal_force(&[0.0; 6]).is_none());
}

/// Sliding, the normal force at a steady spin is the weight.
#[test]
fn the_normal_force_at_a_steady_spin_is_the_weight() {
    let ball =
        kreisel_dynamics::SphereContact::try_new(0.015, DVec3::new(0.0, 0.0, 0.003)).unwrap();
    let i = DMat3::from_diagonal(DVec3::new(8e-7, 8e-7, 7e-7));
    let top =
        GroundTop::try_new(0.006, i, ball, Friction::try_viscous(0.3).unwrap(), 9.81).unwrap();
    let field = BodyOnGround::try_from_ground_top(&top).unwrap();
    let x = field.spinning_about_vertical(-DVec3::Z, 100.0).unwrap();
    let n = field.normal_force(&x).unwrap();
    assert!((n / (0.006 * 9.81) - 1.0).abs() < 1e-15, "{n}");
    assert_eq!(field.state_names().len(), 9);
    assert!(!field.is_conservative());
}
