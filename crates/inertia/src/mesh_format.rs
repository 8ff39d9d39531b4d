//! [`MeshFormat`]: the mesh file formats kreisel reads, named by a path's
//! extension (always compiled: errors name the format even where the
//! loaders of `io` are not built).

use std::fmt;
use std::path::Path;

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
