//! Relative mesh paths of a URDF written to another folder (`--output`):
//! each plain relative `<mesh filename>` is rewritten so that, read from the
//! output's folder, it names the same file.
//!
//! ```text
//! robot/model.urdf  meshes/link0.stl   --output out/filled.urdf  →  ../robot/meshes/link0.stl
//! ```
//!
//! The new path is relative (computed from both folders with symbolic links
//! resolved), so the output keeps loading when the two folders move
//! together; `package://` and `file://` names and absolute paths do not
//! depend on the URDF's folder and are kept. Written to standard output the
//! file is unchanged: where it will be saved is unknown.

use std::ops::Range;
use std::path::{Component, Path, PathBuf};

use super::urdf_document::{Shape, UrdfDocument};

/// The folder of a file path (`.` for a bare name).
fn folder(file: &Path) -> PathBuf {
    match file.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// `path` with `.` and `name/..` removed, without touching the file system.
fn normalized(path: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for c in path.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir
                if matches!(out.components().next_back(), Some(Component::Normal(_))) =>
            {
                out.pop();
            }
            c => out.push(c),
        }
    }
    out
}

/// The real location of `path`: its folder with links resolved when it
/// exists (the file's own name kept, so a linked mesh keeps its name).
fn real(path: &Path) -> PathBuf {
    // The folder as the system resolves it (`..` after a link included);
    // without one, lexically.
    if let (Some(dir), Some(name)) = (path.parent(), path.file_name())
        && let Ok(dir) = std::fs::canonicalize(dir)
    {
        return dir.join(name);
    }
    normalized(&std::path::absolute(path).unwrap_or_else(|_| path.to_path_buf()))
}

/// The relative path from folder `from` to `to` (both absolute), with `/`.
fn relative(from: &Path, to: &Path) -> String {
    let from: Vec<_> = from.components().collect();
    let to: Vec<_> = to.components().collect();
    let common = from.iter().zip(&to).take_while(|(a, b)| a == b).count();
    let mut parts: Vec<String> = vec!["..".to_owned(); from.len() - common];
    parts.extend(
        to[common..]
            .iter()
            .map(|c| c.as_os_str().to_string_lossy().into_owned()),
    );
    parts.join("/")
}

/// `text` escaped for a double-quoted XML attribute.
fn attribute_text(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('"', "&quot;")
}

/// Whether a mesh filename is a plain relative path.
fn is_relative(filename: &str) -> bool {
    !filename.contains("://") && !filename.is_empty() && Path::new(filename).is_relative()
}

/// The edits that rewrite every relative mesh filename of `doc` (read from
/// `urdf`) for a file written to `output`: the byte range of each
/// `filename="…"` attribute and its new text. Empty when both are in the
/// same folder.
pub fn relocate(doc: &UrdfDocument, urdf: &Path, output: &Path) -> Vec<(Range<usize>, String)> {
    let dir = |file: &Path| {
        let folder = folder(file);
        std::fs::canonicalize(&folder)
            .unwrap_or_else(|_| normalized(&std::path::absolute(&folder).unwrap_or(folder)))
    };
    let (from_dir, to_dir) = (dir(urdf), dir(output));
    if from_dir == to_dir {
        return Vec::new();
    }
    let mut edits = Vec::new();
    for link in &doc.links {
        for geometry in link.collision.iter().chain(&link.visual) {
            if let (Shape::Mesh { filename, .. }, Some(range)) =
                (&geometry.shape, &geometry.filename_attribute)
                && is_relative(filename)
            {
                let target = real(&from_dir.join(filename));
                let new = relative(&to_dir, &target);
                edits.push((
                    range.clone(),
                    format!("filename=\"{}\"", attribute_text(&new)),
                ));
            }
        }
    }
    edits
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn relative_paths_between_folders() {
        assert_eq!(
            relative(Path::new("/a/b/out"), Path::new("/a/b/robot/meshes/x.stl")),
            "../robot/meshes/x.stl"
        );
        assert_eq!(
            relative(Path::new("/a"), Path::new("/a/m/x.stl")),
            "m/x.stl"
        );
        assert_eq!(
            relative(Path::new("/a/b/c"), Path::new("/x.stl")),
            "../../../x.stl"
        );
        assert_eq!(normalized(Path::new("/a/./b/../c")), PathBuf::from("/a/c"));
        assert!(is_relative("../meshes/a.stl") && is_relative("meshes/a.stl"));
        assert!(!is_relative("package://p/a.stl") && !is_relative("/abs/a.stl"));
        assert_eq!(attribute_text("a&\"<b"), "a&amp;&quot;&lt;b");
    }
}
