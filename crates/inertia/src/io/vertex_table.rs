//! Exact-duplicate vertex merging while a triangle soup streams in.
//!
//! Binary STL stores every triangle's three corners as `f32` triples, so a
//! closed mesh repeats each vertex about six times. Copying every corner and
//! merging afterwards costs 72 bytes of `f64` corners per triangle plus a
//! `HashMap<[u64; 3], u32>` of 32-byte entries; here each corner is looked
//! up on arrival in an open-addressing table keyed by its `f32` bit pattern
//! (`−0.0` ≡ `+0.0`), and only the first occurrence becomes a vertex.
//!
//! Provisional numbering first: a table lookup of a new vertex is a cache
//! and TLB miss at a random place (60 % of the load's time at 10⁶
//! triangles, 500,000 of them), while a small cache of recently used keys
//! finds ~99 % of the repeats of a file written in surface order. So at
//! first only that cache is kept; a key it misses gets a new index even if
//! it was seen long ago, and those few repeats (each after its first, all
//! in order of first use) are left to the weld's tolerance pass, whose sort
//! puts them side by side anyway. When misses pile up (a file without
//! locality) [`VertexTable::settle`] builds the table and renumbers, as if
//! it had been there from the start.
//!
//! Memory: 8 bytes per slot (32 bits of the key's hash beside the vertex
//! index; the whole key is compared, in the vertex list, only when the
//! hash bits match), at most half the slots full, and the vertices kept as
//! their 12 bytes of `f32` bits until the load ends: ≤ 28 bytes per
//! distinct vertex, about 14 per triangle of a closed mesh. (16-byte slots
//! holding the whole key cost a 16 MB table at 10⁶ triangles; the table
//! lookups of new vertices are misses of cache and TLB, so halving it
//! measured 188 → 179 ns per triangle for the whole load.) Hand-written
//! rather than a `HashMap` for that layout and a multiply-xorshift hash of
//! the key words (SipHash costs more than the probe).

use glam::DVec3;

use super::vertex_index;

/// An empty slot's index.
const EMPTY: u32 = u32::MAX;

/// One table slot: 32 bits of the key's hash and the vertex index.
#[derive(Clone, Copy)]
struct Slot {
    tag: u32,
    index: u32,
}

/// One entry of the recent-vertex cache: the whole key and its index.
#[derive(Clone, Copy)]
struct Recent {
    key: [u32; 3],
    index: u32,
}

/// Entries of the recent-vertex cache (256 kB, within a core's L2).
const RECENT: usize = 1 << 14;

/// Vertices seen so far and the table that finds them.
pub(super) struct VertexTable {
    /// A direct-mapped cache of recently used keys in front of `slots`:
    /// a triangle's corners were mostly seen a few triangles before, and a
    /// hit here costs no trip to main memory.
    recent: Vec<Recent>,
    slots: Vec<Slot>,
    /// `slots.len() − 1` (the length is a power of two).
    mask: usize,
    /// The `f32` bits of each vertex as first read.
    vertices: Vec<[u32; 3]>,
    /// No table yet (`slots` empty): a key the recent cache misses gets a
    /// new index even if it was seen before (see [`VertexTable::settle`]).
    provisional: bool,
}

/// The key of a point: its `f32` bits, `−0.0` as `+0.0`.
#[inline]
fn key_of(bits: [u32; 3]) -> [u32; 3] {
    bits.map(|b| if b == 0x8000_0000 { 0 } else { b })
}

/// A corner as read, with its key and hash, computed once.
#[derive(Clone, Copy)]
struct Corner {
    bits: [u32; 3],
    key: [u32; 3],
    hash: u64,
}

impl Corner {
    /// The corner with these `f32` coordinates.
    #[inline]
    fn new(xyz: [f32; 3]) -> Self {
        let bits = xyz.map(f32::to_bits);
        let key = key_of(bits);
        Self {
            bits,
            key,
            hash: hash(key),
        }
    }
}

/// The `f64` point of a vertex's `f32` bits (exact).
fn point(bits: [u32; 3]) -> DVec3 {
    DVec3::from_array(bits.map(|c| f64::from(f32::from_bits(c))))
}

impl VertexTable {
    /// A table sized for about `expected` distinct vertices (it grows as needed).
    pub(super) fn with_capacity(expected: usize) -> Self {
        let slots = (2 * expected.max(8)).next_power_of_two();
        Self {
            recent: vec![
                Recent {
                    key: [0; 3],
                    index: EMPTY
                };
                RECENT
            ],
            slots: Vec::new(),
            mask: slots - 1,
            vertices: Vec::with_capacity(expected),
            provisional: true,
        }
    }

    /// Whether keys missed by the recent cache still get new indices (the
    /// vertices may then hold exact repeats, each first in order of first
    /// use, all used).
    pub(super) fn is_provisional(&self) -> bool {
        self.provisional
    }

    /// Ends the provisional numbering: builds the table, merging exact
    /// repeats, and returns the new index of each provisional index (new
    /// indices in order of first use, as if the table had been there from
    /// the start).
    pub(super) fn settle(&mut self) -> Vec<u32> {
        let old = std::mem::take(&mut self.vertices);
        self.provisional = false;
        let slots = (2 * old.len().max(8)).next_power_of_two();
        self.slots = vec![Self::empty(); slots];
        self.mask = slots - 1;
        self.recent.fill(Recent {
            key: [0; 3],
            index: EMPTY,
        });
        // Fewer distinct vertices than provisional ones, which had indices.
        old.into_iter()
            .map(|bits| {
                self.index_of(Corner::new(bits.map(f32::from_bits)))
                    .unwrap_or(EMPTY)
            })
            .collect()
    }

    fn empty() -> Slot {
        Slot {
            tag: 0,
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
        self.index_of(Corner::new(xyz))
    }

    /// [`VertexTable::index`] of a corner whose hash is known.
    #[inline]
    fn index_of(&mut self, corner: Corner) -> Result<u32, String> {
        let Corner { bits, key, hash: h } = corner;
        let recent = (h >> 40) as usize & (RECENT - 1);
        let r = self.recent[recent];
        if r.key == key && r.index != EMPTY {
            return Ok(r.index);
        }
        if self.provisional {
            let index = Self::next_index(self.vertices.len())?;
            self.recent[recent] = Recent { key, index };
            self.vertices.push(bits);
            return Ok(index);
        }
        let tag = (h >> 32) as u32;
        let mut at = h as usize & self.mask;
        loop {
            let slot = self.slots[at];
            if slot.index == EMPTY {
                break;
            }
            if slot.tag == tag && key_of(self.vertices[slot.index as usize]) == key {
                self.recent[recent] = Recent {
                    key,
                    index: slot.index,
                };
                return Ok(slot.index);
            }
            at = (at + 1) & self.mask;
        }
        let index = Self::next_index(self.vertices.len())?;
        self.slots[at] = Slot { tag, index };
        self.recent[recent] = Recent { key, index };
        self.vertices.push(bits);
        if 2 * self.vertices.len() > self.slots.len() {
            self.grow();
        }
        Ok(index)
    }

    /// The index of a new vertex after `count` of them.
    fn next_index(count: usize) -> Result<u32, String> {
        let index = vertex_index(count)?;
        if index == EMPTY {
            return Err(format!("more than {} distinct vertices", EMPTY - 1));
        }
        Ok(index)
    }

    /// Doubles the table, reinserting every key.
    fn grow(&mut self) {
        self.slots = vec![Self::empty(); 2 * self.mask + 2];
        self.mask = self.slots.len() - 1;
        for (index, &bits) in self.vertices.iter().enumerate() {
            let h = hash(key_of(bits));
            let mut at = h as usize & self.mask;
            while self.slots[at].index != EMPTY {
                at = (at + 1) & self.mask;
            }
            // Fewer vertices than EMPTY, checked on insertion.
            self.slots[at] = Slot {
                tag: (h >> 32) as u32,
                index: index as u32,
            };
        }
    }

    /// How many distinct vertices there are so far.
    pub(super) fn len(&self) -> usize {
        self.vertices.len()
    }

    /// Appends the vertices of `later` (read after this table's, in order
    /// of first use) as provisional ones, which may repeat this table's;
    /// returns the index of the first. [`VertexTable::settle`] then merges
    /// the repeats as if one table had read everything.
    ///
    /// # Errors
    /// A reason when there would be more distinct vertices than `u32` indices.
    pub(super) fn append(&mut self, later: VertexTable) -> Result<u32, String> {
        let first = vertex_index(self.vertices.len())?;
        Self::next_index(self.vertices.len() + later.vertices.len())?;
        self.vertices.extend(later.vertices);
        self.provisional = true;
        self.slots = Vec::new();
        Ok(first)
    }

    /// The distinct vertices, in order of first appearance, after those of `out`.
    pub(super) fn append_vertices_to(self, out: &mut Vec<DVec3>) {
        drop(self.slots);
        drop(self.recent);
        out.extend(self.vertices.into_iter().map(point));
    }

    /// The distinct vertices, in order of first appearance.
    pub(super) fn into_vertices(self) -> Vec<DVec3> {
        drop(self.slots);
        drop(self.recent);
        self.vertices.into_iter().map(point).collect()
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
        assert!(table.settle().is_empty());
        assert!(!table.is_provisional());
        let point = |i: u32| [i as f32, (i % 7) as f32, -((i / 3) as f32)];
        for i in 0..10_000 {
            assert_eq!(table.index(point(i)).unwrap(), i);
        }
        for i in (0..10_000).rev() {
            assert_eq!(table.index(point(i)).unwrap(), i);
        }
        assert_eq!(table.into_vertices().len(), 10_000);
    }

    #[test]
    fn provisional_repeats_settle_into_first_use_numbering() {
        // 40,000 corners over 10,000 points in an order without locality:
        // the recent cache misses many repeats, which get new indices.
        let point = |i: u32| [i as f32, (i % 7) as f32, -((i / 3) as f32)];
        let order: Vec<u32> = (0..40_000u32).map(|k| (k * 7919) % 10_000).collect();
        let mut table = VertexTable::with_capacity(1);
        let provisional: Vec<u32> = order
            .iter()
            .map(|&i| table.index(point(i)).unwrap())
            .collect();
        assert!(table.is_provisional());
        assert!(table.len() > 10_000, "{}", table.len());
        let new = table.settle();
        let settled: Vec<u32> = provisional.iter().map(|&p| new[p as usize]).collect();
        // The numbering one table from the start gives.
        let mut reference = VertexTable::with_capacity(1);
        reference.settle();
        let expected: Vec<u32> = order
            .iter()
            .map(|&i| reference.index(point(i)).unwrap())
            .collect();
        assert_eq!(settled, expected);
        // After settling, repeats find their index.
        for &i in &order[..100] {
            assert_eq!(
                table.index(point(i)).unwrap(),
                reference.index(point(i)).unwrap()
            );
        }
        let bits = |v: Vec<DVec3>| -> Vec<[u64; 3]> {
            v.iter().map(|p| p.to_array().map(f64::to_bits)).collect()
        };
        assert_eq!(bits(table.into_vertices()), bits(reference.into_vertices()));
    }
}
