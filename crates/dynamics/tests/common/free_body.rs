//! Shared test problems: the free-body reference trajectories under
//! `tests/data/free_body/` (made by `python3 tests/data/gen/free_body.py`),
//! used by tests (the root package's and kreisel-dynamics'), the free-body
//! bench and the work-precision example.
#![allow(dead_code)]

use std::path::PathBuf;

use glam::{DQuat, DVec3};

/// A reference trajectory: principal moments and samples (t, q, L).
pub struct Reference {
    /// Principal moments (I₁, I₂, I₃).
    pub moments: DVec3,
    /// Samples (t, world_from_principal, L in principal axes).
    pub samples: Vec<(f64, DQuat, DVec3)>,
}

/// Loads `tests/data/free_body/NAME.csv`.
pub fn load(name: &str) -> Reference {
    // The workspace root, also when included by a member crate's tests.
    let manifest = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let root = manifest
        .ancestors()
        .find(|dir| dir.join("tests/data/free_body").is_dir())
        .unwrap_or(&manifest);
    let path = root
        .join("tests/data/free_body")
        .join(format!("{name}.csv"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut moments = None;
    let mut samples = Vec::new();
    for line in text.lines() {
        if let Some(rest) = line.strip_prefix("# I = (") {
            let v: Vec<f64> = rest
                .trim_end_matches(')')
                .split(',')
                .map(|x| x.trim().parse().unwrap())
                .collect();
            moments = Some(DVec3::new(v[0], v[1], v[2]));
        } else if !line.starts_with('#') && !line.starts_with('t') && !line.is_empty() {
            let v: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
            samples.push((
                v[0],
                DQuat::from_xyzw(v[2], v[3], v[4], v[1]),
                DVec3::new(v[5], v[6], v[7]),
            ));
        }
    }
    Reference {
        moments: moments.expect("an `# I = (…)` line"),
        samples,
    }
}
