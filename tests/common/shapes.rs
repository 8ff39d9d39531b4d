//! Shared test problems: triangle meshes of primitive solids, used by the
//! tests (convergence to closed forms) and by `benches/inertia.rs`.
#![allow(dead_code)]

use std::f64::consts::{PI, TAU};

use kreisel::inertia::TriMesh;
use kreisel::kinematics::glam::DVec3;

/// A closed surface of revolution about z: the profile `(r, z)` runs from a
/// point on the axis (r = 0) at the bottom to one at the top; `segments`
/// around. Outward wound.
pub fn revolution(profile: &[(f64, f64)], segments: usize) -> TriMesh {
    let rings = &profile[1..profile.len() - 1];
    let mut v = vec![DVec3::new(0.0, 0.0, profile[0].1)];
    for &(r, z) in rings {
        for s in 0..segments {
            let phi = TAU * s as f64 / segments as f64;
            v.push(DVec3::new(r * phi.cos(), r * phi.sin(), z));
        }
    }
    let top = v.len() as u32;
    v.push(DVec3::new(0.0, 0.0, profile[profile.len() - 1].1));
    let n = segments as u32;
    let ring = |k: usize, s: u32| 1 + k as u32 * n + s % n;
    let mut t = Vec::new();
    for s in 0..n {
        t.push([0, ring(0, s + 1), ring(0, s)]);
    }
    for k in 0..rings.len() - 1 {
        for s in 0..n {
            let (a, b) = (ring(k, s), ring(k, s + 1));
            let (c, d) = (ring(k + 1, s), ring(k + 1, s + 1));
            t.push([a, b, d]);
            t.push([a, d, c]);
        }
    }
    let last = rings.len() - 1;
    for s in 0..n {
        t.push([top, ring(last, s), ring(last, s + 1)]);
    }
    TriMesh::new(v, t)
}

/// A UV sphere of `radius` with `segments` around and `segments/2` rings.
pub fn sphere(radius: f64, segments: usize) -> TriMesh {
    let stacks = (segments / 2).max(2);
    let profile: Vec<(f64, f64)> = (0..=stacks)
        .map(|k| {
            let theta = PI * (1.0 - k as f64 / stacks as f64);
            (
                radius * theta.sin().abs() * if k == 0 || k == stacks { 0.0 } else { 1.0 },
                radius * theta.cos(),
            )
        })
        .collect();
    revolution(&profile, segments)
}

/// A cylinder of `radius` and `height`, centred, axis z.
pub fn cylinder(radius: f64, height: f64, segments: usize) -> TriMesh {
    let h = height / 2.0;
    revolution(&[(0.0, -h), (radius, -h), (radius, h), (0.0, h)], segments)
}

/// A cone: base of `radius` at z = 0, apex at z = `height`.
pub fn cone(radius: f64, height: f64, segments: usize) -> TriMesh {
    revolution(&[(0.0, 0.0), (radius, 0.0), (0.0, height)], segments)
}

/// A capsule: cylinder of `length` between two hemispheres of `radius`.
pub fn capsule(radius: f64, length: f64, segments: usize) -> TriMesh {
    let quarter = (segments / 4).max(1);
    let mut profile = Vec::new();
    for k in 0..=quarter {
        let a = -PI / 2.0 + PI / 2.0 * k as f64 / quarter as f64;
        profile.push((
            if k == 0 { 0.0 } else { radius * a.cos() },
            -length / 2.0 + radius * a.sin(),
        ));
    }
    for k in 0..=quarter {
        let a = PI / 2.0 * k as f64 / quarter as f64;
        profile.push((
            if k == quarter { 0.0 } else { radius * a.cos() },
            length / 2.0 + radius * a.sin(),
        ));
    }
    revolution(&profile, segments)
}

/// A torus about z: tube `minor` around a circle of radius `major`.
pub fn torus(major: f64, minor: f64, segments: usize) -> TriMesh {
    let tube = segments / 2;
    let mut v = Vec::new();
    for i in 0..segments {
        let phi = TAU * i as f64 / segments as f64;
        for j in 0..tube {
            let theta = TAU * j as f64 / tube as f64;
            let r = major + minor * theta.cos();
            v.push(DVec3::new(
                r * phi.cos(),
                r * phi.sin(),
                minor * theta.sin(),
            ));
        }
    }
    let (n, m) = (segments as u32, tube as u32);
    let id = |i: u32, j: u32| (i % n) * m + j % m;
    let mut t = Vec::new();
    for i in 0..n {
        for j in 0..m {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i, j + 1), id(i + 1, j + 1));
            t.push([a, b, d]);
            t.push([a, d, c]);
        }
    }
    TriMesh::new(v, t)
}

/// An ellipsoid: the unit sphere scaled by the semi-axes.
pub fn ellipsoid(semi_axes: DVec3, segments: usize) -> TriMesh {
    let (v, t) = sphere(1.0, segments).into_parts();
    TriMesh::new(v.into_iter().map(|p| p * semi_axes).collect(), t)
}
