//! Wavefront OBJ through `tobj`, behind a line-numbered pre-check.
//!
//! Only geometry is read: `v` positions, `f` faces (any polygon, fan
//! triangulated by `tobj`), and `o`/`g` names, which start a new body.
//! Texture coordinates, normals, lines, points and materials are dropped
//! before `tobj` sees the text, so a missing `.mtl` never fails a load.
//!
//! The pre-check validates every `v` line (three numbers) and every face
//! index (`0` is invalid; positive indices are 1-based into the file's
//! vertices; negative ones count back from the last vertex read so far),
//! reporting the line number, and rewrites faces to plain absolute position
//! indices. A face of fewer than three vertices (no area, no edges to share)
//! is skipped with a [`LoadWarning::MalformedFaces`] on the body it belongs
//! to, so one bad line does not lose a whole file. That also keeps `tobj` away from its unchecked texture/normal
//! index arithmetic, which overflows (and panics in debug builds) on
//! indices near `isize::MAX`.

use std::fmt::Write as _;

use glam::DVec3;

use super::{Body, LoadWarning, Source};
use crate::InertiaError;

/// The name `tobj` gives geometry before any `o`/`g` line.
const TOBJ_UNNAMED: &str = "unnamed_object";

/// Loads one body per object/group with faces.
pub(super) fn load(bytes: &[u8], src: &Source<'_>) -> Result<Vec<Body>, InertiaError> {
    if bytes.is_empty() {
        return Err(src.error("the file is empty"));
    }
    let text = String::from_utf8_lossy(bytes);
    let Cleaned {
        text: cleaned,
        mut skipped,
    } = clean(&text).map_err(|r| src.error(r))?;
    let options = tobj::LoadOptions {
        single_index: true,
        triangulate: true,
        ..Default::default()
    };
    let (models, _materials) = tobj::load_obj_buf(&mut cleaned.as_bytes(), &options, |_| {
        Err(tobj::LoadError::OpenFileFailed)
    })
    .map_err(|e| src.error(e.to_string()))?;
    let mut bodies = Vec::new();
    for model in models {
        let mesh = model.mesh;
        if mesh.indices.is_empty() {
            continue;
        }
        let (positions, _) = mesh.positions.as_chunks::<3>();
        let vertices = positions
            .iter()
            .map(|p| DVec3::from_array(p.map(to_f64)))
            .collect();
        let (faces, _) = mesh.indices.as_chunks::<3>();
        // The skipped faces of this object/group (tobj names a model after
        // the `o`/`g` line that started it).
        let (mine, rest): (Vec<_>, Vec<_>) = skipped
            .into_iter()
            .partition(|(object, _)| *object == model.name);
        skipped = rest;
        let name = if model.name == TOBJ_UNNAMED {
            src.stem().to_owned()
        } else {
            model.name
        };
        let mut body = src.body(name, vertices, faces.to_vec())?;
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

/// Widens `tobj`'s float type (`f64` with its `use_f64` feature, else `f32`).
fn to_f64<T: Into<f64>>(x: T) -> f64 {
    x.into()
}

/// The text `tobj` reads, and the faces left out of it.
struct Cleaned {
    /// `v`, `f`, `o` and `g` lines.
    text: String,
    /// Faces of fewer than three vertices: the `tobj` name of their object
    /// and their 1-based line number.
    skipped: Vec<(String, usize)>,
}

/// Keeps the `v`, `f`, `o` and `g` lines, checked, with faces rewritten to
/// absolute 1-based position indices; faces of fewer than three vertices
/// are left out and listed.
fn clean(text: &str) -> Result<Cleaned, String> {
    let total = text.lines().filter(|l| keyword(l) == Some("v")).count();
    let mut out = String::with_capacity(text.len());
    let mut skipped = Vec::new();
    let mut object = TOBJ_UNNAMED.to_owned();
    let mut seen = 0usize;
    for (i, line) in text.lines().enumerate() {
        let n = i + 1;
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => {
                check_vertex(words).map_err(|r| format!("line {n}: {r}"))?;
                seen += 1;
                out.push_str(line.trim());
            }
            Some("f") => {
                let start = out.len();
                out.push('f');
                let mut corners = 0usize;
                for word in words {
                    let index =
                        face_index(word, seen, total).map_err(|r| format!("line {n}: {r}"))?;
                    // Writing to a String cannot fail.
                    let _ = write!(out, " {index}");
                    corners += 1;
                }
                if corners < 3 {
                    out.truncate(start);
                    skipped.push((object.clone(), n));
                    continue;
                }
            }
            Some(word @ ("o" | "g")) => {
                out.push_str(line.trim());
                object = object_name(line, word);
            }
            _ => continue,
        }
        out.push('\n');
    }
    Ok(Cleaned { text: out, skipped })
}

/// The name `tobj` gives the object or group an `o`/`g` line starts: the
/// rest of the line, trimmed (the keyword's own name when empty).
fn object_name(line: &str, keyword: &str) -> String {
    let rest = line.trim_start()[keyword.len()..].trim();
    if rest.is_empty() {
        TOBJ_UNNAMED.to_owned()
    } else {
        rest.to_owned()
    }
}

/// The first word of a line.
fn keyword(line: &str) -> Option<&str> {
    line.split_whitespace().next()
}

/// Checks that a `v` line starts with three numbers.
fn check_vertex<'a>(mut words: impl Iterator<Item = &'a str>) -> Result<(), String> {
    for axis in ["x", "y", "z"] {
        let word = words
            .next()
            .ok_or_else(|| format!("vertex has no {axis} coordinate"))?;
        if word.parse::<f64>().is_err() {
            return Err(format!("vertex {axis} coordinate '{word}' is not a number"));
        }
    }
    Ok(())
}

/// The absolute 1-based position index of one face corner `v[/vt][/vn]`.
///
/// `seen` vertices precede the face; the file has `total`.
fn face_index(word: &str, seen: usize, total: usize) -> Result<u64, String> {
    let v = word.split('/').next().unwrap_or(word);
    let index: i64 = v
        .parse()
        .map_err(|_| format!("face vertex '{word}' is not an index"))?;
    let absolute = match index {
        0 => return Err(format!("face vertex '{word}': OBJ indices start at 1")),
        i if i > 0 => i.unsigned_abs(),
        i => (seen as u64 + 1)
            .checked_sub(i.unsigned_abs())
            .filter(|&a| a >= 1)
            .ok_or_else(|| {
                format!(
                    "face vertex '{word}' reaches before the first vertex \
                     (vertices defined so far: {seen})"
                )
            })?,
    };
    if absolute > total as u64 {
        return Err(format!(
            "face refers to vertex {absolute}, but the file has {total} vertices"
        ));
    }
    Ok(absolute)
}
