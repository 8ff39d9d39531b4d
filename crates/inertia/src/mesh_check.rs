//! Topology checks and repairs of triangle meshes before integration:
//! degenerate triangles, open boundaries, non-manifold edges, inconsistent
//! winding, inside-out surfaces.

use core::fmt;

use glam::DVec3;

use crate::{InertiaError, TriMesh};

/// Something found in a mesh and repaired; the result is still exact.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MeshWarning {
    /// Triangles with a repeated vertex or zero area were skipped.
    DegenerateTriangles {
        /// How many.
        count: usize,
    },
    /// Some triangles were wound against their neighbours and were flipped.
    Reoriented {
        /// How many were flipped.
        triangles: usize,
    },
    /// Closed surfaces whose normals all pointed inwards were turned outwards.
    InsideOut {
        /// How many connected surfaces were turned.
        surfaces: usize,
    },
}

impl fmt::Display for MeshWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MeshWarning::DegenerateTriangles { count } => {
                write!(
                    f,
                    "skipped {count} degenerate triangles (repeated vertex or zero area)"
                )
            }
            MeshWarning::Reoriented { triangles } => write!(
                f,
                "winding was inconsistent: flipped {triangles} triangles to match their neighbours"
            ),
            MeshWarning::InsideOut { surfaces } => write!(
                f,
                "mesh was inside-out (normals pointing inwards): turned {surfaces} closed surface(s) outwards"
            ),
        }
    }
}

/// A mesh ready for integration, with what was repaired on the way.
#[derive(Debug, Clone, PartialEq)]
pub struct CheckedMesh {
    /// The repaired mesh.
    pub mesh: TriMesh,
    /// What was repaired.
    pub warnings: Vec<MeshWarning>,
}

/// An undirected edge `(low, high)` used by triangle `triangle`, `forward`
/// when the triangle runs from `low` to `high`.
#[derive(Clone, Copy)]
struct EdgeUse {
    key: u64,
    triangle: u32,
    forward: bool,
}

/// Drops triangles with a repeated index or an exactly zero cross product.
fn drop_degenerate(mesh: TriMesh) -> (TriMesh, usize) {
    let (vertices, triangles) = mesh.into_parts();
    let before = triangles.len();
    let kept: Vec<[u32; 3]> = triangles
        .into_iter()
        .filter(|&[a, b, c]| {
            let (pa, pb, pc) = (
                vertices[a as usize],
                vertices[b as usize],
                vertices[c as usize],
            );
            a != b && b != c && a != c && (pb - pa).cross(pc - pa) != DVec3::ZERO
        })
        .collect();
    let dropped = before - kept.len();
    // The vertex list is unchanged, so every index stays in range.
    (TriMesh::from_checked_parts(vertices, kept), dropped)
}

/// Every undirected edge's uses, sorted so that uses of one edge are adjacent.
fn edge_uses(triangles: &[[u32; 3]]) -> Vec<EdgeUse> {
    let mut uses: Vec<EdgeUse> = Vec::with_capacity(3 * triangles.len());
    for (t, tri) in triangles.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (tri[k], tri[(k + 1) % 3]);
            let (low, high, forward) = if a < b { (a, b, true) } else { (b, a, false) };
            uses.push(EdgeUse {
                key: (u64::from(low) << 32) | u64::from(high),
                // Triangle counts fit in u32: indices are u32.
                triangle: t as u32,
                forward,
            });
        }
    }
    uses.sort_unstable_by_key(|u| u.key);
    uses
}

/// Whether surface `id` lies inside another surface: the generalised winding
/// number (Jacobson et al., SIGGRAPH 2013) of the other surfaces at one of
/// its vertices is about ±1 rather than 0.
fn enclosed(
    id: usize,
    components: &[Vec<u32>],
    triangles: &[[u32; 3]],
    vertices: &[DVec3],
) -> bool {
    let probe = vertices[triangles[components[id][0] as usize][0] as usize];
    let winding: f64 = components
        .iter()
        .enumerate()
        .filter(|&(other, _)| other != id)
        .flat_map(|(_, m)| m.iter())
        .map(|&t| {
            let [a, b, c] = triangles[t as usize].map(|i| vertices[i as usize] - probe);
            solid_angle(a, b, c)
        })
        .sum::<f64>()
        / (4.0 * core::f64::consts::PI);
    winding.abs() >= 0.5
}

/// Solid angle of triangle (a, b, c) seen from the origin (van Oosterom &
/// Strackee, IEEE Trans. Biomed. Eng. 30:125 (1983)).
fn solid_angle(a: DVec3, b: DVec3, c: DVec3) -> f64 {
    let (la, lb, lc) = (a.length(), b.length(), c.length());
    let numerator = a.dot(b.cross(c));
    let denominator = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    2.0 * numerator.atan2(denominator)
}

/// Checks a mesh for use as a solid and repairs what can be repaired.
///
/// ```text
/// skip degenerate triangles;  every edge used by exactly two triangles (closed, manifold);
/// flip triangles to agree with their neighbours;  turn inside-out surfaces outwards
/// (a surface with negative volume that no other surface encloses)
/// ```
///
/// # Errors
/// [`InertiaError::OpenMesh`] (with the number of boundary edges),
/// [`InertiaError::NonManifold`], [`InertiaError::NonOrientable`],
/// [`InertiaError::EmptyMesh`] when no triangle is left.
///
/// ```
/// use glam::DVec3;
/// use kreisel_inertia::{prepare_solid, MeshWarning, TriMesh};
/// let v = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
/// // Every triangle wound inwards:
/// let tet = TriMesh::new(v, vec![[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]);
/// let checked = prepare_solid(tet)?;
/// assert_eq!(checked.warnings, vec![MeshWarning::InsideOut { surfaces: 1 }]);
/// # Ok::<(), kreisel_inertia::InertiaError>(())
/// ```
pub fn prepare_solid(mesh: TriMesh) -> Result<CheckedMesh, InertiaError> {
    let mut warnings = Vec::new();
    let (mesh, dropped) = drop_degenerate(mesh);
    if dropped > 0 {
        warnings.push(MeshWarning::DegenerateTriangles { count: dropped });
    }
    let (vertices, mut triangles) = mesh.into_parts();
    if triangles.is_empty() {
        return Err(InertiaError::EmptyMesh {
            vertices: vertices.len(),
            triangles: 0,
        });
    }
    let uses = edge_uses(&triangles);
    // Neighbours across each edge: (other triangle, same direction?).
    let mut neighbours: Vec<Vec<(u32, bool)>> = vec![Vec::new(); triangles.len()];
    let (mut boundary, mut non_manifold) = (0, 0);
    for group in uses.chunk_by(|x, y| x.key == y.key) {
        match group {
            [_] => boundary += 1,
            [u, w] => {
                let same = u.forward == w.forward;
                neighbours[u.triangle as usize].push((w.triangle, same));
                neighbours[w.triangle as usize].push((u.triangle, same));
            }
            _ => non_manifold += 1,
        }
    }
    if boundary > 0 {
        return Err(InertiaError::OpenMesh {
            boundary_edges: boundary,
        });
    }
    if non_manifold > 0 {
        return Err(InertiaError::NonManifold {
            edges: non_manifold,
        });
    }

    // Orient each connected surface consistently, flipping the minority.
    let n = triangles.len();
    let mut component = vec![u32::MAX; n];
    let mut flip = vec![false; n];
    let mut components: Vec<Vec<u32>> = Vec::new();
    for seed in 0..n {
        if component[seed] != u32::MAX {
            continue;
        }
        let id = components.len() as u32;
        let mut members = vec![seed as u32];
        component[seed] = id;
        let mut next = 0;
        while next < members.len() {
            let t = members[next] as usize;
            next += 1;
            for &(u, same) in &neighbours[t] {
                let u = u as usize;
                // Neighbours must traverse the shared edge in opposite directions.
                let want = flip[t] ^ same;
                if component[u] == u32::MAX {
                    component[u] = id;
                    flip[u] = want;
                    members.push(u as u32);
                } else if flip[u] != want {
                    return Err(InertiaError::NonOrientable {
                        triangles: members.len(),
                    });
                }
            }
        }
        components.push(members);
    }
    // Apply the consistent winding; the sign of each surface's volume then
    // says whether it points outwards.
    let consistent: Vec<[u32; 3]> = triangles
        .iter()
        .zip(&flip)
        .map(|(&[a, b, c], &f)| if f { [a, c, b] } else { [a, b, c] })
        .collect();
    let origin = vertices[0];
    let signed_volume = |members: &[u32]| -> f64 {
        members
            .iter()
            .map(|&t| {
                let [a, b, c] = consistent[t as usize].map(|i| vertices[i as usize] - origin);
                a.dot(b.cross(c))
            })
            .sum()
    };
    // Turn a surface with negative volume outwards, unless another surface
    // encloses it (then it bounds a cavity and points inwards on purpose).
    let turn: Vec<bool> = components
        .iter()
        .enumerate()
        .map(|(id, members)| {
            signed_volume(members) < 0.0 && !enclosed(id, &components, &consistent, &vertices)
        })
        .collect();
    let (mut reoriented, mut inside_out) = (0, 0);
    for (id, members) in components.iter().enumerate() {
        let changed = members
            .iter()
            .filter(|&&t| flip[t as usize] != turn[id])
            .count();
        if changed == members.len() {
            inside_out += 1;
        } else {
            reoriented += changed;
        }
        for &t in members {
            let t = t as usize;
            triangles[t] = if turn[id] {
                let [a, b, c] = consistent[t];
                [a, c, b]
            } else {
                consistent[t]
            };
        }
    }
    if reoriented > 0 {
        warnings.push(MeshWarning::Reoriented {
            triangles: reoriented,
        });
    }
    if inside_out > 0 {
        warnings.push(MeshWarning::InsideOut {
            surfaces: inside_out,
        });
    }
    Ok(CheckedMesh {
        mesh: TriMesh::from_checked_parts(vertices, triangles),
        warnings,
    })
}

/// Prepares a mesh for use as a thin shell: only degenerate triangles are
/// skipped (a shell may be open and needs no orientation).
///
/// # Errors
/// [`InertiaError::EmptyMesh`] when no triangle is left.
///
/// ```
/// use glam::DVec3;
/// use kreisel_inertia::{prepare_shell, TriMesh};
/// let open = TriMesh::new(vec![DVec3::ZERO, DVec3::X, DVec3::Y], vec![[0, 1, 2], [0, 0, 1]]);
/// let checked = prepare_shell(open)?;
/// assert_eq!(checked.mesh.triangles().len(), 1);
/// # Ok::<(), kreisel_inertia::InertiaError>(())
/// ```
pub fn prepare_shell(mesh: TriMesh) -> Result<CheckedMesh, InertiaError> {
    let (mesh, dropped) = drop_degenerate(mesh);
    if mesh.triangles().is_empty() {
        return Err(InertiaError::EmptyMesh {
            vertices: mesh.vertices().len(),
            triangles: 0,
        });
    }
    let warnings = if dropped > 0 {
        vec![MeshWarning::DegenerateTriangles { count: dropped }]
    } else {
        Vec::new()
    };
    Ok(CheckedMesh { mesh, warnings })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cube(offset: DVec3, scale: f64) -> (Vec<DVec3>, Vec<[u32; 3]>) {
        crate::tri_mesh::box_mesh(offset, offset + DVec3::splat(scale)).into_parts()
    }

    #[test]
    fn every_second_triangle_flipped_is_repaired() {
        let (v, mut t) = cube(DVec3::ZERO, 1.0);
        for tri in t.iter_mut().step_by(2) {
            tri.swap(1, 2);
        }
        let checked = prepare_solid(TriMesh::new(v.clone(), t)).unwrap();
        assert_eq!(
            checked.warnings,
            vec![MeshWarning::Reoriented { triangles: 6 }]
        );
        let (_, good) = cube(DVec3::ZERO, 1.0);
        assert_eq!(checked.mesh.triangles(), &good[..]);
    }

    #[test]
    fn open_and_non_manifold_are_errors() {
        let (v, mut t) = cube(DVec3::ZERO, 1.0);
        t.pop();
        match prepare_solid(TriMesh::new(v.clone(), t.clone())) {
            Err(InertiaError::OpenMesh { boundary_edges }) => assert_eq!(boundary_edges, 3),
            other => panic!("{other:?}"),
        }
        // A fin: one extra triangle on an existing edge.
        let (v2, mut t2) = cube(DVec3::ZERO, 1.0);
        let mut v2 = v2;
        v2.push(DVec3::new(0.5, -1.0, 0.0));
        t2.push([0, 1, 8]);
        t2.push([1, 0, 8]);
        assert!(matches!(
            prepare_solid(TriMesh::new(v2, t2)),
            Err(InertiaError::NonManifold { .. })
        ));
    }

    #[test]
    fn cavity_keeps_its_inward_normals_but_lone_inverted_part_is_turned() {
        // Outer cube 0..3 and an inverted inner cube 1..2: a hollow box.
        let (mut v, mut t) = cube(DVec3::ZERO, 3.0);
        let (vi, ti) = cube(DVec3::ONE, 1.0);
        let base = v.len() as u32;
        v.extend(vi);
        t.extend(ti.iter().map(|&[a, b, c]| [a + base, c + base, b + base]));
        let checked = prepare_solid(TriMesh::new(v.clone(), t.clone())).unwrap();
        assert!(checked.warnings.is_empty(), "{:?}", checked.warnings);
        // The same inner cube beside the outer one is a separate inverted part.
        let (mut v2, mut t2) = cube(DVec3::ZERO, 3.0);
        let (vi, ti) = cube(DVec3::new(5.0, 0.0, 0.0), 1.0);
        v2.extend(vi);
        t2.extend(ti.iter().map(|&[a, b, c]| [a + base, c + base, b + base]));
        let checked = prepare_solid(TriMesh::new(v2, t2)).unwrap();
        assert_eq!(
            checked.warnings,
            vec![MeshWarning::InsideOut { surfaces: 1 }]
        );
    }

    #[test]
    fn degenerate_triangles_are_counted() {
        let (mut v, mut t) = cube(DVec3::ZERO, 1.0);
        v.push(DVec3::new(0.5, 0.0, 0.0)); // on an edge: zero-area sliver with 0 and 1
        t.push([0, 1, 8]);
        t.push([2, 2, 3]);
        // The sliver makes edge (0,1) used thrice unless it is dropped first.
        let checked = prepare_solid(TriMesh::new(v, t)).unwrap();
        assert_eq!(
            checked.warnings,
            vec![MeshWarning::DegenerateTriangles { count: 2 }]
        );
    }
}
