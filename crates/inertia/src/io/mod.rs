//! Mesh files: STL (binary and ASCII), OBJ, PLY (ASCII and binary), glTF/GLB.
//!
//! Loading never trusts a file's own counts for allocation, never panics on
//! malformed input, and reports one typed [`InertiaError`] naming the file.
//!
//! Every body goes through [`TriMesh::try_new`] and then [`TriMesh::welded`]
//! with the [`Weld`] of the [`LoadOptions`] (by default: within `1e-6 ×` the
//! body's bounding-box diagonal), so formats that repeat vertices per
//! triangle (STL) and files whose duplicates differ in the last digits come
//! out with shared edges; a body whose vertices were welded within the
//! tolerance says so in its [`LoadWarning`]s. Coordinates are kept as the
//! file stores them: binary `f32` values convert to `f64` exactly, text values
//! are parsed straight to `f64`. With [`LoadOptions::merge`] all bodies of a
//! file become one (welded together), for files whose objects are closed only
//! as a whole.
//!
//! [`load_solid`] goes on from a file to the mass properties of its bodies
//! and of all of them as one rigid solid ([`SolidOptions`]: units, model,
//! density or total mass): the one way the CLI and the demos build a body
//! from a mesh.
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
//! - OBJ: a face index of 0 or beyond the vertices, a `v` line without
//!   three numbers (all with line number); a face of fewer than three
//!   vertices is skipped with a [`LoadWarning::MalformedFaces`] naming its line;
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

use crate::{InertiaError, TriMesh, Weld};

pub use read_limit::{
    MESH_FILE_LIMIT, TEXT_FILE_LIMIT, read_limited, read_limited_from, read_limited_text, too_large,
};
pub use solid::{Solid, SolidBody, SolidOptions, SolidWarning, load_solid};

mod exact_repeats;
mod gltf;
mod obj;
mod ply;
mod read_limit;
mod solid;
mod stl;
mod text_scan;
mod vertex_table;

pub use crate::mesh_format::MeshFormat;

/// One body of a mesh file: an OBJ object, a glTF mesh, or the whole file.
#[derive(Debug, Clone, PartialEq)]
pub struct Body {
    /// The body's name in the file (or the file stem when it has none).
    pub name: String,
    /// Its triangles, with its vertices welded.
    pub mesh: TriMesh,
    /// What the loader repaired or skipped in this body.
    pub warnings: Vec<LoadWarning>,
}

/// Something a loader repaired or skipped; the body is still usable.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum LoadWarning {
    /// Distinct vertices within the weld tolerance were merged (bit-identical
    /// repeats are not counted).
    Welded {
        /// How many vertices were merged into another.
        vertices: usize,
        /// The tolerance, in the file's units.
        tolerance: f64,
        /// The largest distance a vertex moved, in the file's units.
        max_move: f64,
    },
    /// OBJ faces with fewer than three vertices were skipped.
    MalformedFaces {
        /// Their 1-based line numbers.
        lines: Vec<usize>,
    },
}

impl fmt::Display for LoadWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LoadWarning::Welded {
                vertices,
                tolerance,
                max_move,
            } => write!(
                f,
                "welded {vertices} vertices lying within {tolerance:.3e} of another (largest \
                 move {max_move:.3e}, in the file's units)"
            ),
            LoadWarning::MalformedFaces { lines } => {
                const SHOWN: usize = 10;
                let listed: Vec<String> =
                    lines.iter().take(SHOWN).map(ToString::to_string).collect();
                let more = if lines.len() > SHOWN { ", …" } else { "" };
                write!(
                    f,
                    "skipped {} faces with fewer than 3 vertices (line {}{more})",
                    lines.len(),
                    listed.join(", ")
                )
            }
        }
    }
}

/// How files are loaded: vertex welding and whether bodies are merged.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LoadOptions {
    /// How vertices are welded (default: [`Weld::default`], relative).
    pub weld: Weld,
    /// All bodies of a file as one (welded together), named after the file.
    pub merge: bool,
}

impl LoadOptions {
    /// Loads every body of a mesh file, choosing the format by extension.
    ///
    /// A `.gltf` file's external buffers are resolved relative to its directory.
    ///
    /// # Errors
    /// [`InertiaError::Io`], [`InertiaError::UnknownFormat`],
    /// [`InertiaError::Parse`], [`InertiaError::InFile`] (for meshes that
    /// [`TriMesh::try_new`] rejects, with its reason), and
    /// [`InertiaError::NotFinite`] for a bad weld tolerance; a file read
    /// whole that is larger than [`MESH_FILE_LIMIT`] (an endless device
    /// too) is [`InertiaError::Io`] of kind [`std::io::ErrorKind::FileTooLarge`].
    pub fn load(&self, path: &Path) -> Result<Vec<Body>, InertiaError> {
        let format = MeshFormat::from_path(path).ok_or_else(|| InertiaError::UnknownFormat {
            path: path.to_path_buf(),
        })?;
        let stem = path
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        let src = Source::new(path, format, &stem, path.parent(), *self);
        if format == MeshFormat::Stl {
            // Binary STL streams from the file instead of holding it whole.
            return src.finish(stl::load_file(&src)?);
        }
        let bytes = read_limited(path, MESH_FILE_LIMIT, "a mesh file").map_err(|source| {
            InertiaError::Io {
                path: path.to_path_buf(),
                source,
            }
        })?;
        load(&bytes, &src)
    }

    /// Loads every body of a mesh file already in memory.
    ///
    /// `name` stands for the file: it appears in error messages in place of
    /// a path, and its stem is the default body name. `base_dir` is where a
    /// glTF file's external buffers are looked up; with `None` only embedded
    /// (`data:`) and GLB buffers can be read.
    ///
    /// ```
    /// use kreisel_inertia::io::{LoadOptions, LoadWarning, MeshFormat};
    /// // Two objects, each an open half of a tetrahedron, and a 2-vertex face.
    /// let obj = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\no a\nf 1 3 2\nf 1 2 4\nf 1 2\no b\nf 1 4 3\nf 2 3 4\n";
    /// let options = LoadOptions { merge: true, ..LoadOptions::default() };
    /// let bodies = options.load_bytes(obj, MeshFormat::Obj, "tetra.obj", None)?;
    /// assert_eq!((bodies.len(), bodies[0].name.as_str()), (1, "tetra"));
    /// assert_eq!(bodies[0].mesh.triangles().len(), 4);
    /// assert_eq!(bodies[0].warnings, vec![LoadWarning::MalformedFaces { lines: vec![8] }]);
    /// # Ok::<(), kreisel_inertia::InertiaError>(())
    /// ```
    ///
    /// # Errors
    /// As [`LoadOptions::load`].
    pub fn load_bytes(
        &self,
        bytes: &[u8],
        format: MeshFormat,
        name: &str,
        base_dir: Option<&Path>,
    ) -> Result<Vec<Body>, InertiaError> {
        let path = PathBuf::from(name);
        let stem = path
            .file_stem()
            .map_or_else(|| name.to_owned(), |s| s.to_string_lossy().into_owned());
        load(bytes, &Source::new(&path, format, &stem, base_dir, *self))
    }
}

/// Loads every body of a mesh file with the default [`LoadOptions`].
///
/// # Errors
/// As [`LoadOptions::load`].
pub fn load_bodies(path: &Path) -> Result<Vec<Body>, InertiaError> {
    LoadOptions::default().load(path)
}

/// Loads every body of a mesh file already in memory with the default
/// [`LoadOptions`] (see [`LoadOptions::load_bytes`]).
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
/// As [`LoadOptions::load`].
pub fn load_bodies_from_bytes(
    bytes: &[u8],
    format: MeshFormat,
    name: &str,
    base_dir: Option<&Path>,
) -> Result<Vec<Body>, InertiaError> {
    LoadOptions::default().load_bytes(bytes, format, name, base_dir)
}

fn load(bytes: &[u8], src: &Source<'_>) -> Result<Vec<Body>, InertiaError> {
    let bodies = match src.format {
        MeshFormat::Stl => stl::load(bytes, src),
        MeshFormat::Obj => obj::load(bytes, src),
        MeshFormat::Ply => ply::load(bytes, src),
        MeshFormat::Gltf | MeshFormat::Glb => gltf::load(bytes, src),
    }?;
    src.finish(bodies)
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
    options: LoadOptions,
}

impl<'a> Source<'a> {
    fn new(
        path: &'a Path,
        format: MeshFormat,
        stem: &str,
        base_dir: Option<&'a Path>,
        options: LoadOptions,
    ) -> Self {
        let stem = if stem.is_empty() { "mesh" } else { stem };
        Self {
            path,
            format,
            stem: stem.to_owned(),
            base_dir,
            options,
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

    /// Validates one body's mesh and welds its vertices (unless the bodies
    /// are to be merged: then the merged body is welded).
    ///
    /// A mesh [`TriMesh::try_new`] rejects becomes a [`InertiaError::InFile`]
    /// naming the file and the body, with the mesh error as source (the mesh
    /// error variants carry no path).
    fn body(
        &self,
        name: String,
        vertices: Vec<DVec3>,
        triangles: Vec<[u32; 3]>,
    ) -> Result<Body, InertiaError> {
        let mesh = TriMesh::try_new(vertices, triangles).map_err(|e| self.in_body(&name, e))?;
        self.body_from_mesh(name, mesh)
    }

    /// A body of a checked mesh, welded unless the bodies are to be merged.
    fn body_from_mesh(&self, name: String, mesh: TriMesh) -> Result<Body, InertiaError> {
        let body = Body {
            mesh,
            name,
            warnings: Vec::new(),
        };
        if self.options.merge {
            Ok(body)
        } else {
            self.weld(body)
        }
    }

    /// Welds a body's vertices, recording a warning when any was within the
    /// tolerance but not bit-identical.
    fn weld(&self, mut body: Body) -> Result<Body, InertiaError> {
        let (mesh, welded) = body
            .mesh
            .welded(self.options.weld)
            .map_err(|e| self.in_body(&body.name, e))?;
        body.mesh = mesh;
        if welded.merged > 0 {
            body.warnings.insert(
                0,
                LoadWarning::Welded {
                    vertices: welded.merged,
                    tolerance: welded.tolerance,
                    max_move: welded.max_move,
                },
            );
        }
        Ok(body)
    }

    /// The file's bodies as loaded: merged into one when the options ask.
    fn finish(&self, bodies: Vec<Body>) -> Result<Vec<Body>, InertiaError> {
        if self.options.merge {
            Ok(vec![self.merged(bodies)?])
        } else {
            Ok(bodies)
        }
    }

    /// All bodies as one named after the file, welded together.
    fn merged(&self, bodies: Vec<Body>) -> Result<Body, InertiaError> {
        let mut vertices = Vec::new();
        let mut triangles = Vec::new();
        let mut warnings = Vec::new();
        for body in bodies {
            let (v, t) = body.mesh.into_parts();
            // Every index of the merged body, the last one too, fits in u32.
            vertex_index(vertices.len() + v.len()).map_err(|r| self.error(r))?;
            let base = vertices.len() as u32;
            vertices.extend(v);
            triangles.extend(t.into_iter().map(|tri| tri.map(|i| i + base)));
            warnings.extend(body.warnings);
        }
        let name = self.stem().to_owned();
        let mesh = TriMesh::try_new(vertices, triangles).map_err(|e| self.in_body(&name, e))?;
        self.weld(Body {
            name,
            mesh,
            warnings,
        })
    }

    /// A mesh error of one body of this file.
    fn in_body(&self, body: &str, e: InertiaError) -> InertiaError {
        InertiaError::InFile {
            path: self.path.to_path_buf(),
            body: body.to_owned(),
            source: Box::new(e),
        }
    }
}

/// A vertex count as a `u32` triangle index, or a reason why it does not fit.
fn vertex_index(count: usize) -> Result<u32, String> {
    u32::try_from(count).map_err(|_| format!("more than {} vertices", u32::MAX))
}
