//! Vertex welding: merging vertices that are the same point of the surface,
//! so that the topology checks see shared edges.
//!
//! Two passes, both linear or `n log n` in the vertex count:
//! 1. **Exact**: bit-identical coordinates (`−0.0` ≡ `+0.0`) are merged
//!    through an open-addressing hash table of `u32` vertex indices
//!    (8 bytes per distinct vertex at load ≤ ½). Hand-written rather than a
//!    `HashMap<[u64; 3], u32>` because that holds 32 bytes per entry and a
//!    10 M-triangle STL has ~5 M distinct vertices.
//! 2. **Tolerance** (`|p − q| ≤ tol`): the distinct vertices are sorted by
//!    their projection on a fixed oblique direction `d`; a pair within `tol`
//!    has projections within `tol·|d|`, so one sweep over the sorted list
//!    finds every candidate pair, and the exact distance decides. Meshes
//!    without near-duplicates (the common case) cost only the sort.
//!
//! Loaders that already number vertices in order of first use mark the
//! mesh: pass 1 is skipped, and when exact repeats may remain (the binary
//! STL loader's provisional numbering) pass 2 merges them too, since equal
//! points have equal projections; they are not counted as welded.
//!
//! Chains: the clusters are the connected components of the graph
//! "within `tol`" (union–find), i.e. the transitive closure. The result does
//! not depend on vertex order, and a chain of vertices each within `tol` of
//! the next collapses into one vertex although its ends may lie farther
//! apart than `tol`; [`Welded::max_move`] reports the largest distance any
//! vertex moved, so such a collapse is visible. Each cluster takes the
//! position of its first vertex (in order of first use by a triangle).
//!
//! Units: distances are compared in the mesh's power-of-two unit
//! ([`crate::mesh_unit`]), so a mesh 1e200 across (whose diagonal and
//! squared tolerance would overflow) or 1e-200 across (whose squared
//! distances would underflow to 0) welds exactly as the same mesh 1 across.

use std::borrow::Cow;

use glam::DVec3;

use crate::mesh_check::Topology;
use crate::mesh_unit::{MeshUnit, diagonal_in, ldexp};
use crate::parallel::{PARALLEL_MIN, map_slices, threads_for};
use crate::{InertiaError, TriMesh};

/// Default relative weld tolerance: `1e-6 ×` the bounding-box diagonal.
///
/// About 16 single-precision ulps at the size of the mesh: files written
/// through `f32` (all binary STL) or by exporters that round coordinates
/// repeat a vertex with differences of that order (the real robot meshes
/// this was chosen on have duplicates 1e-15…1e-8 m apart), while no modelled
/// feature is that small (1.7 µm on a 1 m part; 17 nm on a 1 cm part).
pub const DEFAULT_RELATIVE_WELD: f64 = 1e-6;

/// How vertices are welded when a mesh is loaded.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Weld {
    /// Only bit-identical coordinates are merged.
    Exact,
    /// Vertices within `factor ×` the bounding-box diagonal are merged
    /// (the default, with [`DEFAULT_RELATIVE_WELD`]).
    Relative(f64),
    /// Vertices within this distance (in the mesh's own units) are merged.
    Absolute(f64),
}

impl Default for Weld {
    fn default() -> Self {
        Weld::Relative(DEFAULT_RELATIVE_WELD)
    }
}

impl Weld {
    /// The absolute tolerance for a mesh with this bounding-box diagonal.
    ///
    /// # Errors
    /// [`InertiaError::NotFinite`] for a negative, NaN or infinite factor or
    /// tolerance.
    ///
    /// ```
    /// use kreisel_inertia::Weld;
    /// assert_eq!(Weld::Relative(1e-6).tolerance(2.0)?, 2e-6);
    /// assert_eq!(Weld::Absolute(0.5).tolerance(2.0)?, 0.5);
    /// assert_eq!(Weld::Exact.tolerance(2.0)?, 0.0);
    /// assert!(Weld::Absolute(f64::NAN).tolerance(2.0).is_err());
    /// # Ok::<(), kreisel_inertia::InertiaError>(())
    /// ```
    pub fn tolerance(self, diagonal: f64) -> Result<f64, InertiaError> {
        let (quantity, value) = match self {
            Weld::Exact => return Ok(0.0),
            Weld::Relative(f) => ("relative weld tolerance", f),
            Weld::Absolute(t) => ("weld tolerance", t),
        };
        if !(value.is_finite() && value >= 0.0) {
            return Err(InertiaError::NotFinite { quantity, value });
        }
        Ok(match self {
            Weld::Relative(f) => f * diagonal,
            _ => value,
        })
    }
}

/// What welding did.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Welded {
    /// The tolerance used (mesh units; 0 for exact welding).
    pub tolerance: f64,
    /// Distinct vertices merged into another one within the tolerance
    /// (bit-identical repeats are not counted).
    pub merged: usize,
    /// The largest distance a vertex moved (mesh units).
    pub max_move: f64,
}

/// The bits that identify a position exactly (`−0.0` and `+0.0` alike).
#[inline]
fn key(v: DVec3) -> [u64; 3] {
    (v + DVec3::ZERO).to_array().map(f64::to_bits)
}

#[inline]
fn hash(k: [u64; 3]) -> u64 {
    const M: u64 = 0x9E37_79B9_7F4A_7C15;
    let h = (k[0].wrapping_mul(M) ^ k[1]).wrapping_mul(M) ^ k[2];
    let h = h.wrapping_mul(M);
    h ^ (h >> 29)
}

/// Merges bit-identical positions as they arrive: each position gets the
/// index of its first occurrence.
#[derive(Debug, Default)]
pub(crate) struct ExactDedup {
    /// The distinct positions, in order of first insertion.
    vertices: Vec<DVec3>,
    /// Open addressing: `u32::MAX` empty, else an index into `vertices`.
    slots: Vec<u32>,
}

impl ExactDedup {
    /// A table sized for about `expected` distinct positions.
    pub(crate) fn with_capacity(expected: usize) -> Self {
        let size = (2 * expected.max(8)).next_power_of_two();
        Self {
            vertices: Vec::with_capacity(expected),
            slots: vec![u32::MAX; size],
        }
    }

    /// The index of `v`, inserting it when new.
    #[inline]
    pub(crate) fn insert(&mut self, v: DVec3) -> u32 {
        if 2 * (self.vertices.len() + 1) > self.slots.len() {
            self.grow();
        }
        let k = key(v);
        let mask = self.slots.len() - 1;
        let mut at = hash(k) as usize & mask;
        loop {
            let slot = self.slots[at];
            if slot == u32::MAX {
                // Fewer distinct positions than u32 indices in the input.
                let index = self.vertices.len() as u32;
                self.slots[at] = index;
                self.vertices.push(v);
                return index;
            }
            if key(self.vertices[slot as usize]) == k {
                return slot;
            }
            at = (at + 1) & mask;
        }
    }

    fn grow(&mut self) {
        let size = (2 * self.slots.len()).max(16);
        self.slots = vec![u32::MAX; size];
        let mask = size - 1;
        for (i, &v) in self.vertices.iter().enumerate() {
            let mut at = hash(key(v)) as usize & mask;
            while self.slots[at] != u32::MAX {
                at = (at + 1) & mask;
            }
            self.slots[at] = i as u32;
        }
    }

    /// The distinct positions.
    pub(crate) fn into_vertices(self) -> Vec<DVec3> {
        self.vertices
    }
}

/// Merges bit-identical vertices; unused vertices are dropped, triangle
/// order is kept, vertices are numbered in order of first use.
fn weld_exact(vertices: &[DVec3], triangles: &mut [[u32; 3]]) -> Vec<DVec3> {
    let mut dedup = ExactDedup::with_capacity(vertices.len() / 2);
    let mut remap = vec![u32::MAX; vertices.len()];
    for t in triangles.iter_mut() {
        for i in t.iter_mut() {
            let r = &mut remap[*i as usize];
            if *r == u32::MAX {
                *r = dedup.insert(vertices[*i as usize]);
            }
            *i = *r;
        }
    }
    dedup.into_vertices()
}

/// An order-preserving map from `f64` to `u64` (for sorting by key).
#[inline]
fn ordered(x: f64) -> u64 {
    let b = x.to_bits();
    if b >> 63 == 1 { !b } else { b | (1 << 63) }
}

/// The root of `i`, halving paths on the way.
fn find(parent: &mut [u32], mut i: u32) -> u32 {
    while parent[i as usize] != i {
        let p = parent[i as usize];
        parent[i as usize] = parent[p as usize];
        i = p;
    }
    i
}

/// A vertex in the sweep of [`weld_near`]: its projection on the sweep
/// direction (as [`ordered`] bits) and its index, the sort key; and its
/// projection on a second direction rounded to `f32`, a filter that rules
/// out most candidate pairs before their vertices (in random places of
/// memory) are loaded.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
struct Projected {
    key: u64,
    index: u32,
    side: f32,
}

/// Every vertex [`Projected`] on `d` and `e`, sorted by key and index, and
/// the largest `|v · d|` and `|v · e|`, on up to `threads` threads: each
/// sorts its part, then one merge of the sorted runs (the stable sort finds
/// them). Keys and indices together are unique, so the order is the same on
/// any number of threads.
fn projection_order(
    vertices: &[DVec3],
    (d, e): (DVec3, DVec3),
    threads: usize,
) -> (Vec<Projected>, f64, f64) {
    let mut order = vec![Projected::default(); vertices.len()];
    let largest = map_slices(&mut order, threads, 1, |first, part| {
        let (mut largest, mut largest_side): (f64, f64) = (0.0, 0.0);
        for (k, (o, v)) in part.iter_mut().zip(&vertices[first..]).enumerate() {
            let (p, q) = (v.dot(d), v.dot(e));
            largest = largest.max(p.abs());
            largest_side = largest_side.max(q.abs());
            *o = Projected {
                key: ordered(p),
                index: (first + k) as u32,
                side: q as f32,
            };
        }
        part.sort_unstable_by_key(|p| (p.key, p.index));
        (largest, largest_side)
    });
    if threads > 1 {
        order.sort_by_key(|p| (p.key, p.index));
    }
    let (largest, largest_side) = largest.into_iter().fold((0.0, 0.0), |(a, b), (x, y)| {
        (f64::max(a, x), f64::max(b, y))
    });
    (order, largest, largest_side)
}

/// Vertices within `tol` merged: the new index of each vertex, the
/// vertices kept (from `original`) and the report; `None` when nothing is
/// within `tol`. Distances are measured in `vertices` (the original ones in
/// the mesh's power-of-two unit `2^k`); the report is in `original` units.
/// With `repeats`, bit-identical vertices may be among them (the later ones
/// are merged into the first like any pair within `tol`, but not counted in
/// [`Welded::merged`]).
fn weld_near(
    vertices: &[DVec3],
    original: &[DVec3],
    unit: &MeshUnit,
    tol: f64,
    repeats: bool,
) -> Option<(Vec<u32>, Vec<DVec3>, Welded)> {
    // An oblique direction, so that the axis-aligned planes of CAD meshes
    // do not put many vertices at one projection.
    let d = DVec3::new(1.0, 0.754_877_666_246_692_7, 0.569_840_290_998_053_3);
    // Another oblique direction, far from parallel to d, for the filter.
    let e = DVec3::new(-0.569_840_290_998_053_3, 1.0, -0.754_877_666_246_692_7);
    let (order, largest, largest_side) =
        projection_order(vertices, (d, e), threads_for(vertices.len()));
    // Projections of points within `tol` differ by at most `tol |d|`, plus
    // the rounding of the two dot products.
    let reach = tol * d.length() * (1.0 + 1e-12) + 8.0 * f64::EPSILON * largest;
    // The same on e, plus the rounding of both to f32 (half an f32 ulp
    // each, or half the smallest subnormal), twice over.
    let reach_side = tol * e.length() * (1.0 + 1e-12)
        + 8.0 * f64::EPSILON * largest_side
        + 2.0 * f64::from(f32::EPSILON) * largest_side
        + 2.0 * f64::from(f32::MIN_POSITIVE);
    let proj = |k: u64| -> f64 { f64::from_bits(if k >> 63 == 1 { k & !(1 << 63) } else { !k }) };
    let tol2 = tol * tol;
    let mut parent: Vec<u32> = Vec::new();
    // Vertices bit-identical to one with a smaller index (only `repeats`).
    let mut repeat: Vec<bool> = Vec::new();
    for (n, a) in order.iter().enumerate() {
        let (pi, i) = (proj(a.key), a.index);
        for b in &order[n + 1..] {
            if proj(b.key) - pi > reach {
                break;
            }
            let j = b.index;
            if (f64::from(b.side) - f64::from(a.side)).abs() <= reach_side
                && vertices[i as usize].distance_squared(vertices[j as usize]) <= tol2
            {
                if parent.is_empty() {
                    parent = (0..vertices.len() as u32).collect();
                }
                // `==` holds for −0.0 and +0.0 alike, as the keys of the
                // exact pass do; equal points have equal projections, so
                // every pair of them is met here.
                if repeats && vertices[i as usize] == vertices[j as usize] {
                    if repeat.is_empty() {
                        repeat = vec![false; vertices.len()];
                    }
                    repeat[i.max(j) as usize] = true;
                }
                let (a, b) = (find(&mut parent, i), find(&mut parent, j));
                // The smaller index is the root: the first vertex in use order.
                let (lo, hi) = (a.min(b), a.max(b));
                parent[hi as usize] = lo;
            }
        }
    }
    if parent.is_empty() {
        return None;
    }
    let mut new_index = vec![u32::MAX; vertices.len()];
    let mut kept = Vec::new();
    let mut welded = Welded {
        tolerance: unit.scale_back(tol, 1),
        ..Welded::default()
    };
    for i in 0..vertices.len() as u32 {
        let root = find(&mut parent, i);
        if root == i {
            new_index[i as usize] = kept.len() as u32;
            kept.push(original[i as usize]);
        } else {
            // Roots come first in index order, so the root is numbered.
            new_index[i as usize] = new_index[root as usize];
            // A repeat is never a root (its first copy has a smaller index).
            if !repeat.get(i as usize).is_some_and(|&r| r) {
                welded.merged += 1;
            }
            let moved = vertices[i as usize].distance(vertices[root as usize]);
            welded.max_move = welded.max_move.max(moved);
        }
    }
    welded.max_move = unit.scale_back(welded.max_move, 1);
    Some((new_index, kept, welded))
}

impl TriMesh {
    /// The mesh with its vertices welded: bit-identical ones always, and
    /// distinct ones within the tolerance of `weld` (see the module notes on
    /// chains). Unused vertices are dropped; triangle order is kept.
    ///
    /// ```text
    /// v_i ≡ v_j  ⇔  a chain v_i = p_0, p_1, …, p_k = v_j with |p_(n+1) − p_n| ≤ tol
    /// ```
    ///
    /// # Errors
    /// [`InertiaError::NotFinite`] for a negative, NaN or infinite
    /// tolerance.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_inertia::{TriMesh, Weld};
    /// let v = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::X * (1.0 + 1e-12), DVec3::Y, DVec3::Z];
    /// let mesh = TriMesh::new(v, vec![[0, 1, 2], [3, 5, 4]]);
    /// let (exact, none) = mesh.clone().welded(Weld::Exact)?;
    /// assert_eq!((exact.vertices().len(), none.merged), (5, 0));
    /// let (welded, report) = mesh.welded(Weld::default())?;
    /// assert_eq!((welded.vertices().len(), report.merged), (4, 1));
    /// assert_eq!(welded.triangles()[1], [1, 3, 2]);
    /// # Ok::<(), kreisel_inertia::InertiaError>(())
    /// ```
    pub fn welded(self, weld: Weld) -> Result<(TriMesh, Welded), InertiaError> {
        // Tolerances and distances in the mesh's power-of-two unit (exact
        // scaling; the unit is 1 for every mesh between 2^-64 and 2^64 across).
        let unit = MeshUnit::of(self.vertices());
        let tol = match weld {
            Weld::Absolute(_) => ldexp(weld.tolerance(0.0)?, -unit.k),
            _ => weld.tolerance(diagonal_in(self.vertices(), &unit))?,
        };
        let (exact_unique, first_use) = (self.is_exact_unique(), self.is_first_use());
        let (vertices, mut triangles) = self.into_parts();
        let vertices = if exact_unique || first_use {
            // The loader numbered the vertices in order of first use (and
            // merged exact repeats already, unless `first_use`).
            vertices
        } else {
            weld_exact(&vertices, &mut triangles)
        };
        let repeats = first_use && !exact_unique;
        let unchanged = Welded {
            tolerance: unit.scale_back(tol, 1),
            ..Welded::default()
        };
        if tol == 0.0 && !repeats {
            return Ok((TriMesh::from_checked_parts(vertices, triangles), unchanged));
        }
        // The check's topology is found from the triangles on another
        // thread while the tolerance pass runs here; it is kept only when
        // that pass leaves the triangles as they are (the common case; not
        // tried when exact repeats are left to the pass, which then merges
        // them).
        let scaled: Cow<[DVec3]> = if unit.is_identity() {
            Cow::Borrowed(&vertices)
        } else {
            Cow::Owned(vertices.iter().map(|&v| unit.point_in_unit(v)).collect())
        };
        let near = || weld_near(&scaled, &vertices, &unit, tol, repeats);
        let (near, topology) = if triangles.len() >= PARALLEL_MIN && !repeats {
            std::thread::scope(|scope| {
                let topology = scope.spawn(|| Topology::of_solid(&triangles, vertices.len()));
                let near = near();
                (near, topology.join().ok().flatten())
            })
        } else {
            (near(), None)
        };
        let Some((new_index, kept, report)) = near else {
            let mesh = TriMesh::from_checked_parts(vertices, triangles);
            let mesh = match topology {
                Some(t) => mesh.with_topology(t),
                None => mesh,
            };
            return Ok((mesh, unchanged));
        };
        let threads = threads_for(triangles.len());
        map_slices(&mut triangles, threads, 1, |_, part| {
            for t in part {
                *t = t.map(|i| new_index[i as usize]);
            }
        });
        Ok((TriMesh::from_checked_parts(kept, triangles), report))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chains_collapse_transitively_and_report_the_largest_move() {
        // 0 — 1 — 2 each 0.6 apart with tol 1: 0 and 2 are 1.2 apart but one cluster.
        let v = vec![
            DVec3::ZERO,
            DVec3::new(0.6, 0.0, 0.0),
            DVec3::new(1.2, 0.0, 0.0),
            DVec3::new(100.0, 0.0, 0.0),
            DVec3::new(0.0, 100.0, 0.0),
        ];
        let mesh = TriMesh::new(v, vec![[0, 3, 4], [1, 3, 4], [2, 3, 4]]);
        let (m, w) = mesh.welded(Weld::Absolute(1.0)).unwrap();
        assert_eq!(m.vertices().len(), 3);
        assert_eq!(m.triangles(), &[[0, 1, 2], [0, 1, 2], [0, 1, 2]]);
        assert_eq!((w.merged, w.tolerance), (2, 1.0));
        assert!((w.max_move - 1.2).abs() < 1e-15, "{}", w.max_move);
    }

    #[test]
    fn result_does_not_depend_on_vertex_order() {
        let base = [
            DVec3::new(0.3, 0.1, 0.2),
            DVec3::new(0.3 + 1e-9, 0.1, 0.2 - 1e-9),
            DVec3::new(5.0, 1.0, 0.0),
            DVec3::new(0.0, 4.0, 3.0),
        ];
        for perm in [[0, 1, 2, 3], [1, 0, 3, 2], [3, 2, 1, 0]] {
            let v: Vec<DVec3> = perm.iter().map(|&i| base[i]).collect();
            let inv = |i: usize| perm.iter().position(|&p| p == i).unwrap() as u32;
            let mesh = TriMesh::new(v, vec![[inv(0), inv(2), inv(3)], [inv(1), inv(3), inv(2)]]);
            let (m, w) = mesh.welded(Weld::default()).unwrap();
            assert_eq!((m.vertices().len(), w.merged), (3, 1));
            assert_eq!(m.triangles(), &[[0, 1, 2], [0, 2, 1]]);
        }
    }

    #[test]
    fn exact_table_grows_and_keeps_first_indices() {
        let mut d = ExactDedup::with_capacity(1);
        let pts: Vec<DVec3> = (0..1000)
            .map(|i| DVec3::new(f64::from(i), 0.0, -0.0))
            .collect();
        for (i, &p) in pts.iter().enumerate() {
            assert_eq!(d.insert(p) as usize, i);
        }
        for (i, &p) in pts.iter().enumerate().rev() {
            assert_eq!(d.insert(p + DVec3::ZERO) as usize, i);
        }
        assert_eq!(d.into_vertices().len(), 1000);
    }

    #[test]
    fn repeats_left_to_the_tolerance_pass_weld_as_the_exact_pass_does() {
        // First-use order with bit-identical repeats (one as −0.0), and one
        // near-duplicate 1e-9 away: only the near one counts as welded.
        let v = vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::X,
            DVec3::Y,
            DVec3::new(-0.0, 0.0, 0.0),
            DVec3::Z,
            DVec3::Y,
            DVec3::new(1.0 + 1e-9, 0.0, 0.0),
            DVec3::X,
        ];
        let t = vec![[0, 1, 2], [3, 4, 5], [6, 7, 4], [2, 3, 7]];
        for weld in [Weld::Exact, Weld::default()] {
            let full = TriMesh::new(v.clone(), t.clone()).welded(weld).unwrap();
            let left = TriMesh::new(v.clone(), t.clone())
                .known_first_use()
                .welded(weld)
                .unwrap();
            assert_eq!(left.0, full.0);
            let bits = |m: &TriMesh| -> Vec<[u64; 3]> {
                m.vertices()
                    .iter()
                    .map(|p| p.to_array().map(f64::to_bits))
                    .collect()
            };
            assert_eq!(bits(&left.0), bits(&full.0));
            assert_eq!(left.1, full.1);
        }
        let (_, report) = TriMesh::new(v, t)
            .known_first_use()
            .welded(Weld::default())
            .unwrap();
        assert_eq!(report.merged, 1);
    }

    #[test]
    fn tiny_and_huge_meshes_weld_as_the_same_mesh_one_across() {
        // Vertex 4 lies 1e-5 of the size from vertex 0 across the sweep
        // direction (same projection), vertex 5 within 1e-7 of vertex 1.
        // At 2^-540 (≈ 3e-163) the squared distances underflowed to 0 and
        // vertex 4 was merged; at 2^+540 the diagonal overflowed.
        let d = DVec3::new(0.754_877_666_246_692_7, -1.0, 0.0);
        let base = vec![
            DVec3::new(0.25, 0.5, 0.125),
            DVec3::X,
            DVec3::Y,
            DVec3::Z,
            DVec3::new(0.25, 0.5, 0.125) + d * 1e-5,
            DVec3::X + DVec3::splat(1e-7),
        ];
        let t = vec![[0, 1, 2], [4, 2, 3], [5, 3, 0]];
        let (one, w1) = TriMesh::new(base.clone(), t.clone())
            .welded(Weld::default())
            .unwrap();
        assert_eq!((one.vertices().len(), w1.merged), (5, 1));
        for k in [-540_i32, -300, 300, 540] {
            let f = |x: f64| {
                (0..k.unsigned_abs()).fold(x, |x, _| if k > 0 { x * 2.0 } else { x * 0.5 })
            };
            let v = base.iter().map(|p| p.to_array().map(f).into()).collect();
            let (m, w) = TriMesh::new(v, t.clone()).welded(Weld::default()).unwrap();
            assert_eq!(m.triangles(), one.triangles(), "2^{k}");
            assert_eq!(
                (w.merged, w.tolerance, w.max_move),
                (1, f(w1.tolerance), f(w1.max_move)),
                "2^{k}"
            );
            let back: Vec<DVec3> = one
                .vertices()
                .iter()
                .map(|p| p.to_array().map(f).into())
                .collect();
            assert_eq!(m.vertices(), back.as_slice(), "2^{k}");
        }
    }

    #[test]
    fn bad_tolerances_are_errors() {
        for t in [-1.0, f64::NAN, f64::INFINITY] {
            assert!(Weld::Absolute(t).tolerance(1.0).is_err());
            assert!(Weld::Relative(t).tolerance(1.0).is_err());
        }
    }

    #[test]
    fn projection_order_does_not_depend_on_the_thread_count() {
        // Repeated and signed-zero projections among them (ties).
        let v: Vec<DVec3> = (0..5000)
            .map(|i| {
                let t = f64::from(i % 1700);
                DVec3::new((0.3 * t).sin(), if i % 3 == 0 { -0.0 } else { 0.0 }, t)
            })
            .collect();
        let de = (DVec3::new(1.0, 0.75, 0.5), DVec3::new(-0.5, 1.0, -0.75));
        let one = projection_order(&v, de, 1);
        assert!(
            one.0
                .windows(2)
                .all(|w| (w[0].key, w[0].index) < (w[1].key, w[1].index))
        );
        for threads in [2, 3, 8] {
            assert_eq!(projection_order(&v, de, threads), one);
        }
    }

    #[test]
    fn the_side_filter_keeps_pairs_at_the_tolerance_at_every_scale() {
        // Pairs exactly tol apart along the filter's direction, far from the
        // origin (large projections, coarse f32 rounding) and near it.
        for (centre, tol) in [(1e9, 1e-3), (1.0, 1e-12), (1e-30, 1e-40), (0.0, 0.0)] {
            let e = DVec3::new(-0.569_840_290_998_053_3, 1.0, -0.754_877_666_246_692_7);
            let p = DVec3::new(centre, -centre, 0.5 * centre);
            let q = p + e.normalize() * tol * 0.99;
            let far = DVec3::splat(centre + 1.0);
            let mesh = TriMesh::new(vec![p, far, far + DVec3::X, q], vec![[0, 1, 2], [3, 2, 1]]);
            let (welded, report) = mesh.welded(Weld::Absolute(tol)).unwrap();
            assert_eq!(welded.vertices().len(), 3, "{centre} {tol}");
            assert!(report.merged == 1 || p == q, "{centre} {tol}");
        }
    }
}
