//! Ground bodies in the library's `World` with further contact shapes
//! (`BodyBuilder::other_contacts`): Leine & Glocker's tippe top watching
//! its stem ball (sliding ε = 1 mm/s, and viscous friction) stops at the
//! stem's touchdown at the time of the committed
//! scipy generator of the same equations
//! (`tests/data/contact/tippe_top_touchdown.csv`, `python3
//! tests/data/gen/tippe_top.py --touchdown`), as the world's failure with
//! the state left at the touchdown; a start or a setter that puts a further
//! shape into the table, and further shapes where they mean nothing, are
//! typed errors.

mod common;

use glam::{DQuat, DVec3};
use kreisel_dynamics::{
    AdaptiveTolerance, Body, BodyBuilder, ContactShape, DynamicsError, Friction,
    MAX_OTHER_CONTACTS, Plan, SphereContact, World,
};

use common::tippe_top::{
    A, G, I1, I3, M, MU, R, STEM_C, STEM_R, stem, touchdown_reference, world_builder,
};

/// The world's gravity.
const GRAVITY: DVec3 = DVec3::new(0.0, 0.0, -G);

/// Leine & Glocker's tippe top on the ground with `friction`, watching
/// its stem ball.
fn tippe_top(friction: Friction) -> BodyBuilder {
    world_builder(friction).other_contacts(&[stem()])
}

/// The stem ball's gap: the height of its lowest point, m.
fn stem_gap(position: DVec3, world_from_body: DQuat) -> f64 {
    position.z + (world_from_body.normalize() * DVec3::new(0.0, 0.0, STEM_C)).z - STEM_R
}

// Measured (dt = 1e-5 s): see the eprintln.
#[test]
fn the_stem_touches_down_in_the_world_at_the_generators_time() {
    stem_touchdown("sliding", Friction::try_sliding(MU, 1e-3).unwrap());
}

#[test]
fn the_viscous_stem_touches_down_in_the_world_at_the_generators_time() {
    stem_touchdown("viscous", Friction::try_viscous(MU).unwrap());
}

/// The world runs the tippe top with `friction` until its stem touches
/// down; checked against the generator's `scenario` row.
fn stem_touchdown(scenario: &str, friction: Friction) {
    let reference = touchdown_reference(scenario);
    let (t_ref, t_coarse, speed_ref) = (
        reference.time,
        reference.time_coarse,
        reference.approach_speed,
    );
    let body = tippe_top(friction).try_build().unwrap();
    assert_eq!(body.other_contacts(), &[stem()]);
    let mut world = World::try_new(GRAVITY, 1e-5).unwrap();
    let id = world.add(body).unwrap();
    assert_eq!(
        world.plan(id),
        Some(&Plan::OnGround {
            friction: friction.model(),
            watched: 1,
            tolerance: AdaptiveTolerance::new(1e-11, 1e-11),
        })
    );
    let err = world.advance_to(10.0).unwrap_err();
    let DynamicsError::BodyFailed {
        body,
        time: step_end,
        source,
    } = &err
    else {
        panic!("{err}");
    };
    let DynamicsError::ContactTouchdown {
        time,
        contact,
        approach_speed,
    } = **source
    else {
        panic!("{err}");
    };
    let s = world.state(id).unwrap();
    let gap = stem_gap(s.position, s.world_from_body);
    eprintln!(
        "{scenario}: {err}\ngenerator {t_ref} s, Δt/t = {:.1e}; approach {approach_speed} vs {speed_ref} m/s; \
         stem gap there {gap:e} m",
        (time - t_ref).abs() / t_ref
    );
    assert_eq!((*body, contact), (0, 0));
    // The reference's own error (its rtol 1e-11 run) is far below the bound.
    assert!((t_coarse - t_ref).abs() < 1e-8 * t_ref);
    assert!((time - t_ref).abs() <= 1e-6 * t_ref, "{time} vs {t_ref}");
    assert!(
        (approach_speed / speed_ref - 1.0).abs() < 1e-5,
        "{approach_speed} vs {speed_ref}"
    );
    // The world's failure names the step that ended after it.
    assert!(*step_end >= time && *step_end - time <= 1e-5, "{step_end}");
    // The body holds the state at the touchdown: the stem ball on the
    // table to round-off (the model leaves its own gap ≤ 0; this one is
    // computed here, in another order: ±1e-18 m of a 17 mm height), the
    // main ball still touching.
    assert!(gap.abs() < 1e-15, "stem gap {gap:e} m");
    let ball_gap = s.position.z + (s.world_from_body.normalize() * DVec3::new(0.0, 0.0, A)).z - R;
    assert!(ball_gap.abs() < 1e-10, "ball gap {ball_gap:e} m");
    // Nearly inverted there: the axis well past the horizontal.
    let tilt = (s.world_from_body.normalize() * DVec3::Z).z.acos();
    assert!(tilt > 2.0, "tilt {tilt} rad");
    // The world refuses to move on, with the same error.
    assert_eq!(
        world.advance_steps(1).unwrap_err().to_string(),
        err.to_string()
    );
}

#[test]
fn watching_a_far_shape_leaves_the_motion_bit_for_bit_unchanged() {
    let friction = Friction::try_viscous(MU).unwrap();
    let mut states = Vec::new();
    for others in [&[][..], &[stem()][..]] {
        let mut world = World::try_new(GRAVITY, 1e-5).unwrap();
        let id = world
            .add(
                tippe_top(friction)
                    .other_contacts(others)
                    .try_build()
                    .unwrap(),
            )
            .unwrap();
        world.advance_steps(2000).unwrap();
        states.push(world.state(id).unwrap());
    }
    assert_eq!(states[0], states[1]);
}

#[test]
fn further_shapes_that_touch_or_mean_nothing_are_typed_errors() {
    let friction = Friction::None;
    let mut world = World::try_new(GRAVITY, 1e-4).unwrap();
    // Upside down, the stem's ball would be in the table: refused at add,
    // the world left empty.
    let upside_down = tippe_top(friction)
        .world_from_body(DQuat::from_rotation_x(3.0))
        .try_build()
        .unwrap();
    let e = world.add(upside_down).unwrap_err();
    let DynamicsError::OtherContactTouching { contact: 0, gap } = e else {
        panic!("{e}");
    };
    let expected = stem_gap(
        DVec3::new(0.0, 0.0, R - A * 3f64.cos()),
        DQuat::from_rotation_x(3.0),
    );
    assert!(
        (gap - expected).abs() < 1e-15 && gap < 0.0,
        "{gap} vs {expected}"
    );
    assert!(world.is_empty());
    // The second of two further shapes touching is named.
    let low = ContactShape::Sphere(SphereContact::try_new(0.02, DVec3::ZERO).unwrap());
    let e = world
        .add(
            tippe_top(friction)
                .other_contacts(&[stem(), low])
                .try_build()
                .unwrap(),
        )
        .unwrap_err();
    assert!(
        matches!(e, DynamicsError::OtherContactTouching { contact: 1, .. }),
        "{e}"
    );
    // A setter that turns the stem into the table is refused, the state kept.
    let id = world.add(tippe_top(friction).try_build().unwrap()).unwrap();
    let before = world.state(id).unwrap();
    let e = world
        .set_rotation(id, DQuat::from_rotation_x(3.0), DVec3::ZERO)
        .unwrap_err();
    assert!(
        matches!(e, DynamicsError::OtherContactTouching { contact: 0, .. }),
        "{e}"
    );
    assert_eq!(world.state(id).unwrap(), before);
    // More than the capacity.
    let many = [stem(); MAX_OTHER_CONTACTS + 1];
    let e = tippe_top(friction)
        .other_contacts(&many)
        .try_build()
        .unwrap_err();
    assert!(
        matches!(
            e,
            DynamicsError::InvalidContact {
                parameter: "other_contacts",
                ..
            }
        ),
        "{e}"
    );
    assert_eq!(
        tippe_top(friction)
            .other_contacts(&many[..MAX_OTHER_CONTACTS])
            .try_build()
            .unwrap()
            .other_contacts()
            .len(),
        MAX_OTHER_CONTACTS
    );
    // Further shapes on a body that is not on the ground.
    for builder in [
        Body::from_principal_moments(M, DVec3::new(I1, I1, I3)),
        Body::from_principal_moments(M, DVec3::new(I1, I1, I3)).pivot(DVec3::ZERO, DVec3::ZERO),
    ] {
        let e = builder.other_contacts(&[stem()]).try_build().unwrap_err();
        assert!(
            matches!(
                e,
                DynamicsError::InvalidBody {
                    field: "other_contacts",
                    ..
                }
            ),
            "{e}"
        );
    }
}
