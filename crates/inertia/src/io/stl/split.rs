//! Binary STL records merged into shared vertices on two threads.
//!
//! The key space is split in two halves by a bit of the key ([`half`]);
//! each half has its own [`VertexTable`] on its own thread, which sees every
//! record of a chunk but looks up only the corners of its half, numbering
//! its vertices in the order their first corners come. The calling thread
//! reads the chunks and joins the two numberings in record order: a local
//! index met for the first time is the next global one. So the global
//! numbering is the order of first use, the first corner read gives each
//! vertex its coordinates, and the result is exactly that of one table
//! ([`super::Soup`]), while the table lookups (which wait on main memory) run
//! on both cores and each table is half the size.
//!
//! Memory: the two tables together are the size of one; the join keeps one
//! `u32` per distinct vertex per half; chunks in flight are a few hundred kB.

use std::sync::Arc;
use std::sync::mpsc::{Receiver, SyncSender, sync_channel};

use glam::DVec3;

use super::super::vertex_index;
use super::super::vertex_table::{VertexTable, half, point};
use super::{RECORD, corner, non_finite};

/// Worker 0's mark for a corner of the other half.
const OTHER: u32 = u32::MAX;

/// Why the records could not be read.
pub(super) enum SplitError {
    /// The reader failed.
    Io(std::io::Error),
    /// A reason for a parse error (a non-finite coordinate, too many vertices).
    Bad(String),
}

/// What a worker made of one chunk.
struct Part {
    /// Its half's local vertex index of each corner it looked up, in record
    /// order; worker 0 also lists the other corners, as [`OTHER`].
    ids: Vec<u32>,
    /// The `f32` bits of the vertices it met for the first time, in order.
    new: Vec<[u32; 3]>,
}

/// Reads `count` records, `chunk` at a time, through `fill` (which fills the
/// whole buffer it is given), into distinct vertices in order of first use
/// and the triangles indexing them.
///
/// # Errors
/// The reader's error, or the first non-finite corner (as
/// `triangle t, corner k has a non-finite coordinate …`), or more distinct
/// vertices than `u32` indices.
pub(super) fn merge_records(
    count: usize,
    chunk: usize,
    mut fill: impl FnMut(&mut [u8]) -> std::io::Result<()>,
) -> Result<(Vec<DVec3>, Vec<[u32; 3]>), SplitError> {
    let chunk = chunk.max(1);
    std::thread::scope(|scope| {
        let mut to = Vec::new();
        let mut back = Vec::new();
        for mine in 0..2 {
            let (chunks_tx, chunks_rx) = sync_channel(2);
            let (parts_tx, parts_rx) = sync_channel(2);
            // A closed mesh has about half as many vertices as triangles.
            scope.spawn(move || work(mine, count / 4, &chunks_rx, &parts_tx));
            to.push(chunks_tx);
            back.push(parts_rx);
        }
        let mut join = Join {
            local_to_global: [Vec::new(), Vec::new()],
            vertices: Vec::with_capacity(count / 2),
            triangles: Vec::with_capacity(count),
        };
        let mut in_flight = 0;
        let mut done = 0;
        while done < count {
            let take = chunk.min(count - done);
            let mut buffer = vec![0; take * RECORD];
            fill(&mut buffer).map_err(SplitError::Io)?;
            let (records, _) = buffer.as_chunks::<RECORD>();
            non_finite(records, done).map_err(SplitError::Bad)?;
            let shared = Arc::new(buffer);
            for tx in &to {
                tx.send(Arc::clone(&shared)).map_err(|_| stopped())?;
            }
            done += take;
            in_flight += 1;
            // Keep one chunk in flight while the previous one is joined.
            if in_flight > 1 {
                join.receive(&back)?;
                in_flight -= 1;
            }
        }
        drop(to);
        for _ in 0..in_flight {
            join.receive(&back)?;
        }
        Ok((join.vertices, join.triangles))
    })
}

/// A worker that stopped early (it cannot: it stops only when the chunks end).
fn stopped() -> SplitError {
    SplitError::Bad("internal error: a vertex worker stopped".to_owned())
}

/// Worker `mine`: looks up the corners of its half of every chunk.
fn work(
    mine: usize,
    expected: usize,
    chunks: &Receiver<Arc<Vec<u8>>>,
    parts: &SyncSender<Result<Part, String>>,
) {
    let mut table = VertexTable::with_capacity(expected);
    while let Ok(bytes) = chunks.recv() {
        let (records, _) = bytes.as_chunks::<RECORD>();
        let before = table.len();
        let mut ids = Vec::with_capacity(if mine == 0 { 3 } else { 2 } * records.len());
        let looked_up = records.iter().try_for_each(|record| {
            for k in 0..3 {
                let xyz = corner(record, k);
                if half(xyz) == mine {
                    ids.push(table.index(xyz)?);
                } else if mine == 0 {
                    ids.push(OTHER);
                }
            }
            Ok(())
        });
        drop(bytes);
        let part = looked_up.map(|()| Part {
            ids,
            new: table.bits_from(before).to_vec(),
        });
        if parts.send(part).is_err() {
            return;
        }
    }
}

/// The two halves' numberings joined into one.
struct Join {
    /// The global index of each local vertex, per half.
    local_to_global: [Vec<u32>; 2],
    vertices: Vec<DVec3>,
    triangles: Vec<[u32; 3]>,
}

impl Join {
    /// Joins the next chunk's parts from both workers.
    fn receive(&mut self, back: &[Receiver<Result<Part, String>>]) -> Result<(), SplitError> {
        let part = |half: usize| match back[half].recv() {
            Ok(part) => part.map_err(SplitError::Bad),
            Err(_) => Err(stopped()),
        };
        let (zero, one) = (part(0)?, part(1)?);
        self.add(zero, one).map_err(SplitError::Bad)
    }

    /// Adds the triangles of one chunk.
    fn add(&mut self, zero: Part, one: Part) -> Result<(), String> {
        let mut new = [zero.new.into_iter(), one.new.into_iter()];
        let mut ones = one.ids.into_iter();
        let missing = || "internal error: vertex workers disagree".to_owned();
        for three in zero.ids.chunks_exact(3) {
            let mut triangle = [0; 3];
            for (global, &id) in triangle.iter_mut().zip(three) {
                let (half, local) = if id == OTHER {
                    (1, ones.next().ok_or_else(missing)?)
                } else {
                    (0, id)
                };
                let map = &mut self.local_to_global[half];
                *global = match map.get(local as usize) {
                    Some(&g) => g,
                    None => {
                        // Local indices are numbered in record order, so
                        // an unseen one is the next.
                        let bits = new[half].next().ok_or_else(missing)?;
                        let g = vertex_index(self.vertices.len())?;
                        if g == u32::MAX {
                            return Err(format!("more than {} distinct vertices", u32::MAX - 1));
                        }
                        map.push(g);
                        self.vertices.push(point(bits));
                        g
                    }
                };
            }
            self.triangles.push(triangle);
        }
        Ok(())
    }
}
