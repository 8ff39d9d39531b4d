//! Leine & Glocker's tippe top (Eur. J. Mech. A/Solids 22 (2003) 193), the
//! shared test problem of `crates/dynamics/tests/contact_*.rs` and
//! `benches/tippe_top.rs`.

use glam::{DMat3, DQuat, DVec2, DVec3};
use kreisel_dynamics::{
    Body, BodyBuilder, ContactShape, Friction, GroundTop, GroundTopState, SphereContact,
};

/// Mass, kg.
pub const M: f64 = 0.006;
/// Ball radius, m.
pub const R: f64 = 0.015;
/// The ball's centre from the centre of mass towards the stem, m (the
/// centre of mass is `A` below the ball's centre with the stem up).
pub const A: f64 = 0.003;
/// Transverse and axial moments of inertia, kg m².
pub const I1: f64 = 8e-7;
/// See [`I1`].
pub const I3: f64 = 7e-7;
/// Initial tilt, rad, and spin about the axis, rad/s.
pub const THETA0: f64 = 0.1;
/// See [`THETA0`].
pub const OMEGA0: f64 = 180.0;
/// The published friction coefficient (Coulomb's μ; s/m for viscous).
pub const MU: f64 = 0.3;
/// Gravity, m/s².
pub const G: f64 = 9.81;

/// The top with `friction`, tilted by θ₀ about x, spinning at ω₀ about its
/// axis, touching the floor: centre of mass at rest, or, with
/// [`Friction::Rolling`], moving so that the contact point is at rest
/// (`v_G = −ω × ρ`).
pub fn leine_glocker(friction: Friction) -> (GroundTop, GroundTopState) {
    let sphere = SphereContact::try_new(R, DVec3::new(0.0, 0.0, A)).unwrap();
    let inertia = DMat3::from_diagonal(DVec3::new(I1, I1, I3));
    let top = GroundTop::try_new(M, inertia, sphere, friction, G).unwrap();
    let q = DQuat::from_rotation_x(THETA0);
    let omega = q * DVec3::new(0.0, 0.0, OMEGA0);
    let s = match friction {
        Friction::Rolling => top.try_rolling_state_on_ground(q, omega),
        _ => top.try_state_on_ground(q, omega, DVec2::ZERO),
    }
    .unwrap();
    (top, s)
}

/// The same top as a [`kreisel_dynamics::World`] body on the ground with
/// `friction` (still a builder: further contacts may be added).
pub fn world_builder(friction: Friction) -> BodyBuilder {
    let ball = SphereContact::try_new(R, DVec3::new(0.0, 0.0, A)).unwrap();
    Body::from_principal_moments(M, DVec3::new(I1, I1, I3))
        .world_from_body(DQuat::from_rotation_x(THETA0))
        .omega_body(DVec3::new(0.0, 0.0, OMEGA0))
        .on_ground(ContactShape::Sphere(ball), friction)
}

/// The state as one vector of comparable size: positions over R,
/// velocities over R ω₀, the attitude, L over |L₀| (`l0`).
pub fn flat(s: &GroundTopState, l0: f64) -> Vec<f64> {
    let q = s.world_from_body.normalize();
    let mut v = Vec::new();
    v.extend((s.com_world / R).to_array());
    v.extend((s.velocity_world / (R * OMEGA0)).to_array());
    v.extend(q.to_array());
    v.extend((s.l_world / l0).to_array());
    v
}

/// The Euclidean distance of two [`flat`] states.
pub fn distance(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).powi(2))
        .sum::<f64>()
        .sqrt()
}

/// The stem's ball: radius, m, and its centre's distance from the centre
/// of mass along e₃, m (the demo's geometry,
/// `examples/tippe_top/simulation.rs`, and the generator's).
pub const STEM_R: f64 = 0.005;
/// See [`STEM_R`].
pub const STEM_C: f64 = 0.016;

/// The stem's ball as a contact shape.
pub fn stem() -> ContactShape {
    ContactShape::Sphere(SphereContact::try_new(STEM_R, DVec3::new(0.0, 0.0, STEM_C)).unwrap())
}

/// The committed generator's stem touchdown for `scenario`
/// (`tests/data/gen/tippe_top.py --touchdown`).
pub struct Touchdown {
    /// Its time at rtol 1e-13, s.
    pub time: f64,
    /// The same run's time at rtol 1e-11, s.
    pub time_coarse: f64,
    /// The stem ball's approach speed, m/s.
    pub approach_speed: f64,
    /// The state there.
    pub state: GroundTopState,
}

/// The generator's touchdown row for `scenario` (`sliding`, `viscous`).
pub fn touchdown_reference(scenario: &str) -> Touchdown {
    // The workspace root, also when included by the root package.
    let manifest = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let root = manifest
        .ancestors()
        .find(|dir| dir.join("tests/data/contact").is_dir())
        .expect("tests/data/contact in an ancestor");
    let path = root
        .join("tests/data/contact/tippe_top_touchdown.csv")
        .display()
        .to_string();
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let line = text
        .lines()
        .skip(1)
        .find(|l| l.starts_with(&format!("{scenario},")))
        .unwrap_or_else(|| panic!("no {scenario} row in {path}"));
    let x: Vec<f64> = line
        .split(',')
        .skip(1)
        .map(|v| v.parse().unwrap())
        .collect();
    Touchdown {
        time: x[0],
        time_coarse: x[1],
        approach_speed: x[2],
        state: GroundTopState {
            com_world: DVec3::new(x[3], x[4], x[5]),
            velocity_world: DVec3::new(x[6], x[7], x[8]),
            world_from_body: DQuat::from_xyzw(x[10], x[11], x[12], x[9]),
            l_world: DVec3::new(x[13], x[14], x[15]),
        },
    }
}

/// Leine & Glocker's contact law with Contensou's drilling friction:
/// μ = 0.3, Contensou radius 0.5 mm, plastic impacts.
pub fn contensou_law() -> kreisel_dynamics::ContactLaw {
    kreisel_dynamics::ContactLaw::new(MU)
        .try_with_contensou_radius(5e-4)
        .unwrap()
}

/// The top with its ball and its stem on the table, each contact with
/// `law`, in Leine & Glocker's start (tilted θ₀, spinning ω₀, at rest),
/// run by the nonsmooth engine at `rtol` (= atol).
pub fn table_motion(law: kreisel_dynamics::ContactLaw, rtol: f64) -> kreisel_dynamics::TableMotion {
    use kreisel_dynamics::{AdaptiveTolerance, TableBody, TableContact, TableMotion};
    let ball = ContactShape::Sphere(SphereContact::try_new(R, DVec3::new(0.0, 0.0, A)).unwrap());
    let body = TableBody::try_new(
        M,
        DMat3::from_diagonal(DVec3::new(I1, I1, I3)),
        vec![
            TableContact { shape: ball, law },
            TableContact { shape: stem(), law },
        ],
        G,
    )
    .unwrap();
    let (_, start) = leine_glocker(Friction::None);
    TableMotion::try_new(body, start, AdaptiveTolerance::new(rtol, rtol)).unwrap()
}
