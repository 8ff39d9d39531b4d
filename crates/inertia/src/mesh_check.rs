//! Topology checks and repairs of triangle meshes before integration:
//! degenerate triangles, open boundaries, non-manifold edges, inconsistent
//! winding, inside-out surfaces.
//!
//! What makes a solid: the oriented triangles form a closed 2-cycle, i.e.
//! along every edge as many triangles run one way as the other. Then the
//! winding number of every point off the surface is defined and the signed
//! tetrahedra sum to its integral, the enclosed volume. A manifold closed
//! surface is the usual case; an edge shared by four triangles (two cubes
//! touching along an edge) is accepted with a warning when their windings
//! cancel.
//!
//! Zero-area triangles (a collinear sliver closing a T-junction) are part of
//! the topology: they are kept for the closure check and left out of the
//! integrals only, where they contribute nothing. A sliver that only dangles
//! off the surface is tolerated too: when the check with slivers fails, it is
//! retried without them. Triangles with a repeated vertex index (collapsed by
//! welding) have no edges to share and are dropped first.

use core::fmt;
use std::sync::atomic::Ordering::Relaxed;
use std::sync::atomic::{AtomicBool, AtomicU32};

use glam::DVec3;

use crate::edge_uses::{EdgeUses, use_triangle};
use crate::mesh_unit::MeshUnit;
use crate::parallel::{any, map_ranges, threads_for};
use crate::{InertiaError, TriMesh};

/// Something found in a mesh and repaired; the result is still exact.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum MeshWarning {
    /// Triangles with a repeated vertex or zero area were left out of the
    /// integrals (zero-area ones still count for the closure check).
    DegenerateTriangles {
        /// How many.
        count: usize,
    },
    /// Edges shared by more than two triangles whose windings cancel: a
    /// closed surface touching itself, whose enclosed volume is well defined.
    NonManifoldEdges {
        /// How many such edges.
        edges: usize,
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
                    "left {count} degenerate triangles (repeated vertex or zero area) out of the integrals, where they contribute nothing"
                )
            }
            MeshWarning::NonManifoldEdges { edges } => write!(
                f,
                "{edges} edges are shared by more than two triangles (the surface touches itself); their windings cancel, so the enclosed volume is well defined"
            ),
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

/// Which edge slot `k` (from `tri[k]` to `tri[k + 1]`) of `tri` joins the
/// ends of `key`, and whether it runs from low to high.
fn edge_slot(tri: [u32; 3], key: u64) -> (usize, bool) {
    let (low, high) = ((key >> 32) as u32, (key & 0xFFFF_FFFF) as u32);
    for k in 0..3 {
        let (a, b) = (tri[k], tri[(k + 1) % 3]);
        if a == low && b == high {
            return (k, true);
        }
        if a == high && b == low {
            return (k, false);
        }
    }
    // Unreachable: every edge use is made from one of its triangle's three
    // edges, and orienting a triangle in place reverses it, which keeps its
    // edge set; so one of the slots above always matches.
    unreachable!("an edge use names a triangle with that edge")
}

/// Whether a triangle has an exactly zero cross product (zero area).
fn zero_area(vertices: &[DVec3], [a, b, c]: [u32; 3]) -> bool {
    let (pa, pb, pc) = (
        vertices[a as usize],
        vertices[b as usize],
        vertices[c as usize],
    );
    (pb - pa).cross(pc - pa) == DVec3::ZERO
}

/// Whether a triangle repeats a vertex index.
fn collapsed([a, b, c]: [u32; 3]) -> bool {
    a == b || b == c || a == c
}

/// Drops triangles with a repeated index or zero area.
fn drop_degenerate(mesh: TriMesh) -> (TriMesh, usize) {
    let (vertices, mut triangles) = mesh.into_parts();
    let before = triangles.len();
    triangles.retain(|&t| !collapsed(t) && !zero_area(&vertices, t));
    let dropped = before - triangles.len();
    // The vertex list is unchanged, so every index stays in range.
    (TriMesh::from_checked_parts(vertices, triangles), dropped)
}

/// The midpoint of the edge of an [`EdgeUses`] key.
fn edge_midpoint(vertices: &[DVec3], key: u64) -> DVec3 {
    let (low, high) = ((key >> 32) as usize, (key & 0xFFFF_FFFF) as usize);
    0.5 * (vertices[low] + vertices[high])
}

/// Boundary vertices considered for the weld gap (quadratic search).
const MAX_GAP_VERTICES: usize = 4096;

/// When the boundary looks like cracks: the largest distance from a
/// boundary vertex to the nearest boundary vertex it shares no boundary
/// edge with, if at most `0.001 ×` the mesh size.
fn weld_gap(vertices: &[DVec3], boundary: &[u64]) -> Option<f64> {
    let ends = |k: u64| ((k >> 32) as u32, (k & 0xFFFF_FFFF) as u32);
    let mut ids: Vec<u32> = boundary
        .iter()
        .flat_map(|&k| <[u32; 2]>::from(ends(k)))
        .collect();
    ids.sort_unstable();
    ids.dedup();
    if ids.len() > MAX_GAP_VERTICES {
        return None;
    }
    let adjacent = |a: u32, b: u32| {
        let k = (u64::from(a.min(b)) << 32) | u64::from(a.max(b));
        boundary.binary_search(&k).is_ok()
    };
    let mut gap: f64 = 0.0;
    for &a in &ids {
        let nearest = ids
            .iter()
            .filter(|&&b| b != a && !adjacent(a, b))
            .map(|&b| vertices[a as usize].distance(vertices[b as usize]))
            .fold(f64::INFINITY, f64::min);
        gap = gap.max(nearest);
    }
    let size = crate::mesh_unit::bounding_diagonal(vertices);
    (gap.is_finite() && gap <= 1e-3 * size).then_some(gap)
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
/// along every edge, as many triangles run one way as the other (a closed 2-cycle);
/// flip triangles to agree with their neighbours across edges of two triangles;
/// turn inside-out surfaces outwards (negative volume, enclosed by no other surface);
/// leave degenerate triangles out of the result (zero-area ones count for the check)
/// ```
///
/// # Errors
/// [`InertiaError::OpenMesh`] (how many boundary edges, where, and whether
/// welding would close them), [`InertiaError::NonManifold`] (edges of more
/// than two triangles whose windings do not cancel),
/// [`InertiaError::NonOrientable`], [`InertiaError::EmptyMesh`] when no
/// triangle is left.
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
    in_own_unit(mesh, prepare_solid_as_is)
}

/// `check` run on the mesh in its power-of-two unit ([`crate::mesh_unit`]),
/// so that zero-area tests and orientation volumes neither underflow nor
/// overflow; the result keeps the original vertices (checks only drop and
/// flip triangles), and the places an error names are scaled back.
fn in_own_unit(
    mesh: TriMesh,
    check: fn(TriMesh) -> Result<CheckedMesh, InertiaError>,
) -> Result<CheckedMesh, InertiaError> {
    let unit = MeshUnit::of(mesh.vertices());
    if unit.is_identity() {
        return check(mesh);
    }
    let original = mesh.vertices().to_vec();
    let checked = check(mesh.in_unit(&unit)).map_err(|e| unit.error_back(e))?;
    let (_, triangles) = checked.mesh.into_parts();
    Ok(CheckedMesh {
        mesh: TriMesh::from_checked_parts(original, triangles),
        warnings: checked.warnings,
    })
}

/// [`prepare_solid`] in the mesh's units as they are.
fn prepare_solid_as_is(mesh: TriMesh) -> Result<CheckedMesh, InertiaError> {
    let (vertices, mut triangles, known) = mesh.into_parts_and_topology();
    let before = triangles.len();
    // Found on the machine's cores; removed (rarely) on this thread.
    if any(&triangles, |&t| collapsed(t)) {
        triangles.retain(|&t| !collapsed(t));
    }
    let collapsed_count = before - triangles.len();
    if triangles.is_empty() {
        return Err(InertiaError::EmptyMesh {
            vertices: vertices.len(),
            triangles: 0,
        });
    }
    // A topology found while the mesh was welded is that of these very
    // triangles (it is only kept when none repeats an index).
    let first = match known {
        Some(topology) if collapsed_count == 0 => orient_as(&vertices, &mut triangles, &topology),
        _ => orient(&vertices, &mut triangles),
    };
    let mut warnings = match first {
        Ok(warnings) => warnings,
        Err(error) => {
            // A zero-area sliver dangling off the surface: retry without them.
            let before_retry = triangles.len();
            triangles.retain(|&t| !zero_area(&vertices, t));
            if triangles.len() == before_retry || triangles.is_empty() {
                return Err(error);
            }
            orient(&vertices, &mut triangles).map_err(|_| error)?
        }
    };
    let kept = triangles.len();
    if any(&triangles, |&t| zero_area(&vertices, t)) {
        triangles.retain(|&t| !zero_area(&vertices, t));
    }
    let degenerate = collapsed_count + (before - collapsed_count - kept) + (kept - triangles.len());
    if degenerate > 0 {
        warnings.insert(0, MeshWarning::DegenerateTriangles { count: degenerate });
    }
    if triangles.is_empty() {
        return Err(InertiaError::EmptyMesh {
            vertices: vertices.len(),
            triangles: 0,
        });
    }
    Ok(CheckedMesh {
        mesh: TriMesh::from_checked_parts(vertices, triangles),
        warnings,
    })
}

/// Turns triangle `tri` over (swaps its last two vertices).
fn flipped([a, b, c]: [u32; 3]) -> [u32; 3] {
    [a, c, b]
}

/// How the triangles hang together, found from their indices alone (so it
/// holds for the mesh however its vertices are scaled or moved): the
/// connected surfaces across edges of two triangles, and which triangles
/// to flip so that each surface is consistently wound.
#[derive(Debug)]
pub(crate) struct Topology {
    /// The triangles of each connected surface, seed first.
    components: Vec<Vec<u32>>,
    /// Whether each triangle is flipped to agree with its surface's seed.
    flip: Vec<bool>,
    /// Edges of more than two triangles (checked once oriented).
    shared_edges: usize,
}

/// Why triangles cannot be oriented, found from their indices alone.
enum TopologyError {
    /// These edges (`low << 32 | high`, sorted) have one triangle.
    Open(Vec<u64>),
    /// A surface of this many triangles is not orientable.
    NonOrientable(usize),
}

impl TopologyError {
    /// The mesh error, with the places named from the vertices.
    fn into_error(self, vertices: &[DVec3]) -> InertiaError {
        match self {
            TopologyError::Open(boundary) => InertiaError::OpenMesh {
                boundary_edges: boundary.len(),
                at: edge_midpoint(vertices, boundary[0]),
                weld_gap: weld_gap(vertices, &boundary),
            },
            TopologyError::NonOrientable(triangles) => InertiaError::NonOrientable { triangles },
        }
    }
}

/// The neighbours of one triangle across its edges `k` (from `tri[k]` to
/// `tri[k + 1]`), where exactly two triangles share the edge, and whether
/// the neighbour runs along it in the same direction (then exactly one of
/// the two is to be flipped). Atomic so that the threads of the edge pass
/// can fill it; each slot is written once.
struct Across {
    /// The neighbour, `u32::MAX` for none.
    triangle: [AtomicU32; 3],
    same: [AtomicBool; 3],
}

impl Across {
    fn none() -> Self {
        Self {
            triangle: [const { AtomicU32::new(u32::MAX) }; 3],
            same: [const { AtomicBool::new(false) }; 3],
        }
    }

    fn set(&self, k: usize, neighbour: u32, same: bool) {
        self.triangle[k].store(neighbour, Relaxed);
        self.same[k].store(same, Relaxed);
    }

    fn get(&self, k: usize) -> Option<(u32, bool)> {
        let t = self.triangle[k].load(Relaxed);
        (t != u32::MAX).then(|| (t, self.same[k].load(Relaxed)))
    }
}

impl Topology {
    /// The topology of triangles that [`prepare_solid`] would check as they
    /// are (none repeats a vertex index), if they are closed and orientable;
    /// `None` otherwise (then the check finds out again, and says why).
    pub(crate) fn of_solid(triangles: &[[u32; 3]], vertices: usize) -> Option<Self> {
        if triangles.iter().any(|&t| collapsed(t)) {
            return None;
        }
        Self::of(triangles, vertices).ok()
    }

    /// Closure and a consistent winding of triangles without a repeated index.
    fn of(triangles: &[[u32; 3]], vertices: usize) -> Result<Self, TopologyError> {
        let n = triangles.len();
        // The neighbour across each edge of each triangle, found on the
        // machine's cores, each thread the edges of its low vertices (every
        // edge once, so no two threads write the same place; relaxed atomic
        // stores and loads are plain ones on x86).
        let across: Vec<Across> = (0..n).map(|_| Across::none()).collect();
        let uses = EdgeUses::new(triangles, vertices);
        let lows = uses.vertex_ranges(threads_for(n));
        let parts = map_ranges(lows.len(), lows.len(), 1, |r| {
            let (mut boundary, mut shared_edges) = (Vec::new(), 0);
            for lows in &lows[r] {
                uses.for_each_edge_in(lows.clone(), |key, group| match *group {
                    [_] => boundary.push(key),
                    [u, w] => {
                        let (tu, tw) = (use_triangle(u), use_triangle(w));
                        let (ku, forward_u) = edge_slot(triangles[tu], key);
                        let (kw, forward_w) = edge_slot(triangles[tw], key);
                        // Triangle counts fit in u32: indices are u32.
                        across[tu].set(ku, tw as u32, forward_u == forward_w);
                        across[tw].set(kw, tu as u32, forward_u == forward_w);
                    }
                    // Orientation does not propagate across these (which pairs?);
                    // they are checked once every surface is oriented.
                    _ => shared_edges += 1,
                });
            }
            (boundary, shared_edges)
        });
        drop(uses);
        // In edge order, as one thread finds them.
        let boundary: Vec<u64> = parts.iter().flat_map(|p| p.0.iter().copied()).collect();
        let shared_edges: usize = parts.iter().map(|p| p.1).sum();
        if !boundary.is_empty() {
            return Err(TopologyError::Open(boundary));
        }

        // Orient each connected surface consistently, flipping the minority.
        // Per triangle: not reached yet (0), reached as it is (1) or to be
        // flipped (2).
        let mut state = vec![0u8; n];
        let mut components: Vec<Vec<u32>> = Vec::new();
        for seed in 0..n {
            if state[seed] != 0 {
                continue;
            }
            // The first surface is usually the whole mesh: room for all of
            // it at once rather than growing by copies (given back below).
            let mut members = Vec::with_capacity(if seed == 0 { n } else { 1 });
            members.push(seed as u32);
            state[seed] = 1;
            let mut next = 0;
            while next < members.len() {
                let t = members[next] as usize;
                next += 1;
                let flip_t = state[t] == 2;
                for k in 0..3 {
                    let Some((u, same)) = across[t].get(k) else {
                        continue;
                    };
                    let u = u as usize;
                    // Neighbours must traverse the shared edge in opposite directions.
                    let want = flip_t ^ same;
                    match state[u] {
                        0 => {
                            state[u] = 1 + u8::from(want);
                            members.push(u as u32);
                        }
                        s if (s == 2) != want => {
                            return Err(TopologyError::NonOrientable(members.len()));
                        }
                        _ => {}
                    }
                }
            }
            if seed == 0 {
                members.shrink_to_fit();
            }
            components.push(members);
        }
        let flip = state.iter().map(|&s| s == 2).collect();
        Ok(Self {
            components,
            flip,
            shared_edges,
        })
    }
}

/// Triangles per partial sum of a surface's signed volume.
const VOLUME_BLOCK: usize = 4096;

/// Checks closure and orients the triangles in place (none has a repeated
/// index); on an error they are left as they were.
fn orient(
    vertices: &[DVec3],
    triangles: &mut [[u32; 3]],
) -> Result<Vec<MeshWarning>, InertiaError> {
    let topology = Topology::of(triangles, vertices.len()).map_err(|e| e.into_error(vertices))?;
    orient_as(vertices, triangles, &topology)
}

/// Orients the triangles in place as their [`Topology`] says, turns
/// inside-out surfaces outwards and checks the edges of more than two
/// triangles; on an error the triangles are left as they were.
fn orient_as(
    vertices: &[DVec3],
    triangles: &mut [[u32; 3]],
    topology: &Topology,
) -> Result<Vec<MeshWarning>, InertiaError> {
    let mut warnings = Vec::new();
    let components = &topology.components;
    let shared_edges = topology.shared_edges;
    let mut flip = topology.flip.clone();
    // Apply the consistent winding; the sign of each surface's volume then
    // says whether it points outwards.
    for (tri, &f) in triangles.iter_mut().zip(&flip) {
        if f {
            *tri = flipped(*tri);
        }
    }
    let origin = vertices[0];
    let consistent: &[[u32; 3]] = triangles;
    // Only its sign is used. Summed in blocks of members on the machine's
    // cores, the blocks' sums added in order: the same on any thread count.
    let signed_volume = |members: &[u32]| -> f64 {
        let tet = |&t: &u32| {
            let [a, b, c] = consistent[t as usize].map(|i| vertices[i as usize] - origin);
            a.dot(b.cross(c))
        };
        let threads = threads_for(members.len());
        let blocks = map_ranges(members.len(), threads, VOLUME_BLOCK, |r| {
            members[r]
                .chunks(VOLUME_BLOCK)
                .map(|block| block.iter().map(tet).sum::<f64>())
                .collect::<Vec<f64>>()
        });
        blocks.iter().flatten().sum()
    };
    // Turn a surface with negative volume outwards, unless another surface
    // encloses it (then it bounds a cavity and points inwards on purpose).
    let turn: Vec<bool> = components
        .iter()
        .enumerate()
        .map(|(id, members)| {
            signed_volume(members) < 0.0 && !enclosed(id, components, consistent, vertices)
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
        if turn[id] {
            for &t in members {
                let t = t as usize;
                triangles[t] = flipped(triangles[t]);
                flip[t] = !flip[t];
            }
        }
    }
    if shared_edges > 0 {
        // Oriented, every edge of more than two triangles must cancel.
        let mut unbalanced: Vec<u64> = Vec::new();
        EdgeUses::new(triangles, vertices.len()).for_each_edge(|key, group| {
            let forward = group
                .iter()
                .filter(|&&u| edge_slot(triangles[use_triangle(u)], key).1)
                .count();
            if group.len() > 2 && 2 * forward != group.len() {
                unbalanced.push(key);
            }
        });
        if let Some(&first) = unbalanced.first() {
            // Leave the triangles as they came.
            for (tri, &f) in triangles.iter_mut().zip(&flip) {
                if f {
                    *tri = flipped(*tri);
                }
            }
            return Err(InertiaError::NonManifold {
                edges: unbalanced.len(),
                at: edge_midpoint(vertices, first),
            });
        }
        warnings.push(MeshWarning::NonManifoldEdges {
            edges: shared_edges,
        });
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
    Ok(warnings)
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
    in_own_unit(mesh, prepare_shell_as_is)
}

/// [`prepare_shell`] in the mesh's units as they are.
fn prepare_shell_as_is(mesh: TriMesh) -> Result<CheckedMesh, InertiaError> {
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

    /// A closed torus of `2 n²` triangles (R = 1, r = 0.35).
    fn torus(n: u32) -> TriMesh {
        let angle = |i: u32| f64::from(i % n) * core::f64::consts::TAU / f64::from(n);
        let mut v = Vec::new();
        for i in 0..n {
            for j in 0..n {
                let (u, w) = (angle(i), angle(j));
                let ring = 1.0 + 0.35 * w.cos();
                v.push(DVec3::new(ring * u.cos(), ring * u.sin(), 0.35 * w.sin()));
            }
        }
        let at = |i: u32, j: u32| (i % n) * n + j % n;
        let mut t = Vec::new();
        for i in 0..n {
            for j in 0..n {
                let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
                t.push([a, b, c]);
                t.push([a, c, d]);
            }
        }
        TriMesh::new(v, t)
    }

    #[test]
    fn topology_found_while_welding_checks_as_the_check_finds_it() {
        // Big enough for the weld to find the topology on a second thread.
        let (v, t) = torus(130).into_parts();
        assert!(t.len() >= 1 << 15);
        let inside_out: Vec<[u32; 3]> = t.iter().map(|&tri| flipped(tri)).collect();
        let mut mixed = t.clone();
        for tri in mixed.iter_mut().step_by(7) {
            *tri = flipped(*tri);
        }
        for (triangles, warning) in [
            (t, None),
            (inside_out, Some(MeshWarning::InsideOut { surfaces: 1 })),
            (mixed, Some(MeshWarning::Reoriented { triangles: 4829 })),
        ] {
            let (welded, report) = TriMesh::new(v.clone(), triangles)
                .welded(crate::Weld::default())
                .unwrap();
            assert_eq!(report.merged, 0);
            let scaled = welded.try_scaled(1e-3).unwrap();
            let (vertices, triangles, known) = scaled.clone().into_parts_and_topology();
            assert!(known.is_some());
            let with = prepare_solid(scaled).unwrap();
            let without = prepare_solid(TriMesh::new(vertices, triangles)).unwrap();
            assert_eq!(with, without);
            assert_eq!(with.warnings, warning.into_iter().collect::<Vec<_>>());
        }
    }

    #[test]
    fn no_topology_is_kept_when_the_weld_changes_the_triangles() {
        // A vertex copy 1e-9 away used by one triangle: the weld merges it.
        let (mut v, mut t) = torus(130).into_parts();
        v.push(v[0] + DVec3::splat(1e-9));
        t[0][0] = v.len() as u32 - 1;
        let (welded, report) = TriMesh::new(v, t).welded(crate::Weld::default()).unwrap();
        assert_eq!(report.merged, 1);
        assert!(welded.clone().into_parts_and_topology().2.is_none());
        assert!(prepare_solid(welded).unwrap().warnings.is_empty());
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
    fn open_and_unbalanced_non_manifold_are_errors() {
        let (v, mut t) = cube(DVec3::ZERO, 1.0);
        t.pop();
        match prepare_solid(TriMesh::new(v.clone(), t.clone())) {
            Err(InertiaError::OpenMesh {
                boundary_edges,
                weld_gap,
                ..
            }) => {
                assert_eq!(boundary_edges, 3);
                // A hole, not a crack: no weld closes it.
                assert_eq!(weld_gap, None);
            }
            other => panic!("{other:?}"),
        }
        // A one-sided fin on an existing edge: two boundary edges.
        let (mut v2, mut t2) = cube(DVec3::ZERO, 1.0);
        v2.push(DVec3::new(0.5, -1.0, 0.0));
        t2.push([0, 1, 8]);
        assert!(matches!(
            prepare_solid(TriMesh::new(v2.clone(), t2.clone())),
            Err(InertiaError::OpenMesh {
                boundary_edges: 2,
                ..
            })
        ));
        // A tetrahedron with one face repeated: three triangles on each of
        // its edges, which cannot cancel.
        let v3 = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
        let t3 = vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3], [0, 2, 1]];
        match prepare_solid(TriMesh::new(v3, t3)) {
            Err(InertiaError::NonManifold { edges, at }) => {
                assert_eq!(edges, 3);
                assert!(at.z == 0.0, "{at}");
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn cracks_report_the_weld_gap_that_closes_them() {
        // The top four triangles on their own copies of the top vertices, 1e-7 up.
        let (mut v, mut t) = cube(DVec3::ZERO, 1.0);
        let top: Vec<u32> = (4..8).collect();
        for &i in &top {
            v.push(v[i as usize] + DVec3::new(0.0, 0.0, 1e-7));
        }
        for tri in &mut t[2..4] {
            *tri = tri.map(|i| if i >= 4 { i + 4 } else { i });
        }
        match prepare_solid(TriMesh::new(v, t)) {
            Err(InertiaError::OpenMesh {
                boundary_edges: 8,
                weld_gap: Some(gap),
                ..
            }) => assert!((gap - 1e-7).abs() < 1e-15, "{gap}"),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn closed_non_manifold_surfaces_are_solids() {
        // Two unit cubes touching along the edge x = 1, y = 1: four triangles
        // on each of its two mesh edges, two each way.
        let (mut v, mut t) = cube(DVec3::ZERO, 1.0);
        let (v2, t2) = cube(DVec3::new(1.0, 1.0, 0.0), 1.0);
        let base = v.len() as u32;
        v.extend(v2);
        t.extend(t2.iter().map(|tri| tri.map(|i| i + base)));
        let mesh = TriMesh::new(v, t).merge_duplicate_vertices();
        let checked = prepare_solid(mesh).unwrap();
        assert_eq!(
            checked.warnings,
            vec![MeshWarning::NonManifoldEdges { edges: 1 }]
        );
        let volume = crate::MeshMoments::solid(&checked.mesh).zeroth;
        assert!((volume - 2.0).abs() < 1e-14, "{volume}");
    }

    #[test]
    fn a_sliver_closing_a_t_junction_keeps_the_surface_closed() {
        // Cube whose bottom face (z = 0) has a vertex m at the middle of
        // edge 0–1, used by the two bottom triangles and a zero-area sliver
        // (0, m, 1) that closes the side face's edge 0–1.
        let (mut v, mut t) = cube(DVec3::ZERO, 1.0);
        v.push(DVec3::new(0.5, 0.0, 0.0));
        let m = 8;
        // Bottom: [0, 2, 1], [1, 2, 3] become [0, 2, m], [m, 2, 1], [1, 2, 3].
        t[0] = [0, 2, m];
        t.push([m, 2, 1]);
        // The bottom runs m→0 and 1→m and the side y = 0 runs 0→1, so the
        // sliver 0→m→1→0 pairs with all three.
        t.push([0, m, 1]);
        let checked = prepare_solid(TriMesh::new(v, t)).unwrap();
        assert_eq!(
            checked.warnings,
            vec![MeshWarning::DegenerateTriangles { count: 1 }]
        );
        assert_eq!(checked.mesh.triangles().len(), 13);
        let volume = crate::MeshMoments::solid(&checked.mesh).zeroth;
        assert!((volume - 1.0).abs() < 1e-15, "{volume}");
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
