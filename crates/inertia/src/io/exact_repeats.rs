//! Sharing bit-identical vertices of an indexed mesh (OBJ, PLY) in the
//! loader, so that [`TriMesh::welded`] can skip its exact pass.
//!
//! The result is exactly that pass's: vertices numbered in order of first
//! use by the triangles, bit-identical positions (`−0.0` ≡ `+0.0`) sharing
//! the first one's index, unused vertices dropped. It is cheaper here
//! because repeats are found by sorting the positions' hashes instead of
//! looking each position up in a hash table: the sort reads and writes
//! memory in order, where the table misses the cache (and, on this VM, the
//! TLB) once per vertex. On a 1e6-triangle PLY the weld's exact pass was
//! ≈ 14 % of a whole `kreisel inertia` run (`perf record`); a tagged
//! open-addressing table here, tried first, still spent 84 % of its time on
//! that one miss.
//!
//! Meshes that [`TriMesh::try_new`] would refuse (no triangles, a
//! non-finite vertex, an index out of range) are left as they are, so that
//! its error, with the vertex or triangle number of the file, is the one
//! reported.

use glam::DVec3;

use super::{Body, Source};
use crate::{InertiaError, TriMesh};

impl Source<'_> {
    /// A body of an indexed mesh as [`Source::body`] makes it, with exact
    /// repeats already shared when the mesh is valid (see the module notes).
    ///
    /// # Errors
    /// As [`Source::body`].
    pub(super) fn indexed_body(
        &self,
        name: String,
        vertices: Vec<DVec3>,
        mut triangles: Vec<[u32; 3]>,
    ) -> Result<Body, InertiaError> {
        // Merged bodies are welded (exact pass included) only as a whole.
        if self.options.merge {
            return self.body(name, vertices, triangles);
        }
        match shared_in_first_use_order(&vertices, &mut triangles) {
            Some(unique) => {
                let mesh =
                    TriMesh::try_new(unique, triangles).map_err(|e| self.in_body(&name, e))?;
                self.body_from_mesh(name, mesh.known_exact_unique())
            }
            None => self.body(name, vertices, triangles),
        }
    }
}

/// The vertices in order of first use, bit-identical ones shared, with the
/// triangles renumbered to them; `None` (triangles untouched) when
/// [`TriMesh::try_new`] would refuse the mesh or it has `u32::MAX` or more
/// vertices.
fn shared_in_first_use_order(vertices: &[DVec3], triangles: &mut [[u32; 3]]) -> Option<Vec<DVec3>> {
    let n = vertices.len();
    let valid = !triangles.is_empty()
        && n < u32::MAX as usize
        && vertices.iter().all(|v| v.is_finite())
        && triangles.iter().flatten().all(|&i| (i as usize) < n);
    if !valid {
        return None;
    }
    // Number the vertices in order of first use (the rank), as if all were
    // distinct.
    let mut rank = vec![u32::MAX; n];
    let mut used = Vec::new();
    for corner in triangles.iter_mut().flatten() {
        let old = *corner as usize;
        if rank[old] == u32::MAX {
            // Fewer than u32::MAX vertices: the rank fits below it.
            rank[old] = used.len() as u32;
            used.push(vertices[old]);
        }
        *corner = rank[old];
    }
    drop(rank);
    // Bit-identical positions have equal hashes: sorted by hash, they are
    // neighbours. A sort touches memory in order, where a hash table would
    // miss the cache once per vertex (≈ 5× slower at 1e6 vertices).
    let mut by_hash: Vec<(u64, u32)> = used
        .iter()
        .enumerate()
        .map(|(r, &v)| (hash(key(v)), r as u32))
        .collect();
    by_hash.sort_unstable();
    // Per rank, the rank of the first use of the same position.
    let mut first: Vec<u32> = Vec::new();
    for run in by_hash.chunk_by(|a, b| a.0 == b.0).filter(|r| r.len() > 1) {
        if first.is_empty() {
            first = (0..used.len() as u32).collect();
        }
        // Ascending ranks within the run: the first of each position leads.
        for (i, &(_, r)) in run.iter().enumerate() {
            let k = key(used[r as usize]);
            if let Some(&(_, lead)) = run[..i].iter().find(|&&(_, e)| key(used[e as usize]) == k) {
                first[r as usize] = first[lead as usize];
            }
        }
    }
    drop(by_hash);
    if first.is_empty() {
        return Some(used);
    }
    // Number the first uses of each position in rank order.
    let mut unique = Vec::new();
    let mut new_index = vec![0; used.len()];
    for (r, &f) in first.iter().enumerate() {
        new_index[r] = if f as usize == r {
            unique.push(used[r]);
            (unique.len() - 1) as u32
        } else {
            // f < r: numbered already.
            new_index[f as usize]
        };
    }
    for corner in triangles.iter_mut().flatten() {
        *corner = new_index[*corner as usize];
    }
    Some(unique)
}

/// The bits of a position, `−0.0` as `+0.0`.
#[inline]
fn key(v: DVec3) -> [u64; 3] {
    (v + DVec3::ZERO).to_array().map(f64::to_bits)
}

/// A 64-bit mix of the key (multiply–xorshift).
#[inline]
fn hash([x, y, z]: [u64; 3]) -> u64 {
    const M: u64 = 0x9E37_79B9_7F4A_7C15;
    let h = (x.wrapping_mul(M) ^ y.rotate_left(21)).wrapping_mul(M) ^ z.rotate_left(43);
    let h = h.wrapping_mul(0xD6E8_FEB8_6659_FD93);
    h ^ (h >> 29)
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;
    use crate::Weld;

    /// The weld's own exact pass on the same mesh.
    fn reference(vertices: &[DVec3], triangles: &[[u32; 3]]) -> TriMesh {
        TriMesh::new(vertices.to_vec(), triangles.to_vec())
            .welded(Weld::Exact)
            .unwrap()
            .0
    }

    #[test]
    fn shares_repeats_and_signed_zeros_in_first_use_order() {
        let v = [
            DVec3::new(9.0, 9.0, 9.0), // unused
            DVec3::new(0.0, 1.0, 2.0),
            DVec3::new(-0.0, 1.0, 2.0),
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(0.0, 1.0, 2.0 + f64::EPSILON * 2.0),
            DVec3::new(1.0, 0.0, 0.0),
        ];
        let mut t = vec![[3, 2, 4], [1, 5, 4]];
        let expected = reference(&v, &t);
        let unique = shared_in_first_use_order(&v, &mut t).unwrap();
        assert_eq!(t, [[0, 1, 2], [1, 0, 2]]);
        assert_eq!(
            (unique.as_slice(), t.as_slice()),
            (expected.vertices(), expected.triangles())
        );
        // The first occurrence's sign is kept.
        assert!(unique[1].x.is_sign_negative());
    }

    #[test]
    fn meshes_try_new_refuses_are_left_alone() {
        let v = [DVec3::ZERO, DVec3::X, DVec3::new(f64::NAN, 0.0, 0.0)];
        let mut t = vec![[0, 1, 0]];
        assert!(shared_in_first_use_order(&v, &mut t).is_none());
        let mut t = vec![[0, 1, 3]];
        assert!(shared_in_first_use_order(&v[..2], &mut t).is_none());
        assert_eq!(t, [[0, 1, 3]]);
        assert!(shared_in_first_use_order(&v[..2], &mut []).is_none());
    }

    proptest! {
        #[test]
        fn equals_the_welds_exact_pass(
            coords in prop::collection::vec((0..4i8, 0..3i8, -1..1i8), 1..60),
            corners in prop::collection::vec(0..200u32, 3..90),
        ) {
            let v: Vec<DVec3> = coords
                .iter()
                .map(|&(x, y, z)| {
                    let z = if z < 0 { -0.0 } else { 0.0 };
                    DVec3::new(f64::from(x), f64::from(y) * 0.5, z)
                })
                .collect();
            let mut t: Vec<[u32; 3]> = corners
                .chunks_exact(3)
                .map(|c| [c[0], c[1], c[2]].map(|i| i % v.len() as u32))
                .collect();
            let expected = reference(&v, &t);
            let unique = shared_in_first_use_order(&v, &mut t).unwrap();
            let bits = |v: &[DVec3]| -> Vec<[u64; 3]> {
                v.iter().map(|p| p.to_array().map(f64::to_bits)).collect()
            };
            prop_assert_eq!(bits(&unique), bits(expected.vertices()));
            prop_assert_eq!(t.as_slice(), expected.triangles());
        }
    }
}
