//! The references of `tests/data/forced/` (`python3 tests/data/gen/forced.py`:
//! Euler's equations in body axes with the quaternion, written from the
//! physics, integrated at 32 digits by mpmath Gragg–Bulirsch–Stoer and
//! checked against scipy DOP853 at 1e-13), shared by the tests that use them.

use std::collections::HashMap;
use std::path::PathBuf;

use glam::{DMat3, DQuat, DVec3};
use kreisel_dynamics::{
    ForcedBody, ForcedPropagator, ForcedSplitting, ForcedState, Inputs, PointForce, PrincipalState,
    RigidBody,
};
use kreisel_inertia::MassProperties;
use kreisel_kinematics::{rotation_angle_between, rotation_vector_from_quat};

/// The heavy tops with inputs (a pivot held fixed).
pub const TOP_NAMES: [&str; 2] = ["top_motor", "top_pushed"];

pub const NAMES: [&str; 8] = [
    "sphere_world_torque",
    "symmetric_body_torque",
    "asymmetric_body_torque",
    "asymmetric_world_torque",
    "point_force_gravity",
    "damped_asymmetric",
    "magnet",
    "pd_controller",
];

/// One reference: the body, its start and samples `(t, q_wb, ω_b, x, v, work)`.
pub struct Reference {
    pub body: ForcedBody,
    /// The inertia tensor about the centre of mass, body axes.
    pub inertia: DMat3,
    /// On a pivot: the pivot in body coordinates from the centre of mass
    /// and where it is held (world).
    pub pivot: Option<(DVec3, DVec3)>,
    pub start: ForcedState,
    pub samples: Vec<[f64; 15]>,
}

impl Reference {
    pub fn sample_dt(&self) -> f64 {
        self.samples[1][0] - self.samples[0][0]
    }

    pub fn attitude(k: &[f64; 15]) -> DQuat {
        DQuat::from_xyzw(k[2], k[3], k[4], k[1]).normalize()
    }

    /// Runs `method` with `substeps` steps per sample interval; the largest
    /// attitude error over the samples and the final state.
    pub fn run(&self, method: ForcedSplitting, substeps: usize) -> (f64, ForcedState) {
        let h = self.sample_dt() / substeps as f64;
        let mut p = ForcedPropagator::try_new(method, &self.body, 0.0, self.start).unwrap();
        let mut worst: f64 = 0.0;
        for k in 1..self.samples.len() {
            for _ in 0..substeps {
                p.try_advance(h).unwrap();
            }
            worst = worst.max(self.attitude_error(&p.forced_state(), k));
        }
        (worst, p.forced_state())
    }

    pub fn attitude_error(&self, s: &ForcedState, k: usize) -> f64 {
        let q = s.rotation.world_from_body(self.body.body());
        rotation_angle_between(q, Self::attitude(&self.samples[k]))
    }
}

pub fn vec3(v: &[f64]) -> DVec3 {
    DVec3::new(v[0], v[1], v[2])
}

pub fn load(name: &str) -> Reference {
    let manifest = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let root = manifest
        .ancestors()
        .find(|dir| dir.join("tests/data/forced").is_dir())
        .expect("tests/data/forced in an ancestor");
    let path = root.join(format!("tests/data/forced/{name}.csv"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut meta: HashMap<&str, &str> = HashMap::new();
    let mut samples = Vec::new();
    for line in text.lines() {
        if let Some(rest) = line.strip_prefix("# ") {
            if let Some((key, value)) = rest.split_once(": ") {
                meta.insert(key, value);
            }
        } else if !line.starts_with('t') {
            let row: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
            samples.push(row.try_into().unwrap());
        }
    }
    let numbers = |key: &str| -> Vec<f64> {
        meta[key]
            .split_whitespace()
            .map(|x| x.parse().unwrap())
            .collect()
    };
    let tensor = DMat3::from_cols_array(&numbers("inertia").try_into().unwrap()).transpose();
    let body = RigidBody::try_from_inertia_tensor(tensor).unwrap();
    let mut inputs = Inputs::default()
        .with_torque_world(vec3(&numbers("torque_world")))
        .with_torque_body(vec3(&numbers("torque_body")))
        .with_force_world(vec3(&numbers("force_world")))
        .with_angular_damping(numbers("damping")[0]);
    let point_force = vec3(&numbers("point_force"));
    if point_force != DVec3::ZERO {
        inputs = inputs.with_point_force(PointForce {
            point_body: vec3(&numbers("point_body")),
            force_world: point_force,
        });
    }
    let p = numbers("law_params");
    let inputs = match meta["law"] {
        "none" => inputs,
        "magnet" => {
            let (m_body, b0, omega, bz) = (vec3(&p[0..3]), p[3], p[4], p[5]);
            inputs.with_load(move |t, s: &ForcedState| {
                let b = b0 * DVec3::new((omega * t).cos(), (omega * t).sin(), bz);
                (
                    (s.rotation.world_from_body(&body) * m_body).cross(b),
                    DVec3::ZERO,
                )
            })
        }
        "pd" => {
            let (k, c_d) = (p[0], p[1]);
            let moments = body.principal_moments();
            inputs.with_velocity_load(move |_, s: &ForcedState| {
                let rotvec = rotation_vector_from_quat(s.rotation.world_from_body(&body));
                (-k * rotvec - c_d * s.omega_world(moments), DVec3::ZERO)
            })
        }
        law => panic!("unknown law {law}"),
    };
    let (mass, gravity) = (numbers("mass")[0], vec3(&numbers("gravity")));
    let s0: &[f64; 15] = &samples[0];
    let pivot = meta
        .contains_key("pivot_body")
        .then(|| (vec3(&numbers("pivot_body")), vec3(&numbers("pivot_world"))));
    let (forced, start) = match pivot {
        None => {
            let forced = ForcedBody::try_new(body, mass, gravity, inputs).unwrap();
            let start = ForcedState::try_new(
                &body,
                Reference::attitude(s0),
                vec3(&s0[5..8]),
                vec3(&s0[8..11]),
                vec3(&s0[11..14]),
            )
            .unwrap();
            (forced, start)
        }
        Some((pivot_body, pivot_world)) => {
            let props = MassProperties::new(mass, DVec3::ZERO, tensor);
            let forced =
                ForcedBody::try_on_pivot(&props, pivot_body, pivot_world, gravity, inputs).unwrap();
            let about_pivot = *forced.body();
            let rotation = PrincipalState::try_from_omega_body(
                &about_pivot,
                Reference::attitude(s0),
                vec3(&s0[5..8]),
            )
            .unwrap();
            (forced.clone(), forced.state_on_pivot(rotation))
        }
    };
    Reference {
        body: forced,
        inertia: tensor,
        pivot,
        start,
        samples,
    }
}
