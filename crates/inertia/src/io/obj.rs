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

use glam::DVec3;

use super::text_scan::{is_blank, next_line, next_word, parse_float, parse_integer};
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
struct Model {
    /// The `o`/`g` name ([`UNNAMED`] before any).
    name: String,
    /// The positions its faces use, in order of first use.
    vertices: Vec<DVec3>,
    /// Fan-triangulated faces, indices into `vertices`.
    triangles: Vec<[u32; 3]>,
}

/// A whole file, read.
struct Parsed {
    /// The objects/groups with faces, in file order.
    models: Vec<Model>,
    /// Faces of fewer than three vertices: the name of their object and
    /// their 1-based line number.
    skipped: Vec<(String, usize)>,
}

/// A face index that went past the vertices read so far.
#[derive(Clone, Copy)]
struct Forward {
    /// 1-based line number.
    line: usize,
    /// The absolute 1-based index.
    index: u64,
}

/// The parser's state between lines.
struct Reader {
    /// Every `v` position so far.
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

/// Reads the whole file, checking every `v` and `f` line.
fn parse(bytes: &[u8]) -> Result<Parsed, String> {
    let mut r = Reader {
        positions: Vec::new(),
        colours: 0,
        name: UNNAMED.to_owned(),
        triangles: Vec::new(),
        local: Vec::new(),
        models: Vec::new(),
        skipped: Vec::new(),
        forward: Vec::new(),
        deferred: None,
    };
    let mut rest = bytes;
    let mut n = 0;
    let mut corners = Vec::new();
    let mut failed_vertex = 0;
    let failure = loop {
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
            Some(b"f") => {
                corners.clear();
                let mut bad = None;
                for word in words {
                    match r.face_index(word, n) {
                        Ok(index) => corners.push(index),
                        Err(reason) => {
                            bad = Some(reason);
                            break;
                        }
                    }
                }
                if let Some(reason) = bad {
                    break Some(format!("line {n}: {reason}"));
                }
                if corners.len() < 3 {
                    r.skipped.push((r.name.clone(), n));
                    continue;
                }
                let first = corners[0];
                for pair in corners[1..].windows(2) {
                    r.triangles.push([first, pair[0], pair[1]]);
                }
            }
            Some(word @ (b"o" | b"g")) => {
                if !r.triangles.is_empty() {
                    r.finish_model();
                }
                r.name = object_name(&String::from_utf8_lossy(line), word.len());
            }
            _ => {}
        }
    };
    let seen = r.positions.len() as u64;
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

impl Reader {
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

    /// The 0-based position index of one face corner `v[/vt][/vn]` on line
    /// `n` (`u32::MAX` when past `u32`).
    fn face_index(&mut self, word: &[u8], n: usize) -> Result<u32, String> {
        let seen = self.positions.len();
        let v = word.split(|&b| b == b'/').next().unwrap_or(word);
        let word = || String::from_utf8_lossy(word);
        let index: i64 =
            parse_integer(v).ok_or_else(|| format!("face vertex '{}' is not an index", word()))?;
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
