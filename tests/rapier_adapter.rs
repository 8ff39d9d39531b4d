//! kreisel-rapier's `ExactRotation` on rapier3d (`f32`): rapier's tumbling
//! T-handle at every dt from 1/30 to 1/240 against the 60-digit mpmath
//! period (`tests/data/free_body/periods.csv`), contact scenes against
//! rapier alone (energy never added), and every error path.
//!
//! `cargo test --release --test rapier_adapter -- --nocapture` prints the
//! numbers of both engines.

#[allow(dead_code)]
#[path = "../examples/rapier_tumble/main.rs"]
mod demo;

use demo::tumble::{self, Engine};
use kreisel_rapier::ExactRotation;
use rapier3d::prelude::*;

/// The mpmath period of ω for rapier's scenario (ω₀ = (0.01, 1, 0) in
/// f64; the f32 ω₀ the engines start from moves it by 4e-9 relative).
fn reference_period() -> f64 {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/free_body/periods.csv"
    );
    let text = std::fs::read_to_string(path).expect("periods.csv");
    let row = text
        .lines()
        .find(|l| l.starts_with("rapier,"))
        .expect("rapier row");
    row.split(',').nth(1).unwrap().parse().unwrap()
}

#[test]
fn tumbling_t_handle_period_and_drift_at_every_dt() {
    let exact = reference_period();
    for steps_per_second in [30.0f32, 60.0, 120.0, 240.0] {
        let dt = 1.0 / steps_per_second;
        let alone = tumble::run(Engine::Rapier, dt, 100.0).unwrap();
        let with = tumble::run(Engine::RapierKreisel, dt, 100.0).unwrap();
        let relative = |p: Option<f64>| (p.expect("two flips in 100 s") - exact) / exact;
        let (e_alone, e_with) = (relative(alone.period()), relative(with.period()));
        println!(
            "dt = 1/{steps_per_second}: period error rapier {e_alone:+.2e}, rapier+kreisel {e_with:+.2e}; \
             worst |L|, energy drift rapier {:+.1e}, {:+.1e}; rapier+kreisel {:+.1e}, {:+.1e}",
            alone.worst.0, alone.worst.1, with.worst.0, with.worst.1
        );
        assert!(
            e_with.abs() <= 1e-6,
            "dt = 1/{steps_per_second}: {e_with:e}"
        );
        assert!(
            with.worst.0.abs() <= 1e-6 && with.worst.1.abs() <= 1e-6,
            "{:?}",
            with.worst
        );
        // rapier alone is first order in dt: far off at these steps.
        assert!(e_alone.abs() > 100.0 * e_with.abs());
    }
}

/// Total energy of a body from rapier's (`f32`) state, in `f64`:
/// translational + rotational + gravitational (gravity −9.81 along y).
fn total_energy(rb: &RigidBody) -> f64 {
    let f = |v: Vector| kreisel::kinematics::glam::DVec3::new(v.x.into(), v.y.into(), v.z.into());
    let props = &rb.mass_properties().local_mprops;
    let mass = f64::from(props.mass());
    let frame = *rb.rotation() * props.principal_inertia_local_frame;
    let q = kreisel::kinematics::glam::DQuat::from_xyzw(
        frame.x.into(),
        frame.y.into(),
        frame.z.into(),
        frame.w.into(),
    )
    .normalize();
    let omega_principal = q.conjugate() * f(rb.angvel());
    let rotational = 0.5 * (f(props.principal_inertia()) * omega_principal).dot(omega_principal);
    let v = f(rb.linvel());
    rotational + 0.5 * mass * v.length_squared() + mass * 9.81 * f(rb.center_of_mass()).y
}

/// A contact scene: the ground (a fixed box, top face at y = 0) and one
/// dynamic body made by `body`.
struct ContactScene {
    world: PhysicsWorld,
    handle: RigidBodyHandle,
    exact: Option<ExactRotation>,
}

impl ContactScene {
    fn new(engine: Engine, body: RigidBodyBuilder, colliders: Vec<ColliderBuilder>) -> Self {
        let mut world = PhysicsWorld::new();
        world.gravity = Vector::new(0.0, -9.81, 0.0);
        world.insert_collider(
            ColliderBuilder::cuboid(50.0, 0.5, 50.0).translation(Vector::new(0.0, -0.5, 0.0)),
            None,
        );
        let handle = world.insert_body(body);
        for c in colliders {
            world.insert_collider(c.density(1000.0), Some(handle));
        }
        let exact = (engine == Engine::RapierKreisel).then(|| {
            let mut exact = ExactRotation::new();
            exact
                .manage(&mut world.bodies, &world.colliders, handle)
                .unwrap();
            exact
        });
        Self {
            world,
            handle,
            exact,
        }
    }

    /// Steps for `duration` s at 1/60; returns the energies after every step.
    fn run(&mut self, duration: f64) -> Vec<f64> {
        let steps = (duration * 60.0).round() as usize;
        let mut energies = vec![total_energy(&self.world.bodies[self.handle])];
        for _ in 0..steps {
            match &mut self.exact {
                Some(exact) => exact.step_world(&mut self.world).unwrap(),
                None => self.world.step(),
            }
            energies.push(total_energy(&self.world.bodies[self.handle]));
        }
        energies
    }
}

/// The largest energy gain over the start, and over any earlier time,
/// relative to the start's energy (E measured from the ground's level).
fn gains(energies: &[f64]) -> (f64, f64) {
    let e0 = energies[0];
    let over_start = energies.iter().map(|e| e - e0).fold(f64::MIN, f64::max);
    let mut lowest = e0;
    let mut over_earlier = f64::MIN;
    for &e in energies {
        over_earlier = over_earlier.max(e - lowest);
        lowest = lowest.min(e);
    }
    (over_start / e0.abs(), over_earlier / e0.abs())
}

/// Runs a contact scene in rapier alone and with the adapter, printing
/// both; returns the adapter's own energy changes (relative to the start's
/// energy): per step, the energy after [`ExactRotation::after_step`] minus
/// the energy rapier's step had just produced, summed over the steps that
/// raised it (worst one, and all of them).
fn compare(name: &str, make: impl Fn(Engine) -> ContactScene, duration: f64) -> (f64, f64) {
    let alone = make(Engine::Rapier).run(duration);
    let mut scene = make(Engine::RapierKreisel);
    let exact = scene.exact.as_mut().unwrap();
    let world = &mut scene.world;
    let mut with = vec![total_energy(&world.bodies[scene.handle])];
    let (mut worst, mut raised, mut kreisel_steps) = (0.0f64, 0.0, 0);
    for _ in 0..(duration * 60.0).round() as usize {
        let dt = world.integration_parameters.dt;
        exact.before_step(&mut world.bodies).unwrap();
        world.step();
        let rapier_made = total_energy(&world.bodies[scene.handle]);
        let touching = kreisel_rapier::Touching {
            narrow_phase: &world.narrow_phase,
            impulse_joints: &world.impulse_joints,
            multibody_joints: &world.multibody_joints,
        };
        exact.after_step(&mut world.bodies, touching, dt).unwrap();
        let e = total_energy(&world.bodies[scene.handle]);
        worst = worst.max(e - rapier_made);
        raised += (e - rapier_made).max(0.0);
        kreisel_steps +=
            usize::from(exact.carrier(scene.handle) == Some(kreisel_rapier::Carrier::Kreisel));
        with.push(e);
    }
    let e0 = with[0];
    let (g_alone, g_with) = (gains(&alone), gains(&with));
    println!(
        "{name}: energy {e0:.4} J → rapier {:.4} J, rapier+kreisel {:.4} J (kreisel carried {kreisel_steps} of {} steps); \
         largest gain over the start / over any earlier time: rapier {:+.1e} / {:+.1e}, rapier+kreisel {:+.1e} / {:+.1e}; \
         the adapter's own change: worst step {:+.1e}, all raising steps {:+.1e}",
        alone[alone.len() - 1],
        with[with.len() - 1],
        with.len() - 1,
        g_alone.0,
        g_alone.1,
        g_with.0,
        g_with.1,
        worst / e0,
        raised / e0,
    );
    (worst / e0, raised / e0)
}

fn t_handle(engine: Engine) -> ContactScene {
    let body = RigidBodyBuilder::dynamic()
        .translation(Vector::new(0.0, 1.0, 0.0))
        .linvel(Vector::new(2.0, 3.0, 0.0))
        .angvel(Vector::new(0.2, 6.0, 0.3));
    let shaft = ColliderBuilder::cuboid(0.4, 0.04, 0.04);
    let bar = ColliderBuilder::cuboid(0.04, 0.25, 0.04).translation(Vector::new(0.4, 0.0, 0.0));
    ContactScene::new(engine, body, vec![shaft, bar])
}

fn spinning_disk(engine: Engine) -> ContactScene {
    let body = RigidBodyBuilder::dynamic()
        .translation(Vector::new(0.0, 0.01, 0.0))
        .angvel(Vector::new(0.0, 10.0, 0.0));
    ContactScene::new(engine, body, vec![ColliderBuilder::cylinder(0.01, 0.1)])
}

fn coin_on_rim(engine: Engine) -> ContactScene {
    let body = RigidBodyBuilder::dynamic()
        .translation(Vector::new(0.0, 0.1, 0.0))
        .rotation(Vector::new(0.05, 0.0, std::f32::consts::FRAC_PI_2))
        .angvel(Vector::new(0.0, 15.0, 0.0));
    ContactScene::new(engine, body, vec![ColliderBuilder::cylinder(0.01, 0.1)])
}

#[test]
fn contact_scenes_never_gain_energy() {
    for (name, make, duration) in [
        (
            "T-handle thrown onto the ground",
            t_handle as fn(Engine) -> ContactScene,
            6.0,
        ),
        ("disk spinning flat on the ground", spinning_disk, 4.0),
        ("coin spinning on its rim", coin_on_rim, 4.0),
    ] {
        let (worst, raised) = compare(name, make, duration);
        // What the adapter writes back never raises the energy rapier's
        // step produced by more than the f32 rounding of the state.
        assert!(
            worst <= 1e-6 && raised <= 1e-6,
            "{name}: {worst:e}, {raised:e}"
        );
    }
}

/// A fast spin (100 rad/s, 1.7 rad per step at 1/60): rapier caps |ω| at
/// π/4 per step unless fast rotation is allowed; the adapter lifts the cap
/// while kreisel carries the body, and |L| stays that of the start.
#[test]
fn a_fast_spin_is_not_cut() {
    for engine in [Engine::Rapier, Engine::RapierKreisel] {
        let mut world = PhysicsWorld::new();
        world.gravity = Vector::ZERO;
        let props = MassProperties::new(Vector::ZERO, 1.0, Vector::new(1.0, 2.0, 3.0));
        let body = RigidBodyBuilder::dynamic()
            .additional_mass_properties(props)
            .angvel(Vector::new(0.5, 0.0, 100.0));
        let handle = world.insert_body(body);
        let mut exact = ExactRotation::new();
        if engine == Engine::RapierKreisel {
            exact
                .manage(&mut world.bodies, &world.colliders, handle)
                .unwrap();
        }
        let l = |world: &PhysicsWorld| {
            let rb = &world.bodies[handle];
            let r = *rb.rotation();
            let q = kreisel::kinematics::glam::DQuat::from_xyzw(
                r.x.into(),
                r.y.into(),
                r.z.into(),
                r.w.into(),
            );
            let w = rb.angvel();
            let w = q.conjugate()
                * kreisel::kinematics::glam::DVec3::new(w.x.into(), w.y.into(), w.z.into());
            (kreisel::kinematics::glam::DVec3::new(1.0, 2.0, 3.0) * w).length()
        };
        let l0 = l(&world);
        for _ in 0..60 {
            match engine {
                Engine::Rapier => world.step(),
                Engine::RapierKreisel => exact.step_world(&mut world).unwrap(),
            }
        }
        let change = (l(&world) - l0) / l0;
        println!("{engine:?}: |L| after 1 s of a 100 rad/s spin: {change:+.2e} relative");
        match engine {
            // Cut to π/4 per step: 47 rad/s.
            Engine::Rapier => assert!(change < -0.5, "{change}"),
            Engine::RapierKreisel => assert!(change.abs() < 1e-6, "{change}"),
        }
        if engine == Engine::RapierKreisel {
            exact.release(&mut world.bodies, handle);
            assert!(!world.bodies[handle].is_fast_rotation_allowed());
        }
    }
}

/// The README's `cargo run --release --example rapier_tumble`: the report's
/// two lines, the exact period (60-digit reference), rapier's and
/// rapier+kreisel's as stated; bad options are one line.
#[test]
fn the_example_reports_what_the_readme_says() {
    let text = demo::report(1.0 / 60.0, 100.0).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 2, "{text}");
    let numbers: Vec<f64> = lines[0]
        .strip_prefix("period of ω: exact ")
        .unwrap()
        .split(&[',', ' '][..])
        .filter_map(|w| w.parse().ok())
        .collect();
    let [exact, rapier, both] = numbers[..] else {
        panic!("{}", lines[0])
    };
    let reference = reference_period();
    assert!((exact - reference).abs() < 1e-8 * reference, "{exact}");
    assert!((both - reference).abs() < 1e-6 * reference, "{both}");
    assert!(
        ((rapier - reference) / reference - 4.2e-2).abs() < 1e-3,
        "{rapier}"
    );
    assert!(
        lines[1].starts_with("drift of |L| and energy over 100 s"),
        "{}",
        lines[1]
    );
    for (dt, duration) in [(0.0, 100.0), (f64::NAN, 100.0), (1.0 / 60.0, 0.0)] {
        let e = demo::report(dt, duration).unwrap_err();
        assert!(e.starts_with("--") && !e.contains('\n'), "{e}");
    }
}
