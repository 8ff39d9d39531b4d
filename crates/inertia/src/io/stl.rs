//! STL, binary and ASCII, parsed here rather than by `stl_io`.
//!
//! Binary: an 80-byte header, a little-endian `u32` triangle count `n`, then
//! `n` records of 50 bytes (normal, three vertices as `f32`, two attribute
//! bytes). The file length must be exactly `84 + 50·n`: a count that
//! disagrees with the length (a "lying header", a truncated file, trailing
//! bytes) is an error, so nothing is ever allocated from the count alone.
//! Normals and attribute bytes are ignored; winding defines orientation.
//! A binary file on disk is streamed in chunks of records, never held whole,
//! and each corner is merged with its repeats as it arrives
//! ([`VertexTable`]), so memory is the shared vertices and the index
//! triangles (24 bytes per triangle for a closed mesh) plus the table while
//! loading, instead of the file, 72 bytes of corners per triangle and a
//! merge afterwards. While the file shows locality (a corner's repeats come
//! a few triangles apart, as in files written in surface order) the table
//! only keeps its cache of recent vertices, and the few repeats it misses
//! are merged by the weld's tolerance pass; a file without locality settles
//! it into a full hash table (see [`SETTLE`]). From
//! [`crate::parallel::PARALLEL_MIN`] triangles the records are read in
//! contiguous parts on the machine's cores, each part through its own file
//! handle into its own table, and the parts joined in order (see
//! [`read_parts`]): the welded mesh is the same on any number of threads.
//!
//! ASCII: `solid [name]`, facets of `facet normal …`, `outer loop`, three
//! (or more, fan-triangulated) `vertex x y z` lines, `endloop`, `endfacet`,
//! and `endsolid`. Keywords are case-insensitive, coordinates are parsed as
//! `f64` (exact repeats sharing one vertex as they are read), and several
//! solids in one file become several bodies.
//!
//! Which one: a file whose length matches its binary count is binary, unless
//! it starts with `solid` and is entirely printable ASCII text; otherwise a
//! file starting with `solid` is ASCII. (`stl_io` was not used: it decides by
//! the `solid ` prefix alone, so binary files whose header starts with
//! `solid` fail, it rejects a bare `solid` line, reads ASCII as `f32` and
//! drops the solid's name.)

use std::fs::File;
use std::io::{Read, Seek, SeekFrom};

use glam::DVec3;

use super::vertex_table::VertexTable;
use super::{Body, Source, vertex_index};
use crate::parallel::{map_ranges, threads_for};
use crate::weld::ExactDedup;
use crate::{InertiaError, TriMesh};

/// Bytes before the first binary triangle record.
const HEADER: usize = 84;
/// Bytes per binary triangle record.
const RECORD: usize = 50;

/// Loads the solids of an STL file.
pub(super) fn load(bytes: &[u8], src: &Source<'_>) -> Result<Vec<Body>, InertiaError> {
    let count = binary_count(bytes);
    let exact = count.is_some_and(|n| binary_len(n) == bytes.len() as u64);
    let solid = starts_with_solid(bytes);
    if exact && !(solid && is_text(bytes)) {
        let parsed =
            parse_binary(bytes, threads_for(bytes.len() / RECORD)).map_err(|r| src.error(r))?;
        return binary_body(src, parsed);
    }
    if solid {
        let solids = parse_ascii(bytes).map_err(|reason| match count {
            Some(n) if !is_text(bytes) => src.error(format!(
                "{reason} (read as binary instead, its header declares {n} triangles, \
                 which need {} bytes, but the file has {})",
                binary_len(n),
                bytes.len()
            )),
            _ => src.error(reason),
        })?;
        return solids
            .into_iter()
            .map(|s| {
                let name = if s.name.is_empty() {
                    src.stem().to_owned()
                } else {
                    s.name
                };
                src.body(name, s.vertices.into_vertices(), s.triangles)
            })
            .collect();
    }
    Err(src.error(match count {
        _ if bytes.is_empty() => "the file is empty".to_owned(),
        Some(n) => format!(
            "binary STL header declares {n} triangles, which need {} bytes, but the file has {} \
             (and it does not start with 'solid', so it is not ASCII STL)",
            binary_len(n),
            bytes.len()
        ),
        None => format!(
            "{} bytes are too few for a binary STL (at least {HEADER}) and the file does not \
             start with 'solid', so it is not ASCII STL",
            bytes.len()
        ),
    }))
}

/// Records read at a time when a binary file is streamed (≈ 400 kB).
const CHUNK: usize = 8192;

/// Loads the solids of an STL file on disk.
///
/// A binary file is streamed in chunks of records straight into the vertex
/// table and triangle list, so the file is never held whole; anything else
/// (ASCII, broken, or a start that cannot be told apart without the whole
/// file) is read whole and goes through [`load`], which decides exactly as
/// for bytes in memory.
pub(super) fn load_file(src: &Source<'_>) -> Result<Vec<Body>, InertiaError> {
    let io = |source| InertiaError::Io {
        path: src.path.to_path_buf(),
        source,
    };
    let mut file = File::open(src.path).map_err(io)?;
    let len = file.metadata().map_err(io)?.len();
    let mut head = Vec::with_capacity(HEADER);
    (&mut file)
        .take(HEADER as u64)
        .read_to_end(&mut head)
        .map_err(io)?;
    if let Some(n) = binary_count(&head).filter(|&n| binary_len(n) == len)
        && is_binary(&head, &mut file).map_err(io)?
    {
        drop(file);
        // Each part of the records is read through its own handle.
        let parsed = read_parts(n as usize, threads_for(n as usize), |records, soup| {
            let mut file = File::open(src.path).map_err(ReadError::Io)?;
            let offset = HEADER as u64 + RECORD as u64 * records.start as u64;
            file.seek(SeekFrom::Start(offset)).map_err(ReadError::Io)?;
            let mut buffer = vec![0; CHUNK.min(records.len()) * RECORD];
            let mut left = records.len();
            while left > 0 {
                let take = CHUNK.min(left);
                let chunk = &mut buffer[..take * RECORD];
                file.read_exact(chunk).map_err(ReadError::Io)?;
                soup.push(chunk.as_chunks::<RECORD>().0)
                    .map_err(ReadError::Bad)?;
                left -= take;
            }
            Ok(())
        });
        return match parsed {
            Ok(parsed) => binary_body(src, parsed),
            Err(ReadError::Io(e)) => Err(io(e)),
            Err(ReadError::Bad(reason)) => Err(src.error(reason)),
        };
    }
    let bytes = super::read_limited(src.path, super::MESH_FILE_LIMIT, "a mesh file").map_err(io)?;
    load(&bytes, src)
}

/// Whether a file of the exact binary length whose first bytes are `head`
/// is certainly binary: it does not start with `solid`, or a byte that is
/// not text follows. `false` also when the first bytes are too blank to
/// tell (then the whole file decides).
fn is_binary(head: &[u8], rest: &mut impl Read) -> std::io::Result<bool> {
    let start = head.iter().position(|b| !b.is_ascii_whitespace());
    if start.is_none_or(|i| i + 6 > head.len()) {
        return Ok(false);
    }
    if !starts_with_solid(head) || !is_text(head) {
        return Ok(true);
    }
    let mut buffer = vec![0; CHUNK * RECORD];
    loop {
        let got = rest.read(&mut buffer)?;
        if got == 0 {
            return Ok(false);
        }
        if !is_text(&buffer[..got]) {
            return Ok(true);
        }
    }
}

/// The triangle count of a binary header, if the file is long enough to have one.
fn binary_count(bytes: &[u8]) -> Option<u32> {
    let c = bytes.get(80..HEADER)?;
    Some(u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
}

/// The exact length of a binary STL with `n` triangles.
fn binary_len(n: u32) -> u64 {
    HEADER as u64 + RECORD as u64 * u64::from(n)
}

/// Whether the file starts (after blanks) with the keyword `solid`.
fn starts_with_solid(bytes: &[u8]) -> bool {
    let start = bytes.iter().position(|b| !b.is_ascii_whitespace());
    let rest = start.map_or(&[][..], |i| &bytes[i..]);
    rest.len() >= 5
        && rest[..5].eq_ignore_ascii_case(b"solid")
        && rest.get(5).is_none_or(u8::is_ascii_whitespace)
}

/// Whether every byte is printable ASCII or whitespace.
fn is_text(bytes: &[u8]) -> bool {
    bytes
        .iter()
        .all(|&b| b.is_ascii_graphic() || b.is_ascii_whitespace())
}

/// Reads a binary STL whose length has been checked to be `84 + 50·n`.
fn parse_binary(bytes: &[u8], threads: usize) -> Result<Parsed, String> {
    let (records, _) = bytes
        .get(HEADER..)
        .unwrap_or_default()
        .as_chunks::<RECORD>();
    read_parts(records.len(), threads, |part, soup| {
        for chunk in records[part].chunks(CHUNK) {
            soup.push(chunk).map_err(ReadError::Bad)?;
        }
        Ok(())
    })
    .map_err(|e| match e {
        ReadError::Bad(reason) => reason,
        // Nothing is read from a file here.
        ReadError::Io(e) => e.to_string(),
    })
}

/// Why the records could not be read: the file, or what it holds.
enum ReadError {
    Io(std::io::Error),
    Bad(String),
}

/// The shared vertices and triangles of binary records.
struct Parsed {
    vertices: Vec<DVec3>,
    triangles: Vec<[u32; 3]>,
    /// Free of exact repeats (else numbered in order of first use, repeats
    /// left to the weld).
    unique: bool,
}

/// Records `0..n` read in up to `threads` contiguous parts of whole chunks
/// at once, each by `read(records, soup)` into its own [`Soup`], then joined
/// in order: the vertices of part 2 after those of part 1, and so on. Each
/// part numbers its vertices in order of first use, so the joined list is
/// in order of first use too, with the exact repeats between parts left to
/// the weld's tolerance pass, which merges them as it merges a provisional
/// table's (so the welded mesh is the same on any number of threads).
fn read_parts(
    n: usize,
    threads: usize,
    read: impl Fn(std::ops::Range<usize>, &mut Soup) -> Result<(), ReadError> + Sync,
) -> Result<Parsed, ReadError> {
    let parts = map_ranges(n, threads, CHUNK, |records| {
        let mut soup = Soup::new(records.start, records.len());
        if records.start == 0 {
            // The first part's triangles become the whole list: room for
            // all (untouched memory costs nothing until the join writes it).
            soup.triangles.reserve_exact(n - records.len());
        }
        read(records, &mut soup).map(|()| soup)
    });
    // The first failure in file order is the one a single thread meets.
    let mut soups = parts.into_iter().collect::<Result<Vec<Soup>, _>>()?;
    if soups.len() == 1
        && let Some(soup) = soups.pop()
    {
        return Ok(Parsed {
            unique: !soup.table.is_provisional(),
            vertices: soup.table.into_vertices(),
            triangles: soup.triangles,
        });
    }
    let settled = soups.iter().any(|s| !s.table.is_provisional());
    let mut parts = soups.into_iter();
    if settled && let Some(first) = parts.next() {
        // A file without locality: its parts' tables were settled, and the
        // parts share most of their vertices. One table over all of them,
        // settled, gives the numbering of one table from the start.
        let Soup {
            mut table,
            mut triangles,
            ..
        } = first;
        for soup in parts {
            let offset = table.append(soup.table).map_err(ReadError::Bad)?;
            triangles.extend(soup.triangles.iter().map(|t| t.map(|i| i + offset)));
        }
        let new = table.settle();
        for t in &mut triangles {
            *t = t.map(|i| new[i as usize]);
        }
        return Ok(Parsed {
            vertices: table.into_vertices(),
            triangles,
            unique: true,
        });
    }
    let soups: Vec<Soup> = parts.collect();
    let total: usize = soups.iter().map(|s| s.table.len()).sum();
    vertex_index(total).map_err(ReadError::Bad)?;
    let mut vertices = Vec::with_capacity(total);
    let mut triangles = Vec::new();
    for soup in soups {
        // Fewer than u32::MAX vertices in all (checked above).
        let offset = vertices.len() as u32;
        if offset == 0 {
            triangles = soup.triangles;
        } else {
            triangles.extend(soup.triangles.iter().map(|t| t.map(|i| i + offset)));
        }
        soup.table.append_vertices_to(&mut vertices);
    }
    Ok(Parsed {
        vertices,
        triangles,
        unique: false,
    })
}

/// The one body of a binary file, as [`Source::body`] makes it, but marked
/// with what the [`VertexTable`] guarantees: vertices numbered in order of
/// first use, all used, and free of exact repeats once the table is
/// settled (and read as one part); the weld then skips its exact pass (and
/// merges the repeats of a provisional numbering in its tolerance pass).
fn binary_body(src: &Source<'_>, parsed: Parsed) -> Result<Vec<Body>, InertiaError> {
    let Parsed {
        vertices,
        triangles,
        unique,
    } = parsed;
    let name = src.stem().to_owned();
    let mesh = TriMesh::try_new(vertices, triangles).map_err(|e| src.in_body(&name, e))?;
    let mesh = if unique {
        mesh.known_exact_unique()
    } else {
        mesh.known_first_use()
    };
    Ok(vec![src.body_from_mesh(name, mesh)?])
}

/// Binary triangle records being read into shared vertices and triangles.
struct Soup {
    /// The file's index of the first record.
    first: usize,
    table: VertexTable,
    triangles: Vec<[u32; 3]>,
}

impl Soup {
    /// Room for `count` triangles (a count checked against the file length)
    /// from record `first` on.
    fn new(first: usize, count: usize) -> Self {
        Self {
            first,
            // A closed mesh has about half as many vertices as triangles.
            table: VertexTable::with_capacity(count / 2),
            triangles: Vec::with_capacity(count),
        }
    }

    /// Adds the triangles of these records, merging repeated vertices;
    /// settles the table when the provisional vertices outnumber the
    /// triangles by [`SETTLE`] (a file without locality, whose repeats the
    /// recent cache misses).
    fn push(&mut self, records: &[[u8; RECORD]]) -> Result<(), String> {
        non_finite(records, self.first + self.triangles.len())?;
        for record in records {
            let mut triangle = [0; 3];
            for (k, index) in triangle.iter_mut().enumerate() {
                *index = self.table.index(corner(record, k))?;
            }
            self.triangles.push(triangle);
        }
        let (num, den) = SETTLE;
        if self.table.is_provisional() && den * self.table.len() > num * self.triangles.len() {
            let new = self.table.settle();
            for t in &mut self.triangles {
                *t = t.map(|i| new[i as usize]);
            }
        }
        Ok(())
    }
}

/// Provisional vertices per triangle (`3/2`) beyond which the table is
/// settled: a closed mesh read in surface order has about ½ vertex per
/// triangle and the recent cache finds ~99 % of the repeats (10⁶-triangle
/// torus: 530,669 provisional vertices for 500,000 distinct ones), while
/// shuffled triangles give ~3.
const SETTLE: (usize, usize) = (3, 2);

/// Corner `k` (0, 1, 2) of a binary triangle record.
#[inline]
fn corner(record: &[u8; RECORD], k: usize) -> [f32; 3] {
    let at = |i: usize| {
        let o = 12 + 12 * k + 4 * i;
        f32::from_le_bytes([record[o], record[o + 1], record[o + 2], record[o + 3]])
    };
    [at(0), at(1), at(2)]
}

/// The first corner with a non-finite coordinate, as a reason naming it
/// (`first` is the index of the first record).
fn non_finite(records: &[[u8; RECORD]], first: usize) -> Result<(), String> {
    for (t, record) in records.iter().enumerate() {
        for k in 0..3 {
            let xyz = corner(record, k);
            if !xyz.iter().all(|c| c.is_finite()) {
                let v = DVec3::from_array(xyz.map(f64::from));
                return Err(format!(
                    "triangle {}, corner {k} has a non-finite coordinate {v}",
                    first + t
                ));
            }
        }
    }
    Ok(())
}

/// One solid being read: exact repeats of a vertex share one index as they
/// are read (as binary records do through [`VertexTable`]).
struct Solid {
    name: String,
    vertices: ExactDedup,
    /// Corners read so far (at least the distinct vertices).
    corners: usize,
    /// The current facet's vertex indices.
    facet: Vec<u32>,
    triangles: Vec<[u32; 3]>,
}

/// Reads the solids of an ASCII STL.
fn parse_ascii(bytes: &[u8]) -> Result<Vec<Solid>, String> {
    let text = std::str::from_utf8(bytes).map_err(|e| {
        format!(
            "ASCII STL is not valid text (invalid UTF-8 at byte {})",
            e.valid_up_to()
        )
    })?;
    let mut lines = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty());
    let mut solids = Vec::new();
    while let Some((n, line)) = lines.next() {
        let (keyword, rest) = split_keyword(line);
        if !keyword.eq_ignore_ascii_case("solid") {
            return Err(format!("line {n}: expected 'solid', found '{line}'"));
        }
        let mut solid = Solid {
            name: rest.to_owned(),
            vertices: ExactDedup::with_capacity(0),
            corners: 0,
            facet: Vec::new(),
            triangles: Vec::new(),
        };
        while read_facet(&mut lines, &mut solid)? {}
        solids.push(solid);
    }
    Ok(solids)
}

/// Reads one facet into `solid`; `false` at the solid's `endsolid`.
fn read_facet<'t>(
    lines: &mut impl Iterator<Item = (usize, &'t str)>,
    solid: &mut Solid,
) -> Result<bool, String> {
    let mut next = |expected: &str| {
        lines.next().ok_or_else(|| {
            format!("unexpected end of file: expected {expected} (the file may be truncated)")
        })
    };
    let (n, line) = next("'facet' or 'endsolid'")?;
    let (keyword, _) = split_keyword(line);
    if keyword.eq_ignore_ascii_case("endsolid") {
        return Ok(false);
    }
    if !keyword.eq_ignore_ascii_case("facet") {
        return Err(format!(
            "line {n}: expected 'facet' or 'endsolid', found '{line}'"
        ));
    }
    let (n, line) = next("'outer loop'")?;
    let mut words = line.split_whitespace();
    let outer = words
        .next()
        .is_some_and(|w| w.eq_ignore_ascii_case("outer"));
    let looped = words.next().is_some_and(|w| w.eq_ignore_ascii_case("loop"));
    if !(outer && looped && words.next().is_none()) {
        return Err(format!("line {n}: expected 'outer loop', found '{line}'"));
    }
    solid.facet.clear();
    let end = loop {
        let (n, line) = next("'vertex' or 'endloop'")?;
        let (keyword, rest) = split_keyword(line);
        if keyword.eq_ignore_ascii_case("endloop") {
            break n;
        }
        if !keyword.eq_ignore_ascii_case("vertex") {
            return Err(format!(
                "line {n}: expected 'vertex x y z' or 'endloop', found '{line}'"
            ));
        }
        let v = parse_vertex(rest).map_err(|r| format!("line {n}: {r}"))?;
        // Distinct vertices never outnumber the corners read.
        vertex_index(solid.corners)?;
        solid.corners += 1;
        solid.facet.push(solid.vertices.insert(v));
    };
    let corners = solid.facet.len();
    if corners < 3 {
        return Err(format!(
            "line {end}: facet has {corners} vertices, at least 3 are needed"
        ));
    }
    let a = solid.facet[0];
    for w in solid.facet[1..].windows(2) {
        solid.triangles.push([a, w[0], w[1]]);
    }
    let (n, line) = next("'endfacet'")?;
    if !split_keyword(line).0.eq_ignore_ascii_case("endfacet") {
        return Err(format!("line {n}: expected 'endfacet', found '{line}'"));
    }
    Ok(true)
}

/// Splits a trimmed line into its first word and the trimmed rest.
fn split_keyword(line: &str) -> (&str, &str) {
    match line.split_once(|c: char| c.is_ascii_whitespace()) {
        Some((keyword, rest)) => (keyword, rest.trim()),
        None => (line, ""),
    }
}

/// Parses the three coordinates after `vertex`.
fn parse_vertex(rest: &str) -> Result<DVec3, String> {
    let mut words = rest.split_whitespace();
    let mut xyz = [0.0; 3];
    for c in &mut xyz {
        let word = words
            .next()
            .ok_or_else(|| format!("'vertex {rest}' needs three coordinates"))?;
        *c = word
            .parse::<f64>()
            .map_err(|_| format!("'{word}' is not a number"))?;
        if !c.is_finite() {
            return Err(format!("non-finite coordinate '{word}'"));
        }
    }
    if words.next().is_some() {
        return Err(format!("'vertex {rest}' has more than three coordinates"));
    }
    Ok(DVec3::from_array(xyz))
}

#[cfg(test)]
mod tests {
    use std::path::PathBuf;

    use super::*;
    use crate::io::{MeshFormat, load_bodies, load_bodies_from_bytes};

    /// A binary STL of an `n × n` grid of quads (an open sheet): two
    /// triangles per quad, corners repeated per triangle,
    /// the origin once written as `−0.0`, and a header starting with `solid`.
    fn grid_stl(n: u32) -> Vec<u8> {
        let mut bytes = b"solid but binary".to_vec();
        bytes.resize(80, b' ');
        bytes.extend_from_slice(&(2 * n * n).to_le_bytes());
        let point = |i: u32, j: u32| [i as f32 * 0.5, j as f32 * 0.25, ((i * j) % 7) as f32];
        for i in 0..n {
            for j in 0..n {
                let (a, b, c, d) = (
                    point(i, j),
                    point(i + 1, j),
                    point(i + 1, j + 1),
                    point(i, j + 1),
                );
                for (k, tri) in [[a, b, c], [a, c, d]].into_iter().enumerate() {
                    bytes.extend_from_slice(&[0; 12]);
                    for p in tri {
                        // The origin as −0.0 in the first triangle, +0.0 in the second.
                        let p = if p == [0.0; 3] && k == 0 {
                            [-0.0, 0.0, -0.0]
                        } else {
                            p
                        };
                        p.iter()
                            .for_each(|c| bytes.extend_from_slice(&c.to_le_bytes()));
                    }
                    bytes.extend_from_slice(&[0; 2]);
                }
            }
        }
        bytes
    }

    fn temp_file(name: &str, bytes: &[u8]) -> PathBuf {
        let path = std::env::temp_dir().join(format!("kreisel-stl-{}-{name}", std::process::id()));
        std::fs::write(&path, bytes).unwrap();
        path
    }

    #[test]
    fn streamed_binary_file_equals_bytes_in_memory_and_shares_vertices() {
        // 2·70² = 9800 triangles: more than one chunk of records.
        let bytes = grid_stl(70);
        let path = temp_file("grid.stl", &bytes);
        let streamed = load_bodies(&path);
        let _ = std::fs::remove_file(&path);
        let streamed = streamed.unwrap();
        let in_memory = load_bodies_from_bytes(&bytes, MeshFormat::Stl, "grid.stl", None).unwrap();
        assert_eq!(streamed[0].mesh, in_memory[0].mesh);
        assert_eq!(streamed[0].mesh.triangles().len(), 9800);
        // (n + 1)² grid points: repeats and the signed zeros merged.
        assert_eq!(streamed[0].mesh.vertices().len(), 71 * 71);
    }

    #[test]
    fn skipping_the_exact_weld_pass_for_binary_files_changes_nothing() {
        // The loader marks binary bodies as free of exact repeats; the full
        // weld (exact pass included) of the same parsed records must agree.
        let bytes = grid_stl(12);
        let parsed = parse_binary(&bytes, 1).unwrap();
        let (vertices, triangles) = (parsed.vertices, parsed.triangles);
        let (full, _) = TriMesh::new(vertices, triangles)
            .welded(crate::Weld::default())
            .unwrap();
        let loaded = load_bodies_from_bytes(&bytes, MeshFormat::Stl, "grid.stl", None).unwrap();
        assert_eq!(loaded[0].mesh.vertices(), full.vertices());
        assert_eq!(loaded[0].mesh.triangles(), full.triangles());
    }

    #[test]
    fn ascii_facets_share_repeated_vertices_as_they_are_read() {
        let text = "solid s\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n\
            vertex 0 1 0\nvertex -0 1 1\nendloop\nendfacet\nfacet normal 0 0 0\nouter loop\n\
            vertex 1 0 0\nvertex 0 0 0\nvertex 0 0 -0\nendloop\nendfacet\nendsolid\n";
        let solids = parse_ascii(text.as_bytes()).unwrap();
        let solid = solids.into_iter().next().unwrap();
        assert_eq!(solid.triangles, [[0, 1, 2], [0, 2, 3], [1, 0, 0]]);
        assert_eq!(solid.vertices.into_vertices().len(), 4);
    }

    #[test]
    fn a_non_finite_corner_in_a_later_chunk_is_named_when_streamed() {
        let mut bytes = grid_stl(70);
        let at = HEADER + 9000 * RECORD + 12 + 12 + 4;
        bytes[at..at + 4].copy_from_slice(&f32::INFINITY.to_le_bytes());
        let path = temp_file("inf.stl", &bytes);
        let err = load_bodies(&path).map(|_| ()).unwrap_err();
        let _ = std::fs::remove_file(&path);
        assert!(
            err.to_string()
                .contains("triangle 9000, corner 1 has a non-finite"),
            "{err}"
        );
    }

    #[test]
    fn records_read_in_parts_weld_to_the_mesh_read_as_one() {
        // 2·90² = 16200 triangles: two chunks of 8192 records, so at most
        // two parts.
        let bytes = grid_stl(90);
        let welded = |threads: usize| {
            let parsed = parse_binary(&bytes, threads).unwrap();
            let mesh = TriMesh::new(parsed.vertices, parsed.triangles);
            let mesh = if parsed.unique {
                mesh.known_exact_unique()
            } else {
                mesh.known_first_use()
            };
            mesh.welded(crate::Weld::default()).unwrap()
        };
        let one = welded(1);
        assert_eq!(one.0.vertices().len(), 91 * 91);
        for threads in [2, 3, 7] {
            let parsed = parse_binary(&bytes, threads).unwrap();
            // Several parts: repeats between them are left to the weld.
            assert!(
                !parsed.unique && parsed.vertices.len() > 91 * 91,
                "{threads}"
            );
            assert_eq!(welded(threads), one, "{threads}");
        }
    }

    #[test]
    fn a_non_finite_corner_is_named_by_its_file_index_in_a_later_part() {
        // Parts of 8192 records: the first bad corner in file order is named,
        // whichever part meets it.
        for bad in [vec![(14_000, 2)], vec![(5_000, 2), (9_000, 0)]] {
            let mut bytes = grid_stl(90);
            for &(t, k) in &bad {
                let at = HEADER + t * RECORD + 12 + 12 * k + 8;
                bytes[at..at + 4].copy_from_slice(&f32::NAN.to_le_bytes());
            }
            let (t, k) = bad[0];
            for threads in [1, 2] {
                let err = parse_binary(&bytes, threads).map(|_| ()).unwrap_err();
                assert!(
                    err.contains(&format!("triangle {t}, corner {k} has a non-finite")),
                    "{threads}: {err}"
                );
            }
        }
    }

    #[test]
    fn shuffled_records_read_in_parts_give_the_table_of_one_part() {
        // 2·200² = 80,000 triangles in an order without locality: every
        // part's table settles; the joined parts are settled as one.
        let bytes = grid_stl(200);
        let (head, records) = bytes.split_at(HEADER);
        let mut records: Vec<&[u8]> = records.chunks(RECORD).collect();
        let mut state = 12345u64;
        for i in (1..records.len()).rev() {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1);
            records.swap(i, (state >> 33) as usize % (i + 1));
        }
        let shuffled: Vec<u8> = head
            .iter()
            .chain(records.concat().iter())
            .copied()
            .collect();
        let one = parse_binary(&shuffled, 1).unwrap();
        assert!(one.unique);
        assert_eq!(one.vertices.len(), 201 * 201);
        for threads in [2, 3, 10] {
            let many = parse_binary(&shuffled, threads).unwrap();
            assert!(many.unique, "{threads}");
            assert_eq!(many.vertices, one.vertices, "{threads}");
            assert_eq!(many.triangles, one.triangles, "{threads}");
        }
    }
}
