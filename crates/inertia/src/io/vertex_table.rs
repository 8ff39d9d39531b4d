//! Exact-duplicate vertex merging while a triangle soup streams in.
//!
//! Binary STL stores every triangle's three corners as `f32` triples, so a
//! closed mesh repeats each vertex about six times. Copying every corner and
//! merging afterwards costs 72 bytes of `f64` corners per triangle plus a
//! `HashMap<[u64; 3], u32>` of 32-byte entries; here each corner is looked
//! up on arrival in an open-addressing table keyed by its `f32` bit pattern
//! (`−0.0` ≡ `+0.0`), and only the first occurrence becomes a vertex.
//!
//! Memory: 16 bytes per slot (the 12-byte key beside its `u32` index, so a
//! probe touches one cache line), at most half the slots full: ≤ 32 bytes
//! per distinct vertex, about 16 per triangle of a closed mesh, freed when
//! the load ends. Hand-written rather than a `HashMap` for that layout and a
//! multiply-xorshift hash of the key words (SipHash costs more than the
//! probe).

use glam::DVec3;

use super::vertex_index;

/// An empty slot's index.
const EMPTY: u32 = u32::MAX;

/// One slot: the `f32` bit pattern of a vertex and its index.
#[derive(Clone, Copy)]
struct Slot {
    key: [u32; 3],
    index: u32,
}

/// Entries of the recent-vertex cache (256 kB, within a core's L2).
const RECENT: usize = 1 << 14;

/// Distinct vertices seen so far and the table that finds them.
pub(super) struct VertexTable {
    /// A direct-mapped cache of recently used keys in front of `slots`:
    /// a triangle's corners were mostly seen a few triangles before, and a
    /// hit here costs no trip to main memory.
    recent: Vec<Slot>,
    slots: Vec<Slot>,
    /// `slots.len() − 1` (the length is a power of two).
    mask: usize,
    vertices: Vec<DVec3>,
}

impl VertexTable {
    /// A table sized for about `expected` distinct vertices (it grows as needed).
    pub(super) fn with_capacity(expected: usize) -> Self {
        let slots = (2 * expected.max(8)).next_power_of_two();
        Self {
            recent: vec![Self::empty(); RECENT],
            slots: vec![Self::empty(); slots],
            mask: slots - 1,
            vertices: Vec::with_capacity(expected),
        }
    }

    fn empty() -> Slot {
        Slot {
            key: [0; 3],
            index: EMPTY,
        }
    }

    /// The index of the vertex with these `f32` coordinates, adding it when
    /// it is new.
    ///
    /// # Errors
    /// A reason when there would be more distinct vertices than `u32` indices.
    #[inline]
    pub(super) fn index(&mut self, xyz: [f32; 3]) -> Result<u32, String> {
        // −0.0 and +0.0 are the same point.
        let key = xyz.map(|c| if c == 0.0 { 0 } else { c.to_bits() });
        let h = hash(key);
        let recent = (h >> 40) as usize & (RECENT - 1);
        if self.recent[recent].key == key && self.recent[recent].index != EMPTY {
            return Ok(self.recent[recent].index);
        }
        let mut at = h as usize & self.mask;
        loop {
            let slot = self.slots[at];
            if slot.index == EMPTY {
                break;
            }
            if slot.key == key {
                self.recent[recent] = slot;
                return Ok(slot.index);
            }
            at = (at + 1) & self.mask;
        }
        let index = vertex_index(self.vertices.len())?;
        if index == EMPTY {
            return Err(format!("more than {} distinct vertices", EMPTY - 1));
        }
        self.slots[at] = Slot { key, index };
        self.recent[recent] = Slot { key, index };
        self.vertices.push(DVec3::new(
            f64::from(xyz[0]),
            f64::from(xyz[1]),
            f64::from(xyz[2]),
        ));
        if 2 * self.vertices.len() > self.slots.len() {
            self.grow();
        }
        Ok(index)
    }

    /// Doubles the table, reinserting every key.
    fn grow(&mut self) {
        let old = std::mem::replace(&mut self.slots, vec![Self::empty(); 2 * self.mask + 2]);
        self.mask = self.slots.len() - 1;
        for slot in old.into_iter().filter(|s| s.index != EMPTY) {
            let mut at = hash(slot.key) as usize & self.mask;
            while self.slots[at].index != EMPTY {
                at = (at + 1) & self.mask;
            }
            self.slots[at] = slot;
        }
    }

    /// The distinct vertices, in order of first appearance.
    pub(super) fn into_vertices(self) -> Vec<DVec3> {
        self.vertices
    }
}

/// A 64-bit mix of the three key words (multiply–xorshift): the low bits
/// pick the table slot, bits 40 and up the recent-cache entry.
#[inline]
fn hash([x, y, z]: [u32; 3]) -> u64 {
    let a = (u64::from(x) | (u64::from(y) << 32)).wrapping_mul(0x9E37_79B9_7F4A_7C15);
    let b = u64::from(z).wrapping_mul(0xC2B2_AE3D_27D4_EB4F);
    let mut h = a ^ b.rotate_left(29);
    h ^= h >> 32;
    h = h.wrapping_mul(0xD6E8_FEB8_6659_FD93);
    h ^ (h >> 32)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn merges_exact_repeats_and_signed_zeros_only() {
        let mut table = VertexTable::with_capacity(1);
        let points = [
            [0.0, 1.0, 2.0],
            [-0.0, 1.0, 2.0],
            [0.0, 1.0, f32::from_bits(2.0f32.to_bits() + 1)],
            [0.0, 1.0, 2.0],
        ];
        let indices: Vec<u32> = points.iter().map(|&p| table.index(p).unwrap()).collect();
        assert_eq!(indices, [0, 0, 1, 0]);
        let vertices = table.into_vertices();
        assert_eq!(vertices.len(), 2);
        assert_eq!(
            vertices[1].z,
            f64::from(2.0f32) + f64::from(f32::EPSILON) * 2.0
        );
    }

    #[test]
    fn grows_past_its_initial_size_and_finds_every_vertex_again() {
        let mut table = VertexTable::with_capacity(1);
        let point = |i: u32| [i as f32, (i % 7) as f32, -((i / 3) as f32)];
        for i in 0..10_000 {
            assert_eq!(table.index(point(i)).unwrap(), i);
        }
        for i in (0..10_000).rev() {
            assert_eq!(table.index(point(i)).unwrap(), i);
        }
        assert_eq!(table.into_vertices().len(), 10_000);
    }
}
