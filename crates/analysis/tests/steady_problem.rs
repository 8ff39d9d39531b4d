//! Steady motions found near a body's state, changed one parameter at a
//! time, and the maps' boundaries against the closed forms.

use glam::{DQuat, DVec3};
use kreisel_analysis::{AnalysisError, Parameter, Precession, StabilityMap, SteadyProblem, Sweep};
use kreisel_dynamics::Body;

const G: DVec3 = DVec3::new(0.0, 0.0, -9.81);

/// A symmetric top, 1 kg, centre of mass `l` above the pivot along body z.
fn top(l: f64, world_from_body: DQuat, omega_body: DVec3) -> Body {
    Body::from_principal_moments(1.0, DVec3::new(0.02, 0.02, 0.01))
        .world_from_body(world_from_body)
        .omega_body(omega_body)
        .pivot(DVec3::new(0.0, 0.0, -l), DVec3::ZERO)
        .try_build()
        .unwrap()
}

#[test]
fn the_t_handle_s_state_is_near_its_unstable_intermediate_axis() {
    let body = Body::from_principal_moments(1.0, DVec3::new(1.0, 2.0, 3.0))
        .omega_body(DVec3::new(1e-3, 5.0, -2e-3))
        .try_build()
        .unwrap();
    let problem = SteadyProblem::near(&body, G).unwrap();
    let SteadyProblem::FreeRotation { axis, spin, .. } = problem else {
        panic!("{problem:?}")
    };
    // |L| kept: 2·5 ≈ |L| of the start.
    let l_start = (DVec3::new(1.0, 2.0, 3.0) * DVec3::new(1e-3, 5.0, -2e-3)).length();
    assert_eq!(axis, 1);
    assert!(
        (2.0 * spin.abs() - l_start).abs() < 1e-12 * l_start,
        "{spin}"
    );
    assert_eq!(problem.linearise().unwrap().verdict.name(), "unstable");
}

#[test]
fn a_nearly_sleeping_top_is_found_sleeping_and_a_tilted_one_precessing() {
    let spin = 60.0;
    let body = top(
        0.1,
        DQuat::from_rotation_x(1e-7),
        DVec3::new(0.0, 0.0, spin),
    );
    let problem = SteadyProblem::near(&body, G).unwrap();
    let SteadyProblem::SleepingTop {
        spin: found,
        hanging: false,
        ..
    } = problem
    else {
        panic!("{problem:?}")
    };
    assert!((found - spin).abs() < 1e-9 * spin, "{found}");

    // Started exactly at the slow precession at θ₀ = 0.5 (φ̇ from the
    // family), it is found there, slow, at the same tilt and spin.
    let reference = SteadyProblem::Precession {
        top: match SteadyProblem::near(&top(0.1, DQuat::IDENTITY, DVec3::Z), G).unwrap() {
            SteadyProblem::SleepingTop { top, .. } => top,
            other => panic!("{other:?}"),
        },
        tilt: 0.5,
        spin,
        which: Precession::Slow,
    };
    let family = kreisel_analysis::PrecessingTop::try_new(0.03, 0.01, 0.981).unwrap();
    let phi_dot = family.precession_rate(0.5, spin, Precession::Slow).unwrap();
    let omega_body = DVec3::new(0.0, phi_dot * 0.5f64.sin(), spin);
    let found = SteadyProblem::near(&top(0.1, DQuat::from_rotation_x(0.5), omega_body), G).unwrap();
    let SteadyProblem::Precession {
        tilt,
        spin: s,
        which,
        ..
    } = &found
    else {
        panic!("{found:?}")
    };
    assert!(
        (tilt - 0.5).abs() < 1e-12 && (s - spin).abs() < 1e-12 * spin,
        "{tilt} {s}"
    );
    assert_eq!(*which, Precession::Slow);
    let a = found.linearise().unwrap().eigenvalues();
    let b = reference.linearise().unwrap().eigenvalues();
    assert!((a[0].im - b[0].im).abs() < 1e-9 * b[0].im.abs());
}

/// The bisected boundary of a map against the closed form: spin (the
/// notes' Ω_c), gravity and the centre-of-mass offset (the cubic), to
/// 1e-12 relative.
#[test]
fn map_boundaries_match_the_closed_forms() {
    let start =
        SteadyProblem::near(&top(0.1, DQuat::IDENTITY, DVec3::new(0.0, 0.0, 40.0)), G).unwrap();
    for (parameter, from, to) in [
        (Parameter::Spin, 0.0, 80.0),
        (Parameter::Gravity, 1.0, 20.0),
        (Parameter::ComOffset, 0.02, 0.3),
    ] {
        let sweep = Sweep::try_new(parameter.name(), from, to, 9).unwrap();
        let map = StabilityMap::try_new(&[sweep], None, |p| {
            let mut problem = start.clone();
            problem.set(parameter, p[0])?;
            problem.linearise()
        })
        .unwrap();
        let expected = start.closed_form_boundary(parameter).unwrap();
        let inside: Vec<f64> = expected
            .into_iter()
            .filter(|v| *v > from && *v < to)
            .collect();
        assert_eq!(map.boundaries.len(), inside.len(), "{parameter}");
        for (b, e) in map.boundaries.iter().zip(&inside) {
            let error = b.at[0] / e - 1.0;
            eprintln!(
                "{parameter}: boundary {:.15} vs closed form {e:.15} ({error:.1e})",
                b.at[0]
            );
            assert!(error.abs() <= 1e-12, "{parameter}: {error:e}");
        }
    }
}

#[test]
fn bad_parameters_and_states_say_what_is_wrong() {
    let mut free = SteadyProblem::FreeRotation {
        moments: DVec3::new(1.0, 2.0, 3.0),
        axis: 2,
        spin: 1.0,
    };
    let e = free.set(Parameter::Tilt, 0.1).unwrap_err();
    assert_eq!(
        e.to_string(),
        "sweep tilt: a free rotation about a principal axis has no tilt (it has spin)"
    );
    assert!(free.set(Parameter::Spin, f64::NAN).is_err());
    // An asymmetric top held tilted at rest: no steady motion near it.
    let body = Body::from_principal_moments(1.0, DVec3::new(0.02, 0.03, 0.01))
        .world_from_body(DQuat::from_rotation_x(0.7))
        .pivot(DVec3::new(0.0, 0.0, -0.1), DVec3::ZERO)
        .try_build()
        .unwrap();
    match SteadyProblem::near(&body, G) {
        Err(
            e @ AnalysisError::NoSteadyMotionNearby {
                start,
                relative_distance,
                ..
            },
        ) => {
            // Upright at rest has the same Casimirs, 0.7 rad away.
            assert!(start > 1e-3 && relative_distance > 0.5, "{e}");
            assert!(
                e.to_string()
                    .starts_with("no steady motion near this state: relative residual")
            );
        }
        other => panic!("{other:?}"),
    }
}

/// Leine & Glocker's tippe top spinning upright on the table (one sphere,
/// Coulomb μ = 0.3, touching): no slip at the contact, so it is analysed
/// rolling — the same eigenvalues as the tippe-top family built from its
/// parameters with `Friction::Rolling`, to 1e-12; with μ = 0 it is the
/// frictionless family. Two contacts, or a drilling torque, are refused.
#[test]
fn a_top_spinning_on_the_table_is_the_rolling_top() {
    use kreisel_analysis::{LEINE_GLOCKER, Linearisation, TippeTop};
    use kreisel_dynamics::{ContactLaw, ContactShape, Friction, SphereContact, TableContact};
    let sphere =
        ContactShape::Sphere(SphereContact::try_new(0.015, DVec3::new(0.0, 0.0, 0.003)).unwrap());
    let on_table = |laws: &[ContactLaw]| {
        let contacts: Vec<TableContact> = laws
            .iter()
            .map(|&law| TableContact { shape: sphere, law })
            .collect();
        Body::from_principal_moments(0.006, DVec3::new(8e-7, 8e-7, 7e-7))
            .omega_body(DVec3::new(0.0, 0.0, 180.0))
            .on_table(DVec3::new(0.0, 0.0, 0.015 - 0.003), DVec3::ZERO, &contacts)
            .try_build()
            .unwrap()
    };
    let sorted = |lin: &Linearisation| {
        let mut v: Vec<(f64, f64)> = lin.eigenvalues().iter().map(|e| (e.re, e.im)).collect();
        v.sort_by(|a, b| a.1.total_cmp(&b.1).then(a.0.total_cmp(&b.0)));
        v
    };
    for (mu, friction) in [(0.3, Friction::Rolling), (0.0, Friction::None)] {
        let problem = SteadyProblem::near(&on_table(&[ContactLaw::new(mu)]), G).unwrap();
        assert_eq!(
            problem.kind(),
            "spin about the vertical on its contact point"
        );
        let found = problem.linearise().unwrap();
        let family = TippeTop::try_new(LEINE_GLOCKER, friction).unwrap();
        let reference =
            Linearisation::try_new(&family, &family.spinning_upright(180.0).unwrap()).unwrap();
        assert_eq!(found.verdict.name(), reference.verdict.name(), "μ = {mu}");
        let (a, b) = (sorted(&found), sorted(&reference));
        assert_eq!(a.len(), b.len());
        for (x, y) in a.iter().zip(&b) {
            let scale = y.0.hypot(y.1).max(1.0);
            assert!(
                (x.0 - y.0).abs() <= 1e-12 * scale && (x.1 - y.1).abs() <= 1e-12 * scale,
                "μ = {mu}: {x:?} vs {y:?}"
            );
        }
    }
    let two = on_table(&[ContactLaw::new(0.3), ContactLaw::new(0.3)]);
    assert!(matches!(
        SteadyProblem::near(&two, G),
        Err(AnalysisError::NoSuchMotion { .. })
    ));
    let drilling = ContactLaw::try_new(0.3)
        .unwrap()
        .try_with_contensou_radius(1e-3)
        .unwrap();
    let e = SteadyProblem::near(&on_table(&[drilling]), G).unwrap_err();
    assert!(e.to_string().contains("drilling torque"), "{e}");
}

/// Regression: a reaction wheel spun up by a motor (`spin_up.toml`) was
/// analysed as a free body at rest ("neutral"), its torque ignored. A
/// driven body is refused, named or nearest.
#[test]
fn a_driven_body_is_refused() {
    use kreisel_analysis::SteadyKind;
    use kreisel_dynamics::Inputs;
    let wheel = Body::from_principal_moments(1.0, DVec3::new(0.01, 0.01, 0.02))
        .with_inputs(Inputs::default().with_torque_body(DVec3::new(0.0, 0.0, 0.1)))
        .try_build()
        .unwrap();
    for kind in [SteadyKind::Nearest, SteadyKind::Sleeping] {
        let e = SteadyProblem::named(&wheel, G, kind).unwrap_err();
        assert!(e.to_string().contains("the body is driven"), "{e}");
    }
}
