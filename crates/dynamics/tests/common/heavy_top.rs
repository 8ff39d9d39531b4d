//! Shared test problems: the heavy-top reference trajectories under
//! `tests/data/heavy_top/` (made by `python3 tests/data/gen/heavy_top.py`),
//! used by the heavy-top tests, the bench and the work-precision example.
#![allow(dead_code)]

use std::path::PathBuf;

use glam::{DMat3, DQuat, DVec3};
use kreisel_dynamics::{HeavyTop, PrincipalState};
use kreisel_inertia::MassProperties;

/// The names of the reference scenarios.
pub const NAMES: [&str; 4] = ["bruls", "asymmetric_fast", "lagrange_slow", "tumbling"];

/// A heavy-top reference: the top, its initial state and samples
/// `(t, world_from_body, L_body about the pivot)`.
pub struct HeavyTopReference {
    /// The top (pivot at the body origin).
    pub top: HeavyTop,
    /// Mass properties about the centre of mass, body axes.
    pub mass_properties: MassProperties,
    /// Gravity, world axes.
    pub gravity: DVec3,
    /// The initial state.
    pub start: PrincipalState,
    /// Initial angular velocity, body axes.
    pub omega0: DVec3,
    /// Initial attitude, world from body.
    pub q0: DQuat,
    /// Reference samples.
    pub samples: Vec<(f64, DQuat, DVec3)>,
    /// The energy and vertical momentum of the reference (60 digits, rounded).
    pub energy: f64,
    /// `L_world · e_z`.
    pub l_world_z: f64,
}

fn numbers(rest: &str) -> Vec<f64> {
    rest.trim_start_matches('(')
        .trim_end_matches(')')
        .split(',')
        .map(|x| x.trim().parse().unwrap())
        .collect()
}

/// Loads `tests/data/heavy_top/NAME.csv`.
pub fn load(name: &str) -> HeavyTopReference {
    let manifest = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let root = manifest
        .ancestors()
        .find(|dir| dir.join("tests/data/heavy_top").is_dir())
        .unwrap_or(&manifest);
    let path = root
        .join("tests/data/heavy_top")
        .join(format!("{name}.csv"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut meta = std::collections::HashMap::new();
    let mut samples = Vec::new();
    for line in text.lines() {
        if let Some(rest) = line.strip_prefix("# ") {
            if let Some((key, value)) = rest.split_once(" = ") {
                meta.insert(key.to_owned(), value.to_owned());
            }
        } else if !line.starts_with('t') && !line.is_empty() {
            let v: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
            samples.push((
                v[0],
                DQuat::from_xyzw(v[2], v[3], v[4], v[1]),
                DVec3::new(v[5], v[6], v[7]),
            ));
        }
    }
    let get = |key: &str| {
        numbers(
            meta.get(key)
                .unwrap_or_else(|| panic!("{name}: no `{key}`")),
        )
    };
    let mass = get("mass")[0];
    let inertia = DMat3::from_cols_array(&get("inertia_cm").try_into().unwrap()).transpose();
    let com = DVec3::from_slice(&get("com"));
    let gravity = DVec3::from_slice(&get("gravity"));
    let omega0 = DVec3::from_slice(&get("omega0"));
    let q = get("q0");
    let q0 = DQuat::from_xyzw(q[1], q[2], q[3], q[0]).normalize();
    let mass_properties = MassProperties::try_new(mass, com, inertia).unwrap();
    let top = HeavyTop::try_new(&mass_properties, DVec3::ZERO, gravity).unwrap();
    let start = PrincipalState::try_from_omega_body(top.body(), q0, omega0).unwrap();
    HeavyTopReference {
        top,
        mass_properties,
        gravity,
        start,
        omega0,
        q0,
        samples,
        energy: get("energy")[0],
        l_world_z: get("l_world_z")[0],
    }
}

impl HeavyTopReference {
    /// The top as a World body: its start, on a pivot at the body origin
    /// held at the world origin.
    pub fn world_body(&self) -> kreisel_dynamics::Body {
        kreisel_dynamics::Body::from_mass_properties(self.mass_properties)
            .world_from_body(self.q0)
            .omega_body(self.omega0)
            .pivot(DVec3::ZERO, DVec3::ZERO)
            .try_build()
            .unwrap()
    }

    /// The attitude error (rad) of `state` against sample `k`.
    pub fn attitude_error(&self, state: &PrincipalState, k: usize) -> f64 {
        kreisel_kinematics::rotation_angle_between(
            state.world_from_body(self.top.body()),
            self.samples[k].1,
        )
    }
}
