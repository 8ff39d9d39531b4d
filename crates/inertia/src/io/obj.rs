//! Wavefront OBJ, read in one pass by a parser of our own.
//!
//! Only geometry is read: `v` positions, `f` faces (any polygon, fan
//! triangulated from its first corner), and `o`/`g` names, which start a new
//! body. Texture coordinates, normals, lines, points, comments and materials
//! are skipped, so a missing `.mtl` never fails a load.
//!
//! Why not the `tobj` crate (used here before): on a 1e6-triangle torus
//! (`cargo run --release --example mesh_load_phases`) `tobj::load_obj_buf`
//! alone took 935 ns per triangle (its `single_index` mode hashes every
//! `v/vt/vn` tuple), and the line-numbered pre-check that had to rewrite the
//! text for it another ≈ 360 ns; the budget for the whole load (issue 12) is
//! 300 ns per triangle. This parser keeps that loader's results exactly (the
//! differential test `tests/obj_vs_tobj.rs` compares it with `tobj` on the
//! same text): the bodies, their names, vertices in order of first use per
//! body, triangles, warnings and errors.
//!
//! Every `v` line needs three numbers and every face index is checked
//! (`0` is invalid; positive indices are 1-based into the file's vertices;
//! negative ones count back from the last vertex read so far), with the line
//! number in the error. A face of fewer than three vertices (no area, no
//! edges to share) is skipped with a [`LoadWarning::MalformedFaces`] on the
//! body it belongs to, so one bad line does not lose a whole file. Numbers
//! are read with the standard library's `str::parse::<f64>` (correctly
//! rounded). What `tobj` did beyond that is kept too: a fourth `v` number
//! `w` divides the position (`0` is an error), three more are a colour
//! (two, or more than three, are an error), and a body's vertices must be
//! defined before the next `o`/`g` line that ends it.
//!
//! Lines and words are split on the bytes (see `text_scan`). A file of a
//! megabyte or more has its second half read on a second thread while the
//! first half is read, up to the first line that depends on what came
//! before it beyond the line and vertex counts (an `o`/`g` line, a `v` line
//! with `w` or a colour, any error); the first thread reads on from there.
//! The results, warnings and errors are those of one thread (test below).

use glam::DVec3;

use super::text_scan::{
    is_blank, next_line, next_plain_digits, next_word, parse_float, parse_integer,
};
use super::{Body, LoadWarning, Source};
use crate::InertiaError;

/// The name of geometry before any `o`/`g` line (`tobj`'s, kept so that a
/// group named so still joins it as before).
const UNNAMED: &str = "unnamed_object";

/// Loads one body per object/group with faces.
pub(super) fn load(bytes: &[u8], src: &Source<'_>) -> Result<Vec<Body>, InertiaError> {
    if bytes.is_empty() {
        return Err(src.error("the file is empty"));
    }
    let Parsed {
        models,
        mut skipped,
    } = parse(bytes).map_err(|r| src.error(r))?;
    let mut bodies = Vec::new();
    for model in models {
        // The skipped faces of this object/group (by name: every skipped
        // face of a name goes to its first body).
        let (mine, rest): (Vec<_>, Vec<_>) = skipped
            .into_iter()
            .partition(|(object, _)| *object == model.name);
        skipped = rest;
        let name = if model.name == UNNAMED {
            src.stem().to_owned()
        } else {
            model.name
        };
        let mut body = src.indexed_body(name, model.vertices, model.triangles)?;
        if !mine.is_empty() {
            let lines = mine.into_iter().map(|(_, line)| line).collect();
            body.warnings.push(LoadWarning::MalformedFaces { lines });
        }
        bodies.push(body);
    }
    let Some(first) = bodies.first_mut() else {
        return Err(src.error("no faces (an OBJ body needs 'f' lines)"));
    };
    // Skipped faces of an object left without faces: reported on the first body.
    if !skipped.is_empty() {
        let mut lines: Vec<usize> = skipped.into_iter().map(|(_, line)| line).collect();
        match first.warnings.iter_mut().find_map(|w| match w {
            LoadWarning::MalformedFaces { lines } => Some(lines),
            _ => None,
        }) {
            Some(own) => {
                own.append(&mut lines);
                own.sort_unstable();
            }
            None => first.warnings.push(LoadWarning::MalformedFaces { lines }),
        }
    }
    Ok(bodies)
}

/// One object/group with faces, as read.
#[derive(Debug, PartialEq)]
struct Model {
    /// The `o`/`g` name ([`UNNAMED`] before any).
    name: String,
    /// The positions its faces use, in order of first use.
    vertices: Vec<DVec3>,
    /// Fan-triangulated faces, indices into `vertices`.
    triangles: Vec<[u32; 3]>,
}

/// A whole file, read.
#[derive(Debug, PartialEq)]
struct Parsed {
    /// The objects/groups with faces, in file order.
    models: Vec<Model>,
    /// Faces of fewer than three vertices: the name of their object and
    /// their 1-based line number.
    skipped: Vec<(String, usize)>,
}

/// A face index that went past the vertices read so far.
#[derive(Clone, Copy, Debug)]
struct Forward {
    /// 1-based line number.
    line: usize,
    /// The absolute 1-based index.
    index: u64,
}

/// The parser's state between lines.
struct Reader {
    /// How many `v` positions come before `positions` (those of the part of
    /// the file before the one this reader reads; 0 for the whole file).
    base: usize,
    /// Every `v` position so far (after the first `base`).
    positions: Vec<DVec3>,
    /// Colour components read so far (`v` lines with six numbers).
    colours: usize,
    /// The current object/group's name.
    name: String,
    /// Its triangles so far, as 0-based indices into `positions`
    /// (`u32::MAX` past `u32`).
    triangles: Vec<[u32; 3]>,
    /// Per position, its index in the body being finished (`u32::MAX`: none).
    local: Vec<u32>,
    /// Bodies finished.
    models: Vec<Model>,
    /// Skipped short faces.
    skipped: Vec<(String, usize)>,
    /// Forward references, each past all earlier ones: only these can be
    /// the first one past the file's vertex count.
    forward: Vec<Forward>,
    /// The first error of the structure (not of a line's syntax or index
    /// range, which come first whatever their place in the file).
    deferred: Option<&'static str>,
}

/// Reads the whole file, checking every `v` and `f` line (the second half
/// of a large file read ahead on a second thread, see [`Ahead`]).
fn parse(bytes: &[u8]) -> Result<Parsed, String> {
    if bytes.len() < PARALLEL_BYTES {
        return parse_from(bytes, None);
    }
    // The line after the middle byte.
    let split = bytes.len() / 2 + newline_after(&bytes[bytes.len() / 2..]);
    std::thread::scope(|scope| {
        // No thread (the system refused one): one thread reads it all.
        let ahead = std::thread::Builder::new()
            .spawn_scoped(scope, || Ahead::read(bytes, split))
            .ok();
        parse_from(bytes, ahead.map(|handle| (split, handle)))
    })
}

/// Bytes from which an OBJ file's second half is read on a second thread
/// (smaller files: one thread).
const PARALLEL_BYTES: usize = 1 << 20;

/// The length of `bytes` up to and including its first `\n` (all of it
/// when none).
fn newline_after(bytes: &[u8]) -> usize {
    let mut rest = bytes;
    next_line(&mut rest);
    bytes.len() - rest.len()
}

/// Reads the file, taking over the lines a second thread read ahead (when
/// `ahead` is given) once the first half is read.
fn parse_from(
    bytes: &[u8],
    mut ahead: Option<(usize, std::thread::ScopedJoinHandle<'_, Ahead>)>,
) -> Result<Parsed, String> {
    let mut r = Reader::new(0);
    let mut rest = bytes;
    let mut n = 0;
    let mut corners = Vec::new();
    let mut failed_vertex = 0;
    let failure = loop {
        if let Some((split, _)) = ahead
            && bytes.len() - rest.len() == split
            && let Some((_, handle)) = ahead.take()
            && let Ok(read) = handle.join()
        {
            read.hand_over(&mut r, &mut rest, &mut n, bytes);
        }
        let Some(line) = next_line(&mut rest) else {
            break None;
        };
        n += 1;
        let lossy;
        let mut words = if line.is_ascii() {
            Words::Ascii(line)
        } else {
            lossy = String::from_utf8_lossy(line);
            Words::Other(lossy.split_whitespace())
        };
        match words.next() {
            Some(b"v") => {
                if let Err(reason) = r.vertex(words) {
                    // This line counts among the file's vertices too.
                    failed_vertex = 1;
                    break Some(format!("line {n}: {reason}"));
                }
            }
            Some(b"f") => match r.face(&mut words, n, &mut corners) {
                Err(reason) => break Some(format!("line {n}: {reason}")),
                Ok(false) => r.skipped.push((r.name.clone(), n)),
                Ok(true) => {}
            },
            Some(word @ (b"o" | b"g")) => {
                if !r.triangles.is_empty() {
                    r.finish_model();
                }
                r.name = object_name(&String::from_utf8_lossy(line), word.len());
            }
            _ => {}
        }
    };
    let seen = r.seen() as u64;
    // The file's vertex count: those read, and those after an error line.
    let total = seen
        + failed_vertex
        + String::from_utf8_lossy(rest)
            .lines()
            .filter(|l| l.split_whitespace().next() == Some("v"))
            .count() as u64;
    if let Some(f) = r.forward.iter().find(|f| f.index > total) {
        return Err(format!(
            "line {}: face refers to vertex {}, but the file has {total} vertices",
            f.line, f.index
        ));
    }
    if let Some(reason) = failure {
        return Err(reason);
    }
    r.finish_model();
    if let Some(reason) = r.deferred {
        return Err(reason.to_owned());
    }
    Ok(Parsed {
        models: r.models,
        skipped: r.skipped,
    })
}

/// The second half of a file, from the line after its middle byte, read
/// while the first half is: as [`parse_from`] reads it, up to the first
/// line it cannot read without what comes before (an `o`/`g` line, a `v`
/// line with more than three values, a line with an error, a face of fewer
/// than three vertices). The first half is only scanned for its lines and
/// `v` lines, which gives the line numbers and the position count
/// (`base`) relative indices and bounds depend on. Taken over only when
/// the first half is read without error and to the same counts.
struct Ahead {
    /// The state after the lines read.
    reader: Reader,
    /// The first line's number, less one.
    line_before: usize,
    /// The lines read.
    lines: usize,
    /// Where reading starts and stops (byte offsets into the file).
    start: usize,
    stop: usize,
}

impl Ahead {
    fn read(bytes: &[u8], start: usize) -> Ahead {
        let (head, tail) = bytes.split_at(start);
        let (mut lines_before, mut vertices_before) = (0, 0);
        let mut rest = head;
        while let Some(line) = next_line(&mut rest) {
            lines_before += 1;
            if first_word_is_v(line) {
                vertices_before += 1;
            }
        }
        let mut reader = Reader::new(vertices_before);
        let mut rest = tail;
        let mut lines = 0;
        let mut corners = Vec::new();
        loop {
            let before = rest;
            let Some(line) = next_line(&mut rest) else {
                break;
            };
            let n = lines_before + lines + 1;
            let lossy;
            let mut words = if line.is_ascii() {
                Words::Ascii(line)
            } else {
                lossy = String::from_utf8_lossy(line);
                Words::Other(lossy.split_whitespace())
            };
            let read = match words.next() {
                Some(b"v") => match vertex3(words) {
                    Some(p) => {
                        reader.positions.push(DVec3::from_array(p));
                        true
                    }
                    None => false,
                },
                Some(b"f") => reader.face(&mut words, n, &mut corners) == Ok(true),
                Some(b"o" | b"g") => false,
                _ => true,
            };
            if !read {
                // Left to the first half's reader, from this line on; a
                // face's forward references were recorded before its error.
                rest = before;
                reader.forward.retain(|f| f.line < n);
                break;
            }
            lines += 1;
        }
        Ahead {
            reader,
            line_before: lines_before,
            lines,
            start,
            stop: bytes.len() - rest.len(),
        }
    }

    /// Hands the lines read over to `r`, which has just read the first half
    /// (`n` lines, `rest` the rest of `bytes`), when its counts agree.
    fn hand_over<'a>(self, r: &mut Reader, rest: &mut &'a [u8], n: &mut usize, bytes: &'a [u8]) {
        let agrees = *n == self.line_before
            && r.seen() == self.reader.base
            && bytes.len() - rest.len() == self.start;
        if !agrees {
            return;
        }
        let Reader {
            positions,
            triangles,
            forward,
            ..
        } = self.reader;
        r.positions.extend(positions);
        r.triangles.extend(triangles);
        // Each kept forward reference is past all earlier ones.
        let last = r.forward.last().map_or(0, |f| f.index);
        r.forward
            .extend(forward.into_iter().filter(|f| f.index > last));
        *n += self.lines;
        *rest = &bytes[self.stop..];
    }
}

/// Whether a line's first word is `v`, as [`parse_from`] splits it.
fn first_word_is_v(line: &[u8]) -> bool {
    if line.is_ascii() {
        let mut words = Words::Ascii(line);
        words.next() == Some(b"v")
    } else {
        String::from_utf8_lossy(line).split_whitespace().next() == Some("v")
    }
}

/// A `v` line's three coordinates when it has just three numbers.
fn vertex3<'a>(mut words: impl Iterator<Item = &'a [u8]>) -> Option<[f64; 3]> {
    let p = [
        parse_float(words.next()?)?,
        parse_float(words.next()?)?,
        parse_float(words.next()?)?,
    ];
    words.next().is_none().then_some(p)
}

impl Reader {
    /// An empty reader after `base` positions.
    fn new(base: usize) -> Self {
        Reader {
            base,
            positions: Vec::new(),
            colours: 0,
            name: UNNAMED.to_owned(),
            triangles: Vec::new(),
            local: Vec::new(),
            models: Vec::new(),
            skipped: Vec::new(),
            forward: Vec::new(),
            deferred: None,
        }
    }

    /// The `v` positions so far in the file.
    fn seen(&self) -> usize {
        self.base + self.positions.len()
    }

    /// Reads a `v` line's words after the keyword: three numbers, then
    /// optionally `w` or a colour.
    fn vertex<'a>(&mut self, mut words: impl Iterator<Item = &'a [u8]>) -> Result<(), String> {
        let mut p = [0.0; 3];
        for (axis, value) in ["x", "y", "z"].into_iter().zip(&mut p) {
            let word = words
                .next()
                .ok_or_else(|| format!("vertex has no {axis} coordinate"))?;
            *value = parse_float(word).ok_or_else(|| {
                let word = String::from_utf8_lossy(word);
                format!("vertex {axis} coordinate '{word}' is not a number")
            })?;
        }
        if let Some(first) = words.next() {
            self.extra(first, words, &mut p);
        }
        self.positions.push(DVec3::from_array(p));
        Ok(())
    }

    /// The words after a vertex's coordinates: `w` divides them; three are
    /// a colour (counted: a face's vertex needs one once any has one).
    fn extra<'a>(
        &mut self,
        first: &[u8],
        mut words: impl Iterator<Item = &'a [u8]>,
        p: &mut [f64; 3],
    ) {
        match (words.next(), words.next()) {
            (None, _) => match parse_float::<f64>(first) {
                None => self.defer("position parse error"),
                Some(0.0) => self.defer("scaling (w) by zero"),
                Some(w) => {
                    for x in p.iter_mut() {
                        *x /= w;
                    }
                }
            },
            (Some(second), Some(third)) if words.next().is_none() => {
                self.colours += [first, second, third]
                    .into_iter()
                    .take_while(|c| parse_float::<f64>(c).is_some())
                    .count();
            }
            _ => self.defer("color parse error (too many or too few components)"),
        }
    }

    /// Records the first error of the structure.
    fn defer(&mut self, reason: &'static str) {
        self.deferred.get_or_insert(reason);
    }

    /// Reads the corners of the face on line `n` (into `corners`) and, when
    /// there are at least three, appends its fan of triangles: `Ok(true)`;
    /// `Ok(false)` for a face of fewer than three corners (nothing added);
    /// the first bad corner's reason otherwise.
    fn face(
        &mut self,
        words: &mut Words<'_>,
        n: usize,
        corners: &mut Vec<u32>,
    ) -> Result<bool, String> {
        corners.clear();
        while let Some((word, plain)) = words.next_index() {
            corners.push(self.face_index(word, plain, n)?);
        }
        if corners.len() < 3 {
            return Ok(false);
        }
        let first = corners[0];
        for pair in corners[1..].windows(2) {
            self.triangles.push([first, pair[0], pair[1]]);
        }
        Ok(true)
    }

    /// The 0-based position index of one face corner `v[/vt][/vn]` on line
    /// `n` (`u32::MAX` when past `u32`).
    /// `plain`: the word's value when it is plain digits (see
    /// [`Words::next_index`]).
    fn face_index(&mut self, word: &[u8], plain: Option<i64>, n: usize) -> Result<u32, String> {
        let seen = self.seen();
        let v = word.split(|&b| b == b'/').next().unwrap_or(word);
        let word = || String::from_utf8_lossy(word);
        let index: i64 = plain
            .or_else(|| parse_integer(v))
            .ok_or_else(|| format!("face vertex '{}' is not an index", word()))?;
        let absolute = match index {
            0 => {
                return Err(format!("face vertex '{}': OBJ indices start at 1", word()));
            }
            i if i > 0 => i.unsigned_abs(),
            i => (seen as u64 + 1)
                .checked_sub(i.unsigned_abs())
                .filter(|&a| a >= 1)
                .ok_or_else(|| {
                    format!(
                        "face vertex '{}' reaches before the first vertex \
                         (vertices defined so far: {seen})",
                        word()
                    )
                })?,
        };
        if absolute > seen as u64 && self.forward.last().is_none_or(|f| absolute > f.index) {
            self.forward.push(Forward {
                line: n,
                index: absolute,
            });
        }
        Ok(u32::try_from(absolute - 1).unwrap_or(u32::MAX))
    }

    /// Ends the current object/group: its vertices in order of first use,
    /// which must all be defined by now.
    fn finish_model(&mut self) {
        let triangles = std::mem::take(&mut self.triangles);
        if triangles.is_empty() || self.deferred.is_some() {
            return;
        }
        self.local.resize(self.positions.len(), u32::MAX);
        let mut vertices = Vec::new();
        let mut used = Vec::new();
        let mut out = Vec::with_capacity(triangles.len());
        'faces: for tri in &triangles {
            let mut t = [0; 3];
            for (corner, &g) in t.iter_mut().zip(tri) {
                let g = g as usize;
                *corner = match self.local.get(g) {
                    Some(&l) if l != u32::MAX => l,
                    Some(_) => {
                        if self.colours > 0 && g.saturating_mul(3).saturating_add(2) >= self.colours
                        {
                            self.defer("face vertex color index out of bounds");
                            break 'faces;
                        }
                        let l = vertices.len() as u32;
                        vertices.push(self.positions[g]);
                        self.local[g] = l;
                        used.push(g);
                        l
                    }
                    None => {
                        self.defer("face vertex index out of bounds");
                        break 'faces;
                    }
                };
            }
            out.push(t);
        }
        for g in used {
            self.local[g] = u32::MAX;
        }
        if self.deferred.is_none() {
            self.models.push(Model {
                name: self.name.clone(),
                vertices,
                triangles: out,
            });
        }
    }
}

/// The words of a line, as `str::split_whitespace` gives them: by bytes
/// when the line is ASCII (the same separators then, [`is_blank`]), which
/// is the bulk of the parse's time otherwise.
enum Words<'a> {
    /// The rest of an ASCII line.
    Ascii(&'a [u8]),
    /// Any other line, decoded (invalid UTF-8 replaced, as for the whole
    /// text before).
    Other(std::str::SplitWhitespace<'a>),
}

impl<'a> Words<'a> {
    /// The next word and, when it is 1 to 18 plain digits on an ASCII line,
    /// its value, read in the same pass as the split.
    #[inline]
    fn next_index(&mut self) -> Option<(&'a [u8], Option<i64>)> {
        if let Words::Ascii(rest) = self
            && let Some((value, word)) = next_plain_digits(rest, is_blank)
        {
            return Some((word, Some(value)));
        }
        self.next().map(|word| (word, None))
    }
}

impl<'a> Iterator for Words<'a> {
    type Item = &'a [u8];

    #[inline]
    fn next(&mut self) -> Option<&'a [u8]> {
        match self {
            Words::Ascii(rest) => next_word(rest, is_blank),
            Words::Other(words) => words.next().map(str::as_bytes),
        }
    }
}

/// The name of the object or group an `o`/`g` line starts: the rest of the
/// line after the keyword of `keyword_len` bytes, trimmed ([`UNNAMED`] when
/// empty).
fn object_name(line: &str, keyword_len: usize) -> String {
    let rest = line.trim_start()[keyword_len..].trim();
    if rest.is_empty() {
        UNNAMED.to_owned()
    } else {
        rest.to_owned()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A strip of `blocks` blocks: each adds two `v` lines and two faces
    /// (absolute and relative indices) — over [`PARALLEL_BYTES`] for 16 000.
    fn strip(blocks: usize) -> String {
        let mut text = String::from("# strip\nv 0 0 0\nv 0 1 0\n");
        for b in 1..=blocks {
            let x = b as f64 * 0.01;
            text += &format!("v {x} 0 {}\nv {x} 1 {}\n", x * x, -x);
            let i = 2 * b + 1;
            text += &format!("f {} {} {i}\nf -3 -1 -2\n", i - 2, i - 1);
        }
        text
    }

    /// `text` with `insert` put at the start of the line holding byte
    /// `at` (a fraction of the length).
    fn with_line(text: &str, at: f64, insert: &str) -> String {
        let byte = (text.len() as f64 * at) as usize;
        let start = text[..byte].rfind('\n').map_or(0, |i| i + 1);
        format!("{}{insert}{}", &text[..start], &text[start..])
    }

    #[test]
    fn the_second_half_read_ahead_gives_what_one_thread_gives() {
        let base = strip(16_000);
        assert!(base.len() > PARALLEL_BYTES);
        let split = base.len() / 2 + newline_after(&base.as_bytes()[base.len() / 2..]);
        let ahead = Ahead::read(base.as_bytes(), split);
        assert!(ahead.lines > 30_000, "read ahead: {} lines", ahead.lines);
        assert_eq!(ahead.stop, base.len());
        let inserts = [
            "",
            "o second\n",
            "g\n",
            "v 1 2 3 2\n",
            "v 1 2 3 0.5 0.5 0.5\n",
            "v 1 2 0\n",
            "v 1 2\n",
            "v 1 2 x\n",
            "f 1 0 2\n",
            "f 1 2\n",
            "f 1 2 99999999\n",
            "f 1 2 31000\n",
            "f 31990/1/1 2 3\n",
            "f -99999999 1 2\n",
            "f 1 -1 x\n",
            "# caf\u{e9}\n",
            "v\u{a0}1 2 3\n",
            "\r\n\n  \n",
            "vt 0.5 0.5\nvn 0 0 1\nl 1 2\n",
        ];
        let mut errors = 0;
        for insert in inserts {
            for at in [0.25, 0.5, 0.5001, 0.999] {
                let text = with_line(&base, at, insert);
                let one = parse_from(text.as_bytes(), None);
                let two = parse(text.as_bytes());
                assert_eq!(one, two, "{insert:?} at {at}");
                errors += usize::from(two.is_err());
            }
        }
        // Seven of the inserts are errors wherever they are.
        assert_eq!(errors, 7 * 4);
        // Two edits: one in each half.
        let text = with_line(&with_line(&base, 0.8, "f 1 2\n"), 0.2, "f 3 4\n");
        assert_eq!(parse_from(text.as_bytes(), None), parse(text.as_bytes()));
    }
}
