//! Managing and releasing bodies, and who carries them: rapier's
//! gyroscopic flag, re-managing, removed bodies, joints, sleep, a throw
//! from the ground.

mod common;

use common::{angle, attitude, free_world, managed};
use kreisel_rapier::{Carrier, ExactRotation};
use rapier3d::prelude::*;

fn spinning_box(world: &mut PhysicsWorld, y: f32) -> RigidBodyHandle {
    world
        .insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(0.0, y, 0.0))
                .angvel(Vector::new(0.3, 2.0, -0.1)),
            ColliderBuilder::cuboid(0.4, 0.2, 0.1),
        )
        .0
}

/// A world with gravity and a ground box whose top face is at y = 0.
fn world_with_ground() -> PhysicsWorld {
    let mut world = PhysicsWorld::new();
    world.insert_collider(
        ColliderBuilder::cuboid(20.0, 0.5, 20.0).translation(Vector::new(0.0, -0.5, 0.0)),
        None,
    );
    world
}

#[test]
fn manage_and_release_switch_rapiers_gyroscopic_term() {
    let mut world = free_world();
    let handle = spinning_box(&mut world, 0.0);
    let other = spinning_box(&mut world, 5.0);
    assert!(world.bodies[handle].gyroscopic_forces_enabled());
    let mut exact = ExactRotation::new();
    assert!(exact.is_empty());
    assert_eq!(exact.carrier(handle), None);
    assert!(exact.rotation(handle).is_none());
    exact
        .manage(&mut world.bodies, &world.colliders, handle)
        .unwrap();
    assert!(!world.bodies[handle].gyroscopic_forces_enabled());
    assert!(world.bodies[other].gyroscopic_forces_enabled());
    assert_eq!(exact.carrier(handle), Some(Carrier::Kreisel));
    assert_eq!(exact.carrier(other), None);
    assert!(!exact.release(&mut world.bodies, other));
    assert!(world.bodies[other].gyroscopic_forces_enabled());
    assert!(exact.release(&mut world.bodies, handle));
    assert!(world.bodies[handle].gyroscopic_forces_enabled());
    assert!(exact.is_empty());
    assert_eq!(exact.carrier(handle), None);
    assert!(!exact.release(&mut world.bodies, handle));
}

#[test]
fn managing_twice_resynchronises_without_a_second_twin() {
    let mut world = free_world();
    let handle = spinning_box(&mut world, 0.0);
    let mut exact = managed(&mut world, handle);
    for _ in 0..10 {
        exact.step_world(&mut world).unwrap();
    }
    // rapier's state changed behind the adapter's back, then manage again.
    let omega = Vector::new(-1.0, 0.5, 3.0);
    world.bodies[handle].set_angvel(omega, false);
    exact
        .manage(&mut world.bodies, &world.colliders, handle)
        .unwrap();
    assert_eq!(exact.len(), 1);
    assert_eq!(exact.world().len(), 1);
    let now = exact.rotation(handle).unwrap();
    let error = (now.omega_world - common::d(omega)).length();
    assert!(error <= 1e-6 * common::d(omega).length(), "{error:e}");
}

#[test]
fn a_removed_body_is_released_at_the_next_step() {
    let mut world = free_world();
    let a = spinning_box(&mut world, 0.0);
    let b = spinning_box(&mut world, 5.0);
    let mut exact = managed(&mut world, a);
    exact
        .manage(&mut world.bodies, &world.colliders, b)
        .unwrap();
    exact.step_world(&mut world).unwrap();
    world.remove_body(a);
    assert_eq!(exact.len(), 2);
    exact.step_world(&mut world).unwrap();
    assert_eq!(exact.len(), 1);
    assert!(!exact.is_managed(a));
    assert_eq!(exact.carrier(a), None);
    // The other body is still carried, and still exactly: L_world kept.
    let l0 = exact.rotation(b).unwrap().l_world;
    for _ in 0..30 {
        exact.step_world(&mut world).unwrap();
    }
    let l = exact.rotation(b).unwrap().l_world;
    assert!((l - l0).length() <= 1e-13 * l0.length(), "{l} vs {l0}");
}

#[test]
fn a_jointed_body_is_carried_by_rapier() {
    let mut world = free_world();
    let anchor = world.insert_body(RigidBodyBuilder::fixed());
    let handle = spinning_box(&mut world, 0.0);
    let joint = RevoluteJointBuilder::new(Vector::Y)
        .local_anchor1(Vector::ZERO)
        .local_anchor2(Vector::new(0.4, 0.0, 0.0));
    world.insert_impulse_joint(anchor, handle, joint);
    let mut exact = managed(&mut world, handle);
    exact.step_world(&mut world).unwrap();
    assert_eq!(exact.carrier(handle), Some(Carrier::Rapier));
    assert!(world.bodies[handle].gyroscopic_forces_enabled());
    assert!(exact.rotation(handle).is_none());
    for _ in 0..60 {
        exact.step_world(&mut world).unwrap();
        assert_eq!(exact.carrier(handle), Some(Carrier::Rapier));
    }
}

/// Steps until the body sleeps (at most `max` steps); the step count.
fn steps_to_sleep(
    world: &mut PhysicsWorld,
    handle: RigidBodyHandle,
    mut exact: Option<&mut ExactRotation>,
    max: usize,
) -> Option<usize> {
    for k in 1..=max {
        match exact.as_deref_mut() {
            Some(exact) => exact.step_world(world).unwrap(),
            None => world.step(),
        }
        if world.bodies[handle].is_sleeping() {
            return Some(k);
        }
    }
    None
}

#[test]
fn a_resting_body_falls_asleep_as_in_rapier_alone() {
    let scene = || {
        let mut world = world_with_ground();
        let (handle, _) = world.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(0.0, 0.3, 0.0))
                .angvel(Vector::new(0.0, 1.0, 0.0)),
            ColliderBuilder::cuboid(0.4, 0.2, 0.1),
        );
        (world, handle)
    };
    let (mut alone, h) = scene();
    let n_alone = steps_to_sleep(&mut alone, h, None, 600).expect("rapier alone sleeps");
    let (mut world, handle) = scene();
    let mut exact = managed(&mut world, handle);
    let n = steps_to_sleep(&mut world, handle, Some(&mut exact), 600).expect("managed sleeps");
    println!("asleep after {n_alone} steps (rapier alone), {n} (managed)");
    assert!(n <= 300, "{n} steps");
    assert!(n.abs_diff(n_alone) <= 30, "{n} vs {n_alone}");
    assert_eq!(exact.carrier(handle), Some(Carrier::Rapier));
    assert!(world.bodies[handle].gyroscopic_forces_enabled());
    // Asleep it stays put.
    let q = attitude(&world.bodies[handle]);
    for _ in 0..30 {
        exact.step_world(&mut world).unwrap();
    }
    assert!(world.bodies[handle].is_sleeping());
    assert_eq!(q, attitude(&world.bodies[handle]));
}

#[test]
fn a_thrown_body_is_carried_by_kreisel_in_flight_and_by_rapier_after_landing() {
    let mut world = world_with_ground();
    let (handle, _) = world.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(0.0, 0.25, 0.0))
            .linvel(Vector::new(0.0, 5.0, 0.0))
            .angvel(Vector::new(0.5, 4.0, 0.2)),
        ColliderBuilder::cuboid(0.4, 0.2, 0.1),
    );
    let mut exact = managed(&mut world, handle);
    let mut carriers = Vec::new();
    let mut heights = Vec::new();
    for _ in 0..180 {
        exact.step_world(&mut world).unwrap();
        carriers.push(exact.carrier(handle).unwrap());
        heights.push(world.bodies[handle].center_of_mass().y);
    }
    // Up and down at 5 m/s under 9.81 m/s²: about 1 s = 60 steps of
    // flight, the centre of mass above 0.9 m from 0.17 s to 0.67 s.
    let landed_at = carriers
        .iter()
        .position(|&c| c == Carrier::Rapier)
        .expect("landed");
    let switches = carriers.windows(2).filter(|w| w[0] != w[1]).count();
    println!(
        "landed after {} steps at y = {}; {switches} switches",
        landed_at + 1,
        heights[landed_at]
    );
    assert!(carriers[..40].iter().all(|&c| c == Carrier::Kreisel));
    assert!(heights[10..40].iter().all(|&y| y > 0.5));
    assert!((50..=70).contains(&landed_at), "{landed_at}");
    assert!(heights[landed_at] < 0.5, "{}", heights[landed_at]);
    // 2 s after landing it lies on the ground, carried by rapier.
    assert_eq!(carriers.last(), Some(&Carrier::Rapier));
    assert!(heights.last().unwrap() < &0.5);
    assert!(world.bodies[handle].gyroscopic_forces_enabled());
}

/// Regression: a disabled body (`RigidBody::set_enabled(false)`) is not moved
/// by rapier, but the adapter sees it as free (awake, no contact, no
/// joint) and keeps turning it with the exact flow.
#[test]
fn a_disabled_body_stays_put() {
    let mut world = free_world();
    let handle = spinning_box(&mut world, 0.0);
    let mut exact = managed(&mut world, handle);
    exact.step_world(&mut world).unwrap();
    world.bodies[handle].set_enabled(false);
    let q = *world.bodies[handle].rotation();
    for _ in 0..10 {
        exact.step_world(&mut world).unwrap();
    }
    let now = *world.bodies[handle].rotation();
    let moved = angle(attitude_of(q), attitude_of(now));
    assert!(q == now, "a disabled body turned by {moved} rad");
}

/// A managed body changed after `manage` (by `change`), then stepped 10
/// times by rapier alone (released) and with the adapter: the two
/// bodies' angular velocities.
fn changed_after_manage(change: fn(&mut RigidBody)) -> [Vector; 2] {
    [false, true].map(|keep| {
        let mut world = free_world();
        let handle = spinning_box(&mut world, 0.0);
        let mut exact = managed(&mut world, handle);
        exact.step_world(&mut world).unwrap();
        if !keep {
            exact.release(&mut world.bodies, handle);
        }
        change(&mut world.bodies[handle]);
        for _ in 0..10 {
            exact.step_world(&mut world).unwrap();
        }
        world.bodies[handle].angvel()
    })
}

/// Regression: a managed body made kinematic after `manage` is still carried by
/// the adapter: its prescribed angular velocity is replaced by the
/// torque-free flow's (rapier alone keeps it constant). `before_step`
/// checks the mass properties but not the body type.
#[test]
fn a_body_made_kinematic_keeps_its_prescribed_angular_velocity() {
    let [alone, with] =
        changed_after_manage(|rb| rb.set_body_type(RigidBodyType::KinematicVelocityBased, true));
    assert_eq!(with, alone);
}

/// A rapier rotation in `f64`, normalised.
fn attitude_of(q: Rotation) -> glam::DQuat {
    kreisel_kinematics::glam033_interop::dquat_from_quat(q).normalize()
}
