//! Indexed triangle meshes: vertices and triangles, validated on construction.

use std::sync::Arc;

use glam::DVec3;

use crate::InertiaError;
use crate::mesh_check::Topology;
use crate::parallel::any;

/// A triangle mesh: vertex positions and triangles as vertex-index triples.
///
/// Triangles are wound counter-clockwise seen from outside (normals
/// `(b − a) × (c − a)` point outwards) for a correctly oriented closed
/// surface. Construction checks only what every use needs (non-empty,
/// finite coordinates, indices in range); topology (closed, manifold,
/// consistent winding) is checked separately.
#[derive(Debug, Clone)]
pub struct TriMesh {
    vertices: Vec<DVec3>,
    triangles: Vec<[u32; 3]>,
    /// Known to have no two bit-identical vertices (`−0.0 ≡ +0.0`), none
    /// unused, numbered in order of first use: what the exact pass of
    /// [`TriMesh::welded`] would produce, so it is skipped. Set by loaders
    /// that merge exact repeats as they read; cleared by any change.
    exact_unique: bool,
    /// Known to be numbered in order of first use with none unused, but
    /// perhaps with bit-identical vertices (each repeat after its first):
    /// [`TriMesh::welded`] skips its exact pass and merges the repeats in
    /// its tolerance pass. Set by loaders; cleared by any change.
    first_use: bool,
    /// The closed, orientable topology of `triangles`, when found while the
    /// mesh was welded (on another thread, beside the tolerance pass), so
    /// that [`crate::prepare_solid`] need not find it again. It depends on
    /// the triangles alone: scaling and moving keep it; every mesh built
    /// from parts starts without it.
    topology: Option<Arc<Topology>>,
}

/// Meshes are equal when their vertices and triangles are.
impl PartialEq for TriMesh {
    fn eq(&self, other: &Self) -> bool {
        self.vertices == other.vertices && self.triangles == other.triangles
    }
}

impl TriMesh {
    /// Builds a mesh, checking that it is non-empty, that every coordinate
    /// is finite and every index in range.
    ///
    /// # Errors
    /// [`InertiaError::EmptyMesh`], [`InertiaError::NonFiniteVertex`],
    /// [`InertiaError::IndexOutOfRange`].
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_inertia::TriMesh;
    /// let v = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::Z];
    /// let t = vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
    /// let mesh = TriMesh::try_new(v.clone(), t)?;
    /// assert_eq!(mesh.triangles().len(), 4);
    /// assert!(TriMesh::try_new(v, vec![[0, 1, 4]]).is_err());
    /// # Ok::<(), kreisel_inertia::InertiaError>(())
    /// ```
    pub fn try_new(vertices: Vec<DVec3>, triangles: Vec<[u32; 3]>) -> Result<Self, InertiaError> {
        if vertices.is_empty() || triangles.is_empty() {
            return Err(InertiaError::EmptyMesh {
                vertices: vertices.len(),
                triangles: triangles.len(),
            });
        }
        // Looked for on the machine's cores; the first one found on this
        // thread (rarely).
        if any(&vertices, |v| !v.is_finite())
            && let Some(vertex) = vertices.iter().position(|v| !v.is_finite())
        {
            return Err(InertiaError::NonFiniteVertex { vertex });
        }
        let n = vertices.len();
        let out_of_range = |t: &[u32; 3]| t.iter().any(|&i| i as usize >= n);
        let bad = if any(&triangles, out_of_range) {
            &triangles[..]
        } else {
            &[]
        };
        for (triangle, t) in bad.iter().enumerate() {
            if let Some(&index) = t.iter().find(|&&i| i as usize >= n) {
                return Err(InertiaError::IndexOutOfRange {
                    triangle,
                    index: u64::from(index),
                    vertex_count: n,
                });
            }
        }
        Ok(Self {
            vertices,
            triangles,
            exact_unique: false,
            first_use: false,
            topology: None,
        })
    }

    /// Builds a mesh from valid data.
    ///
    /// # Panics
    /// On input that [`TriMesh::try_new`] rejects.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_inertia::TriMesh;
    /// let mesh = TriMesh::new(vec![DVec3::ZERO, DVec3::X, DVec3::Y], vec![[0, 1, 2]]);
    /// assert_eq!(mesh.vertices().len(), 3);
    /// ```
    pub fn new(vertices: Vec<DVec3>, triangles: Vec<[u32; 3]>) -> Self {
        match Self::try_new(vertices, triangles) {
            Ok(m) => m,
            Err(e) => panic!("{e}"),
        }
    }

    /// Builds a mesh from parts already known to be valid (indices in range,
    /// coordinates finite), e.g. a checked mesh with triangles removed.
    pub(crate) fn from_checked_parts(vertices: Vec<DVec3>, triangles: Vec<[u32; 3]>) -> Self {
        Self {
            vertices,
            triangles,
            exact_unique: false,
            first_use: false,
            topology: None,
        }
    }

    /// Marks the mesh as having no bit-identical, unused or out-of-order
    /// vertices (the caller's guarantee; see the field), so that
    /// [`TriMesh::welded`] skips its exact pass.
    #[cfg_attr(not(feature = "formats"), allow(dead_code))]
    pub(crate) fn known_exact_unique(mut self) -> Self {
        self.exact_unique = true;
        self
    }

    /// Marks the mesh as numbered in order of first use, none unused, exact
    /// repeats possible (the caller's guarantee; see the field).
    #[cfg_attr(not(feature = "formats"), allow(dead_code))]
    pub(crate) fn known_first_use(mut self) -> Self {
        self.first_use = true;
        self
    }

    /// Whether [`TriMesh::known_first_use`] holds.
    pub(crate) fn is_first_use(&self) -> bool {
        self.first_use
    }

    /// The mesh with the topology of its triangles attached (see the field).
    pub(crate) fn with_topology(mut self, topology: Topology) -> Self {
        self.topology = Some(Arc::new(topology));
        self
    }

    /// The vertices, the triangles and their topology if it is known.
    pub(crate) fn into_parts_and_topology(
        self,
    ) -> (Vec<DVec3>, Vec<[u32; 3]>, Option<Arc<Topology>>) {
        (self.vertices, self.triangles, self.topology)
    }

    /// Whether [`TriMesh::known_exact_unique`] holds.
    pub(crate) fn is_exact_unique(&self) -> bool {
        self.exact_unique
    }

    /// The vertex positions.
    pub fn vertices(&self) -> &[DVec3] {
        &self.vertices
    }

    /// The triangles, as indices into [`TriMesh::vertices`].
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// Splits the mesh into its vertex and triangle lists.
    pub fn into_parts(self) -> (Vec<DVec3>, Vec<[u32; 3]>) {
        (self.vertices, self.triangles)
    }

    /// The three corners of triangle `t`.
    ///
    /// # Panics
    /// When an index of `t` is not a vertex of this mesh (never for the
    /// mesh's own [`TriMesh::triangles`]); [`TriMesh::try_corners`] returns
    /// `None` instead.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_inertia::TriMesh;
    /// let mesh = TriMesh::new(vec![DVec3::ZERO, DVec3::X, DVec3::Y], vec![[0, 1, 2]]);
    /// assert_eq!(mesh.corners([2, 1, 0]), [DVec3::Y, DVec3::X, DVec3::ZERO]);
    /// ```
    #[inline]
    pub fn corners(&self, t: [u32; 3]) -> [DVec3; 3] {
        t.map(|i| self.vertices[i as usize])
    }

    /// The three corners of triangle `t`, or `None` when an index is not a
    /// vertex of this mesh.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_inertia::TriMesh;
    /// let mesh = TriMesh::new(vec![DVec3::ZERO, DVec3::X, DVec3::Y], vec![[0, 1, 2]]);
    /// assert_eq!(mesh.try_corners([0, 1, 2]), Some([DVec3::ZERO, DVec3::X, DVec3::Y]));
    /// assert_eq!(mesh.try_corners([0, 1, 3]), None);
    /// ```
    pub fn try_corners(&self, t: [u32; 3]) -> Option<[DVec3; 3]> {
        let [a, b, c] = t.map(|i| self.vertices.get(i as usize).copied());
        Some([a?, b?, c?])
    }

    /// The mesh with every vertex scaled about the origin by `factor`.
    ///
    /// ```text
    /// v ↦ s · v
    /// ```
    ///
    /// # Errors
    /// [`InertiaError::NotFinite`] for a NaN or infinite factor,
    /// [`InertiaError::NonFiniteVertex`] when a scaled coordinate overflows.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_inertia::TriMesh;
    /// let mesh = TriMesh::new(vec![DVec3::ZERO, DVec3::X, DVec3::Y], vec![[0, 1, 2]]);
    /// assert_eq!(mesh.clone().try_scaled(1e-3)?.vertices()[1], DVec3::new(1e-3, 0.0, 0.0));
    /// assert!(mesh.clone().try_scaled(f64::NAN).is_err());
    /// assert!(mesh.try_scaled(1e308)?.try_scaled(10.0).is_err());
    /// # Ok::<(), kreisel_inertia::InertiaError>(())
    /// ```
    pub fn try_scaled(mut self, factor: f64) -> Result<Self, InertiaError> {
        if !factor.is_finite() {
            return Err(InertiaError::NotFinite {
                quantity: "scale factor",
                value: factor,
            });
        }
        self.exact_unique = false;
        self.first_use = false;
        for v in &mut self.vertices {
            *v *= factor;
        }
        self.check_finite()
    }

    /// The mesh with every vertex scaled about the origin by `factor`.
    ///
    /// # Panics
    /// When [`TriMesh::try_scaled`] fails (a non-finite factor, overflow).
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_inertia::TriMesh;
    /// let mesh = TriMesh::new(vec![DVec3::ZERO, DVec3::X, DVec3::Y], vec![[0, 1, 2]]).scaled(1e-3);
    /// assert_eq!(mesh.vertices()[1], DVec3::new(1e-3, 0.0, 0.0));
    /// ```
    pub fn scaled(self, factor: f64) -> Self {
        self.try_scaled(factor).unwrap_or_else(|e| panic!("{e}"))
    }

    /// The mesh with every vertex moved by `offset`.
    ///
    /// ```text
    /// v ↦ v + offset
    /// ```
    ///
    /// # Errors
    /// [`InertiaError::NotFinite`] for a non-finite offset,
    /// [`InertiaError::NonFiniteVertex`] when a moved coordinate overflows.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_inertia::TriMesh;
    /// let mesh = TriMesh::new(vec![DVec3::ZERO, DVec3::X, DVec3::Y], vec![[0, 1, 2]]);
    /// assert_eq!(mesh.clone().try_translated(DVec3::Z)?.vertices()[0], DVec3::Z);
    /// assert!(mesh.try_translated(DVec3::splat(f64::INFINITY)).is_err());
    /// # Ok::<(), kreisel_inertia::InertiaError>(())
    /// ```
    pub fn try_translated(mut self, offset: DVec3) -> Result<Self, InertiaError> {
        if let Some(&value) = offset.to_array().iter().find(|x| !x.is_finite()) {
            return Err(InertiaError::NotFinite {
                quantity: "offset",
                value,
            });
        }
        self.exact_unique = false;
        self.first_use = false;
        for v in &mut self.vertices {
            *v += offset;
        }
        self.check_finite()
    }

    /// The mesh with every vertex moved by `offset`.
    ///
    /// # Panics
    /// When [`TriMesh::try_translated`] fails (a non-finite offset, overflow).
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_inertia::TriMesh;
    /// let mesh = TriMesh::new(vec![DVec3::ZERO, DVec3::X, DVec3::Y], vec![[0, 1, 2]]).translated(DVec3::Z);
    /// assert_eq!(mesh.vertices()[0], DVec3::Z);
    /// ```
    pub fn translated(self, offset: DVec3) -> Self {
        self.try_translated(offset)
            .unwrap_or_else(|e| panic!("{e}"))
    }

    /// The mesh in the power-of-two unit `unit` (see [`crate::mesh_unit`]):
    /// exact scaling, so the known topology is kept.
    pub(crate) fn in_unit(mut self, unit: &crate::mesh_unit::MeshUnit) -> Self {
        self.exact_unique = false;
        self.first_use = false;
        for v in &mut self.vertices {
            *v = unit.point_in_unit(*v);
        }
        self
    }

    /// `self`, or the first vertex with a non-finite coordinate.
    fn check_finite(self) -> Result<Self, InertiaError> {
        match self.vertices.iter().position(|v| !v.is_finite()) {
            Some(vertex) => Err(InertiaError::NonFiniteVertex { vertex }),
            None => Ok(self),
        }
    }

    /// Merges vertices with bit-identical coordinates (as STL files repeat
    /// every vertex once per triangle), so that topology checks see shared
    /// edges. Unused vertices are dropped; triangle order is kept. The same
    /// as [`TriMesh::welded`] with [`crate::Weld::Exact`].
    ///
    /// ```text
    /// v_i ≡ v_j  ⇔  v_i == v_j exactly   (−0.0 ≡ +0.0)
    /// ```
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_inertia::TriMesh;
    /// let v = vec![DVec3::ZERO, DVec3::X, DVec3::Y, DVec3::X, DVec3::Y, DVec3::Z];
    /// let mesh = TriMesh::new(v, vec![[0, 1, 2], [3, 5, 4]]).merge_duplicate_vertices();
    /// assert_eq!(mesh.vertices().len(), 4);
    /// assert_eq!(mesh.triangles()[1], [1, 3, 2]);
    /// ```
    pub fn merge_duplicate_vertices(self) -> Self {
        match self.welded(crate::Weld::Exact) {
            Ok((mesh, _)) => mesh,
            // Exact welding has no tolerance to reject.
            Err(_) => unreachable!("exact welding cannot fail"),
        }
    }
}

/// An axis-aligned box from `lo` to `hi` as 12 outward-wound triangles
/// (vertex `i` has bit 0, 1, 2 selecting `hi` in x, y, z), for unit tests.
#[cfg(test)]
pub(crate) fn box_mesh(lo: DVec3, hi: DVec3) -> TriMesh {
    let pick = |i: usize, bit: usize, lo: f64, hi: f64| if i & bit == 0 { lo } else { hi };
    let v: Vec<DVec3> = (0..8)
        .map(|i| {
            DVec3::new(
                pick(i, 1, lo.x, hi.x),
                pick(i, 2, lo.y, hi.y),
                pick(i, 4, lo.z, hi.z),
            )
        })
        .collect();
    let t = vec![
        [0, 2, 1],
        [1, 2, 3],
        [4, 5, 6],
        [5, 7, 6],
        [0, 1, 4],
        [1, 5, 4],
        [2, 6, 3],
        [3, 6, 7],
        [0, 4, 2],
        [2, 4, 6],
        [1, 3, 5],
        [3, 7, 5],
    ];
    TriMesh::new(v, t)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rejects_empty_nan_and_bad_index() {
        assert!(matches!(
            TriMesh::try_new(vec![], vec![]),
            Err(InertiaError::EmptyMesh { .. })
        ));
        let v = vec![DVec3::ZERO, DVec3::new(f64::NAN, 0.0, 0.0), DVec3::Y];
        assert!(matches!(
            TriMesh::try_new(v, vec![[0, 1, 2]]),
            Err(InertiaError::NonFiniteVertex { vertex: 1 })
        ));
        let v = vec![DVec3::ZERO, DVec3::X, DVec3::Y];
        assert!(matches!(
            TriMesh::try_new(v, vec![[0, 1, 2], [0, 1, 7]]),
            Err(InertiaError::IndexOutOfRange {
                triangle: 1,
                index: 7,
                vertex_count: 3
            })
        ));
    }

    #[test]
    fn merge_treats_signed_zeros_alike_and_drops_unused() {
        let v = vec![
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(-0.0, 0.0, 0.0),
            DVec3::X,
            DVec3::Y,
            DVec3::Z,
        ];
        let mesh = TriMesh::new(v, vec![[0, 2, 3], [1, 3, 2]]).merge_duplicate_vertices();
        assert_eq!(mesh.vertices().len(), 3);
        assert_eq!(mesh.triangles(), &[[0, 1, 2], [0, 2, 1]]);
    }

    #[test]
    fn large_meshes_name_their_first_bad_vertex_and_index() {
        // Large enough to be searched on several threads.
        let n = 3 * crate::parallel::PARALLEL_MIN;
        let mut v: Vec<DVec3> = (0..n).map(|i| DVec3::splat(i as f64)).collect();
        let mut t: Vec<[u32; 3]> = (0..n as u32).map(|i| [i, i, i]).collect();
        t[n - 10][1] = n as u32 + 5;
        t[n / 2 + 1][2] = n as u32;
        assert!(matches!(
            TriMesh::try_new(v.clone(), t.clone()),
            Err(InertiaError::IndexOutOfRange { triangle, index, .. })
                if triangle == n / 2 + 1 && index == n as u64
        ));
        v[n - 1].y = f64::NAN;
        v[n / 3].z = f64::INFINITY;
        assert!(matches!(
            TriMesh::try_new(v, t),
            Err(InertiaError::NonFiniteVertex { vertex }) if vertex == n / 3
        ));
    }
}
