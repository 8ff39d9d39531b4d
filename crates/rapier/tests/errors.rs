//! Every error path of `RapierAdapterError`, and that nothing changes on
//! an error (the number of managed bodies, rapier's gyroscopic flag, the
//! body's state).

mod common;

use common::{body_with_moments, free_world, managed};
use kreisel_rapier::{ExactRotation, RapierAdapterError};
use rapier3d::prelude::*;

/// A dynamic cuboid in a world without gravity, spinning.
fn spinning_box(world: &mut PhysicsWorld) -> RigidBodyHandle {
    world
        .insert(
            RigidBodyBuilder::dynamic().angvel(Vector::new(0.3, 2.0, -0.1)),
            ColliderBuilder::cuboid(0.4, 0.2, 0.1),
        )
        .0
}

/// `manage` fails with an error matching `expected`, and neither the
/// adapter nor the body's gyroscopic flag changed.
fn assert_refused(
    world: &mut PhysicsWorld,
    exact: &mut ExactRotation,
    handle: RigidBodyHandle,
    expected: fn(&RapierAdapterError) -> bool,
) -> RapierAdapterError {
    let len = exact.len();
    let gyro = world
        .bodies
        .get(handle)
        .map(|rb| rb.gyroscopic_forces_enabled());
    let e = exact
        .manage(&mut world.bodies, &world.colliders, handle)
        .unwrap_err();
    assert!(expected(&e), "unexpected error {e:?}");
    assert!(!e.to_string().is_empty());
    assert_eq!(exact.len(), len);
    assert!(!exact.is_managed(handle));
    assert_eq!(
        world
            .bodies
            .get(handle)
            .map(|rb| rb.gyroscopic_forces_enabled()),
        gyro
    );
    e
}

#[test]
fn unknown_body_from_another_set_or_removed() {
    let mut world = free_world();
    let mut exact = ExactRotation::new();
    // A handle from another set: the other set's second body.
    let mut other = free_world();
    spinning_box(&mut other);
    let foreign = spinning_box(&mut other);
    let e = assert_refused(&mut world, &mut exact, foreign, |e| {
        matches!(e, RapierAdapterError::UnknownBody { .. })
    });
    assert_eq!(e, RapierAdapterError::UnknownBody { handle: foreign });
    // A removed body.
    let handle = spinning_box(&mut world);
    world.remove_body(handle);
    assert_refused(&mut world, &mut exact, handle, |e| {
        matches!(e, RapierAdapterError::UnknownBody { .. })
    });
}

#[test]
fn not_dynamic_fixed_and_kinematic() {
    let mut world = free_world();
    let mut exact = ExactRotation::new();
    for (builder, kind) in [
        (RigidBodyBuilder::fixed(), "fixed"),
        (
            RigidBodyBuilder::kinematic_position_based(),
            "kinematic (position-based)",
        ),
        (
            RigidBodyBuilder::kinematic_velocity_based(),
            "kinematic (velocity-based)",
        ),
    ] {
        let (handle, _) = world.insert(builder, ColliderBuilder::ball(0.5));
        let e = assert_refused(&mut world, &mut exact, handle, |e| {
            matches!(e, RapierAdapterError::NotDynamic { .. })
        });
        assert_eq!(e, RapierAdapterError::NotDynamic { handle, kind });
        assert!(e.to_string().contains(kind), "{e}");
    }
}

#[test]
fn rotation_locked_all_axes_or_one() {
    let mut world = free_world();
    let mut exact = ExactRotation::new();
    for builder in [
        RigidBodyBuilder::dynamic().lock_rotations(),
        RigidBodyBuilder::dynamic().enabled_rotations(true, false, true),
        RigidBodyBuilder::dynamic().enabled_rotations(true, true, false),
    ] {
        let (handle, _) = world.insert(builder, ColliderBuilder::cuboid(0.4, 0.2, 0.1));
        let e = assert_refused(&mut world, &mut exact, handle, |e| {
            matches!(e, RapierAdapterError::RotationLocked { .. })
        });
        assert_eq!(e, RapierAdapterError::RotationLocked { handle });
    }
}

#[test]
fn invalid_mass_properties_no_mass_or_triangle_inequality() {
    let mut world = free_world();
    let mut exact = ExactRotation::new();
    // No collider, no mass.
    let bare = world.insert_body(RigidBodyBuilder::dynamic().angvel(Vector::new(0.0, 1.0, 0.0)));
    let e = assert_refused(&mut world, &mut exact, bare, |e| {
        matches!(e, RapierAdapterError::InvalidMassProperties { .. })
    });
    let RapierAdapterError::InvalidMassProperties { mass, moments, .. } = e else {
        unreachable!()
    };
    assert_eq!((mass, moments), (0.0, [0.0; 3]));
    // Moments (1, 1, 3): I₁ + I₂ < I₃, no rigid body has them.
    let flat = body_with_moments(
        &mut world,
        Vector::new(1.0, 1.0, 3.0),
        Rotation::IDENTITY,
        Vector::ZERO,
        Rotation::IDENTITY,
        Vector::new(0.0, 1.0, 0.0),
    );
    let e = assert_refused(&mut world, &mut exact, flat, |e| {
        matches!(e, RapierAdapterError::InvalidMassProperties { .. })
    });
    let RapierAdapterError::InvalidMassProperties { mass, moments, .. } = e else {
        unreachable!()
    };
    assert_eq!(mass, 1.0);
    let mut sorted = moments;
    sorted.sort_by(f32::total_cmp);
    assert_eq!(sorted, [1.0, 1.0, 3.0]);
}

#[test]
fn mass_properties_changed_after_a_collider_is_added() {
    let mut world = free_world();
    let handle = spinning_box(&mut world);
    let mut exact = managed(&mut world, handle);
    exact.step_world(&mut world).unwrap();
    world.insert_collider(
        ColliderBuilder::ball(0.3).translation(Vector::new(0.5, 0.0, 0.0)),
        Some(handle),
    );
    // rapier updates the mass properties at its next step; the adapter
    // notices before the step after that one.
    let mut result = Ok(());
    for _ in 0..2 {
        result = exact.step_world(&mut world);
        if result.is_err() {
            break;
        }
    }
    assert_eq!(
        result,
        Err(RapierAdapterError::MassPropertiesChanged { handle })
    );
    assert_eq!(exact.len(), 1);
    // Release and manage again: the new mass properties are taken.
    assert!(exact.release(&mut world.bodies, handle));
    exact
        .manage(&mut world.bodies, &world.colliders, handle)
        .unwrap();
    exact.step_world(&mut world).unwrap();
}

#[test]
fn invalid_step_zero_negative_nan() {
    for dt in [0.0f32, -1.0 / 60.0, f32::NAN, f32::INFINITY] {
        let mut world = free_world();
        let handle = spinning_box(&mut world);
        let mut exact = managed(&mut world, handle);
        world.integration_parameters.dt = dt;
        let e = exact.step_world(&mut world).unwrap_err();
        match e {
            RapierAdapterError::InvalidStep { dt: got } => {
                assert!(got.to_bits() == dt.to_bits(), "{got} vs {dt}")
            }
            other => panic!("dt = {dt}: {other:?}"),
        }
        assert_eq!(exact.len(), 1);
        assert!(!world.bodies[handle].gyroscopic_forces_enabled());
    }
}

/// Regression: `step_world` took rapier's step before `after_step` refuses the
/// time step. A negative `dt` is harmless (rapier skips steps of
/// `dt <= 0`), but with `dt` = NaN or ∞ rapier integrates, finds the
/// body's state non-finite and quarantines it (velocity zeroed, body
/// disabled) before the adapter reports `InvalidStep`.
#[test]
fn invalid_step_leaves_rapier_untouched() {
    for dt in [-1.0 / 60.0, f32::NAN, f32::INFINITY] {
        let mut world = free_world();
        let handle = spinning_box(&mut world);
        let mut exact = managed(&mut world, handle);
        let rb = &world.bodies[handle];
        let before = (*rb.position(), rb.angvel(), rb.is_enabled());
        world.integration_parameters.dt = dt;
        assert!(exact.step_world(&mut world).is_err());
        let rb = &world.bodies[handle];
        let after = (*rb.position(), rb.angvel(), rb.is_enabled());
        assert!(
            after.0.rotation == before.0.rotation
                && after.0.translation == before.0.translation
                && after.1 == before.1
                && after.2 == before.2,
            "dt = {dt}: rapier's body went from {before:?} to {after:?}"
        );
    }
}

#[test]
fn dynamics_error_for_a_non_finite_angular_velocity() {
    let mut world = free_world();
    let handle = spinning_box(&mut world);
    let mut exact = ExactRotation::new();
    // At manage.
    world.bodies[handle].set_angvel(Vector::new(f32::NAN, 1.0, 0.0), false);
    let e = assert_refused(&mut world, &mut exact, handle, |e| {
        matches!(e, RapierAdapterError::Dynamics { .. })
    });
    assert!(matches!(e, RapierAdapterError::Dynamics { handle: h, .. } if h == handle));
    // Set by the user mid-flight: refused before rapier's step is taken.
    world.bodies[handle].set_angvel(Vector::new(0.3, 2.0, -0.1), false);
    exact
        .manage(&mut world.bodies, &world.colliders, handle)
        .unwrap();
    exact.step_world(&mut world).unwrap();
    world.bodies[handle].set_angvel(Vector::new(0.0, f32::INFINITY, 0.0), false);
    let before = *world.bodies[handle].position();
    let e = exact.step_world(&mut world).unwrap_err();
    assert!(matches!(e, RapierAdapterError::Dynamics { handle: h, .. } if h == handle));
    assert_eq!(world.bodies[handle].position().rotation, before.rotation);
    assert_eq!(exact.len(), 1);
    assert!(!world.bodies[handle].gyroscopic_forces_enabled());
}
