//! Indexed triangle meshes: vertices and triangles, validated on construction.

use std::collections::HashMap;

use glam::DVec3;

use crate::InertiaError;

/// A triangle mesh: vertex positions and triangles as vertex-index triples.
///
/// Triangles are wound counter-clockwise seen from outside (normals
/// `(b − a) × (c − a)` point outwards) for a correctly oriented closed
/// surface. Construction checks only what every use needs (non-empty,
/// finite coordinates, indices in range); topology (closed, manifold,
/// consistent winding) is checked separately.
#[derive(Debug, Clone, PartialEq)]
pub struct TriMesh {
    vertices: Vec<DVec3>,
    triangles: Vec<[u32; 3]>,
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
        if let Some(vertex) = vertices.iter().position(|v| !v.is_finite()) {
            return Err(InertiaError::NonFiniteVertex { vertex });
        }
        let n = vertices.len();
        for (triangle, t) in triangles.iter().enumerate() {
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
        }
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
    #[inline]
    pub fn corners(&self, t: [u32; 3]) -> [DVec3; 3] {
        t.map(|i| self.vertices[i as usize])
    }

    /// The mesh with every vertex scaled about the origin by `factor`.
    ///
    /// ```text
    /// v ↦ s · v
    /// ```
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_inertia::TriMesh;
    /// let mesh = TriMesh::new(vec![DVec3::ZERO, DVec3::X, DVec3::Y], vec![[0, 1, 2]]).scaled(1e-3);
    /// assert_eq!(mesh.vertices()[1], DVec3::new(1e-3, 0.0, 0.0));
    /// ```
    pub fn scaled(mut self, factor: f64) -> Self {
        for v in &mut self.vertices {
            *v *= factor;
        }
        self
    }

    /// The mesh with every vertex moved by `offset`.
    ///
    /// ```text
    /// v ↦ v + offset
    /// ```
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_inertia::TriMesh;
    /// let mesh = TriMesh::new(vec![DVec3::ZERO, DVec3::X, DVec3::Y], vec![[0, 1, 2]]).translated(DVec3::Z);
    /// assert_eq!(mesh.vertices()[0], DVec3::Z);
    /// ```
    pub fn translated(mut self, offset: DVec3) -> Self {
        for v in &mut self.vertices {
            *v += offset;
        }
        self
    }

    /// Merges vertices with bit-identical coordinates (as STL files repeat
    /// every vertex once per triangle), so that topology checks see shared
    /// edges. Unused vertices are dropped; triangle order is kept.
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
        let key = |v: DVec3| (v + DVec3::ZERO).to_array().map(f64::to_bits);
        let mut index_of: HashMap<[u64; 3], u32> = HashMap::with_capacity(self.vertices.len());
        let mut vertices = Vec::new();
        let mut remap = vec![u32::MAX; self.vertices.len()];
        let triangles = self
            .triangles
            .iter()
            .map(|t| {
                t.map(|i| {
                    let i = i as usize;
                    if remap[i] == u32::MAX {
                        let v = self.vertices[i];
                        remap[i] = *index_of.entry(key(v)).or_insert_with(|| {
                            vertices.push(v);
                            // Fewer vertices than the input, which had u32 indices.
                            (vertices.len() - 1) as u32
                        });
                    }
                    remap[i]
                })
            })
            .collect();
        Self {
            vertices,
            triangles,
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
}
