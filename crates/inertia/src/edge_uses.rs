//! Every undirected edge use of a triangle list, grouped by edge: the
//! adjacency the topology check ([`crate::mesh_check`]) is built on.
//!
//! A counting sort by the low vertex, then each (short) bucket sorted by
//! high vertex and triangle. A use is `(high << 32) | triangle`; 8 bytes
//! per use, 24 per triangle. Uses are unique (a triangle without a repeated
//! index has three different edges), so each bucket's sorted order is the
//! only one and the result does not depend on how the buckets were filled.
//!
//! On several threads ([`crate::parallel`]) each thread owns a contiguous
//! range of low vertices, hence a contiguous piece of the uses: it reads
//! every triangle (a sequential scan) and counts, then fills and sorts,
//! only the buckets of its range. No thread writes where another does, and
//! the result is the same on any number of threads.

use std::ops::Range;

use crate::parallel::{map_pieces, map_slices, ranges, threads_for};

/// The uses of each edge, bucket by low vertex.
pub(crate) struct EdgeUses {
    /// Where the uses whose low vertex is `v` start; `vertices + 1` entries.
    start: Vec<usize>,
    /// The uses, bucket by bucket.
    uses: Vec<u64>,
}

/// The low vertex of edge `k` (from `tri[k]` to `tri[k + 1]`).
#[inline]
fn low(tri: &[u32; 3], k: usize) -> usize {
    tri[k].min(tri[(k + 1) % 3]) as usize
}

/// The triangle of an edge use.
pub(crate) fn use_triangle(u: u64) -> usize {
    (u & 0xFFFF_FFFF) as usize
}

impl EdgeUses {
    /// Groups the edges of `triangles` (indices below `vertices`, none repeated
    /// within a triangle), on the machine's cores for large meshes.
    pub(crate) fn new(triangles: &[[u32; 3]], vertices: usize) -> Self {
        Self::new_on(triangles, vertices, threads_for(triangles.len()))
    }

    /// [`EdgeUses::new`] on at most `threads` threads.
    fn new_on(triangles: &[[u32; 3]], vertices: usize, threads: usize) -> Self {
        let mut start = vec![0usize; vertices + 1];
        // Counts: start[v] = uses whose low vertex is v, per vertex range.
        map_slices(&mut start[..vertices], threads, 1, |first, counts| {
            let end = first + counts.len();
            for tri in triangles {
                for k in 0..3 {
                    let l = low(tri, k);
                    if (first..end).contains(&l) {
                        counts[l - first] += 1;
                    }
                }
            }
        });
        // Exclusive prefix sums: bucket v is uses[start[v]..start[v + 1]].
        let mut sum = 0;
        for s in &mut start {
            let count = *s;
            *s = sum;
            sum += count;
        }
        let mut uses = vec![0u64; 3 * triangles.len()];
        let vertex_cuts = ranges(vertices, threads, 1);
        let use_cuts: Vec<Range<usize>> = vertex_cuts
            .iter()
            .map(|r| start[r.start]..start[r.end])
            .collect();
        map_pieces(&mut uses, &use_cuts, |p, piece| {
            let range = vertex_cuts[p].clone();
            let base = start[range.start];
            // Where the next use of each bucket of the range goes.
            let mut next: Vec<usize> = start[range.clone()].iter().map(|s| s - base).collect();
            for (t, tri) in triangles.iter().enumerate() {
                for k in 0..3 {
                    let l = low(tri, k);
                    if range.contains(&l) {
                        let high = tri[k].max(tri[(k + 1) % 3]);
                        let at = &mut next[l - range.start];
                        piece[*at] = (u64::from(high) << 32) | t as u64;
                        *at += 1;
                    }
                }
            }
            for w in start[range.start..=range.end].windows(2) {
                piece[w[0] - base..w[1] - base].sort_unstable();
            }
        });
        Self { start, uses }
    }

    /// Vertex ranges for visiting the edges on `threads` threads (about
    /// equal numbers of low vertices each).
    pub(crate) fn vertex_ranges(&self, threads: usize) -> Vec<Range<usize>> {
        ranges(self.start.len() - 1, threads, 1)
    }

    /// Calls `f(key, group)` for every edge in `(low, high)` order, with
    /// `key = (low << 32) | high` and the group's uses.
    pub(crate) fn for_each_edge(&self, f: impl FnMut(u64, &[u64])) {
        self.for_each_edge_in(0..self.start.len() - 1, f);
    }

    /// [`EdgeUses::for_each_edge`] for the edges whose low vertex is in `lows`.
    pub(crate) fn for_each_edge_in(&self, lows: Range<usize>, mut f: impl FnMut(u64, &[u64])) {
        let first = lows.start;
        for (i, w) in self.start[lows.start..=lows.end].windows(2).enumerate() {
            let low = (first + i) as u64;
            let bucket = &self.uses[w[0]..w[1]];
            for group in bucket.chunk_by(|x, y| x >> 32 == y >> 32) {
                f((low << 32) | (group[0] >> 32), group);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The edges of a closed grid of `n × n` quads on a torus.
    fn torus(n: u32) -> (Vec<[u32; 3]>, usize) {
        let at = |i: u32, j: u32| (i % n) * n + j % n;
        let mut tris = Vec::new();
        for i in 0..n {
            for j in 0..n {
                let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
                tris.push([a, b, c]);
                tris.push([a, c, d]);
            }
        }
        (tris, (n * n) as usize)
    }

    fn groups(uses: &EdgeUses) -> Vec<(u64, Vec<u64>)> {
        let mut out = Vec::new();
        uses.for_each_edge(|key, group| out.push((key, group.to_vec())));
        out
    }

    #[test]
    fn any_thread_count_groups_every_edge_alike() {
        let (tris, vertices) = torus(37);
        let one = EdgeUses::new_on(&tris, vertices, 1);
        let edges = groups(&one);
        // A closed torus: 3 edges per 2 triangles, each used twice.
        assert_eq!(edges.len(), 3 * tris.len() / 2);
        assert!(edges.iter().all(|(_, g)| g.len() == 2));
        assert!(edges.windows(2).all(|w| w[0].0 < w[1].0));
        for threads in [2, 3, 5, 64] {
            let many = EdgeUses::new_on(&tris, vertices, threads);
            assert_eq!((&many.start, &many.uses), (&one.start, &one.uses));
            let mut parts = Vec::new();
            for r in many.vertex_ranges(threads) {
                many.for_each_edge_in(r, |key, group| parts.push((key, group.to_vec())));
            }
            assert_eq!(parts, edges, "{threads}");
        }
    }

    #[test]
    fn unused_vertices_have_empty_buckets() {
        let uses = EdgeUses::new_on(&[[3, 1, 5]], 8, 3);
        assert_eq!(
            groups(&uses),
            vec![
                ((1 << 32) | 3, vec![3 << 32]),
                ((1 << 32) | 5, vec![5 << 32]),
                ((3 << 32) | 5, vec![5 << 32]),
            ]
        );
    }
}
