//! Mesh files: STL (binary and ASCII), OBJ, PLY (ASCII and binary), glTF/GLB.
//!
//! Loading never trusts a file's own counts for allocation, never panics on
//! malformed input, and reports one typed [`InertiaError`] naming the file.
//!
//! Every body goes through [`TriMesh::try_new`] and then
//! [`TriMesh::merge_duplicate_vertices`], so formats that repeat vertices per
//! triangle (STL) come out with shared edges. Coordinates are kept as the file
//! stores them: binary `f32` values convert to `f64` exactly, text values are
//! parsed straight to `f64`.
//!
//! | format | bodies | name |
//! | --- | --- | --- |
//! | STL | one per `solid` (binary: one) | `solid NAME`, else the file stem |
//! | OBJ | one per object/group (`o`/`g`) with faces | the object/group name |
//! | PLY | one | the file stem |
//! | glTF/GLB | one per mesh instance in the scene | node name, mesh name or `mesh{i}` |
//!
//! What counts as broken, per format:
//! - binary STL: the length must be exactly `84 + 50·n` for the header's
//!   count `n`; a shorter file (truncated, or a header claiming more) and a
//!   longer one (trailing bytes, or a header claiming fewer) are both
//!   refused, since either way the count is wrong;
//! - OBJ: a face index of 0 or beyond the vertices, a face of fewer than
//!   three vertices, a `v` line without three numbers (all with line number);
//! - PLY: header counts that need more bytes than follow the header; a
//!   face index outside the vertex element (bytes after the last element
//!   are ignored);
//! - glTF: an accessor or buffer view reaching past its buffer, a buffer
//!   shorter than its `byteLength`, a node hierarchy that is not a tree,
//!   a URI that is neither `data:` nor a relative file path;
//! - all: an empty file, no triangles, a non-finite coordinate.

use core::fmt;
use std::path::{Path, PathBuf};

use glam::DVec3;

use crate::{InertiaError, TriMesh};

mod gltf;
mod obj;
mod ply;
mod stl;
mod vertex_table;

/// The mesh file formats kreisel reads.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MeshFormat {
    /// STL, binary or ASCII (`.stl`).
    Stl,
    /// Wavefront OBJ (`.obj`).
    Obj,
    /// Stanford PLY, ASCII or binary (`.ply`).
    Ply,
    /// glTF 2.0 JSON with embedded or adjacent buffers (`.gltf`).
    Gltf,
    /// Binary glTF (`.glb`).
    Glb,
}

impl MeshFormat {
    /// The format named by a path's extension (case-insensitive), if any.
    ///
    /// ```
    /// use std::path::Path;
    /// use kreisel_inertia::io::MeshFormat;
    /// assert_eq!(MeshFormat::from_path(Path::new("part.STL")), Some(MeshFormat::Stl));
    /// assert_eq!(MeshFormat::from_path(Path::new("scene.glb")), Some(MeshFormat::Glb));
    /// assert_eq!(MeshFormat::from_path(Path::new("notes.txt")), None);
    /// ```
    pub fn from_path(path: &Path) -> Option<Self> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "stl" => Some(Self::Stl),
            "obj" => Some(Self::Obj),
            "ply" => Some(Self::Ply),
            "gltf" => Some(Self::Gltf),
            "glb" => Some(Self::Glb),
            _ => None,
        }
    }
}

impl fmt::Display for MeshFormat {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            MeshFormat::Stl => "STL",
            MeshFormat::Obj => "OBJ",
            MeshFormat::Ply => "PLY",
            MeshFormat::Gltf => "glTF",
            MeshFormat::Glb => "GLB",
        })
    }
}

/// One body of a mesh file: an OBJ object, a glTF mesh, or the whole file.
#[derive(Debug, Clone, PartialEq)]
pub struct Body {
    /// The body's name in the file (or the file stem when it has none).
    pub name: String,
    /// Its triangles, with duplicate vertices merged.
    pub mesh: TriMesh,
}

/// Loads every body of a mesh file, choosing the format by extension.
///
/// A `.gltf` file's external buffers are resolved relative to its directory.
///
/// # Errors
/// [`InertiaError::Io`], [`InertiaError::UnknownFormat`],
/// [`InertiaError::Parse`] (also for meshes that [`TriMesh::try_new`]
/// rejects, with its reason).
pub fn load_bodies(path: &Path) -> Result<Vec<Body>, InertiaError> {
    let format = MeshFormat::from_path(path).ok_or_else(|| InertiaError::UnknownFormat {
        path: path.to_path_buf(),
    })?;
    let stem = path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let src = Source::new(path, format, &stem, path.parent());
    if format == MeshFormat::Stl {
        // Binary STL streams from the file instead of holding it whole.
        return stl::load_file(&src);
    }
    let bytes = std::fs::read(path).map_err(|source| InertiaError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    load(&bytes, &src)
}

/// Loads every body of a mesh file already in memory.
///
/// `name` stands for the file: it appears in error messages in place of a
/// path, and its stem is the default body name. `base_dir` is where a glTF file's
/// external buffers are looked up; with `None` only embedded (`data:`) and
/// GLB buffers can be read.
///
/// ```
/// use kreisel_inertia::io::{load_bodies_from_bytes, MeshFormat};
/// let obj = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
/// let bodies = load_bodies_from_bytes(obj, MeshFormat::Obj, "tetra.obj", None)?;
/// assert_eq!(bodies[0].name, "tetra");
/// assert_eq!(bodies[0].mesh.triangles().len(), 4);
/// # Ok::<(), kreisel_inertia::InertiaError>(())
/// ```
///
/// # Errors
/// As [`load_bodies`].
pub fn load_bodies_from_bytes(
    bytes: &[u8],
    format: MeshFormat,
    name: &str,
    base_dir: Option<&Path>,
) -> Result<Vec<Body>, InertiaError> {
    let path = PathBuf::from(name);
    let stem = path
        .file_stem()
        .map_or_else(|| name.to_owned(), |s| s.to_string_lossy().into_owned());
    load(bytes, &Source::new(&path, format, &stem, base_dir))
}

fn load(bytes: &[u8], src: &Source<'_>) -> Result<Vec<Body>, InertiaError> {
    match src.format {
        MeshFormat::Stl => stl::load(bytes, src),
        MeshFormat::Obj => obj::load(bytes, src),
        MeshFormat::Ply => ply::load(bytes, src),
        MeshFormat::Gltf | MeshFormat::Glb => gltf::load(bytes, src),
    }
}

/// Longest reason text kept from a parser (whose messages may quote input).
const MAX_REASON: usize = 400;

/// Where the bytes being parsed came from: for error messages, default body
/// names and relative references.
struct Source<'a> {
    path: &'a Path,
    format: MeshFormat,
    stem: String,
    base_dir: Option<&'a Path>,
}

impl<'a> Source<'a> {
    fn new(path: &'a Path, format: MeshFormat, stem: &str, base_dir: Option<&'a Path>) -> Self {
        let stem = if stem.is_empty() { "mesh" } else { stem };
        Self {
            path,
            format,
            stem: stem.to_owned(),
            base_dir,
        }
    }

    /// The default body name: the file stem.
    fn stem(&self) -> &str {
        &self.stem
    }

    /// The directory relative references resolve against, if any.
    fn base_dir(&self) -> Option<&'a Path> {
        self.base_dir
    }

    /// A parse error for this file, its reason clipped to a readable length.
    fn error(&self, reason: impl Into<String>) -> InertiaError {
        let mut reason = reason.into();
        if reason.len() > MAX_REASON {
            let mut cut = MAX_REASON;
            while !reason.is_char_boundary(cut) {
                cut -= 1;
            }
            reason.truncate(cut);
            reason.push('…');
        }
        InertiaError::Parse {
            path: self.path.to_path_buf(),
            format: self.format,
            reason,
        }
    }

    /// Validates one body's mesh and merges its duplicate vertices.
    ///
    /// A mesh [`TriMesh::try_new`] rejects becomes a [`InertiaError::Parse`]
    /// naming the file and the body, with the mesh error as reason (the mesh
    /// error variants carry no path).
    fn body(
        &self,
        name: String,
        vertices: Vec<DVec3>,
        triangles: Vec<[u32; 3]>,
    ) -> Result<Body, InertiaError> {
        match TriMesh::try_new(vertices, triangles) {
            Ok(mesh) => Ok(Body {
                name,
                mesh: mesh.merge_duplicate_vertices(),
            }),
            Err(e) => Err(InertiaError::InFile {
                path: self.path.to_path_buf(),
                body: name,
                source: Box::new(e),
            }),
        }
    }
}

/// A vertex count as a `u32` triangle index, or a reason why it does not fit.
fn vertex_index(count: usize) -> Result<u32, String> {
    u32::try_from(count).map_err(|_| format!("more than {} vertices", u32::MAX))
}
