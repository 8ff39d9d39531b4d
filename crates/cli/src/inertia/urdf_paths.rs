//! Where a URDF `<mesh filename>` leads: `package://NAME/…` through
//! `--package NAME=DIR` or a folder named NAME found by searching upward
//! from the URDF's folder (the URDF inside its package, or the package beside
//! one of its ancestors, as in a ROS workspace's `src/`); `file://` and plain
//! paths, relative ones relative to the URDF.

use std::path::{Path, PathBuf};

use super::PackageDir;

/// Resolves mesh filenames of one URDF.
#[derive(Debug, Clone)]
pub struct MeshPaths {
    /// The URDF's folder.
    urdf_dir: PathBuf,
    /// `--package` directories.
    packages: Vec<PackageDir>,
}

impl MeshPaths {
    /// The resolver for the URDF at `urdf` with the `--package` options.
    pub fn new(urdf: &Path, packages: &[PackageDir]) -> Self {
        let urdf_dir = match urdf.parent() {
            Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
            _ => PathBuf::from("."),
        };
        Self {
            urdf_dir,
            packages: packages.to_vec(),
        }
    }

    /// The directory of package `name`.
    fn package(&self, name: &str) -> Result<PathBuf, String> {
        if let Some(p) = self.packages.iter().rev().find(|p| p.name == name) {
            return Ok(p.dir.clone());
        }
        let start = std::fs::canonicalize(&self.urdf_dir).unwrap_or_else(|_| self.urdf_dir.clone());
        for dir in start.ancestors() {
            if dir.file_name().is_some_and(|n| n == name) {
                return Ok(dir.to_path_buf());
            }
            let beside = dir.join(name);
            if beside.is_dir() {
                return Ok(beside);
            }
        }
        Err(format!(
            "package '{name}' not found: no folder named '{name}' in or above {}; give --package {name}=DIR",
            self.urdf_dir.display()
        ))
    }

    /// The file a `<mesh filename>` names; it must exist.
    ///
    /// # Errors
    /// A one-line message for an unknown package, an unsupported URL scheme
    /// or a file that does not exist.
    pub fn resolve(&self, filename: &str) -> Result<PathBuf, String> {
        let path = if let Some(rest) = filename.strip_prefix("package://") {
            let (name, inner) = rest.split_once('/').unwrap_or((rest, ""));
            self.package(name)?.join(inner)
        } else if let Some(rest) = filename.strip_prefix("file://") {
            PathBuf::from(rest)
        } else if let Some((scheme, _)) = filename.split_once("://") {
            return Err(format!(
                "mesh '{filename}': unsupported URL scheme '{scheme}://' (package://, file:// or a path)"
            ));
        } else {
            self.urdf_dir.join(filename)
        };
        // Anything that exists is handed to the loader, which reads at most
        // its size limit (a device such as /dev/zero included).
        if path.exists() {
            Ok(path)
        } else {
            Err(format!(
                "mesh file not found: {} (from '{filename}')",
                path.display()
            ))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn packages_and_relative_paths() {
        let root = std::env::temp_dir().join(format!("kreisel-urdf-paths-{}", std::process::id()));
        let urdf_dir = root.join("ws/src/bot/urdf");
        let meshes = root.join("ws/src/bot/meshes");
        let other = root.join("ws/src/parts");
        for d in [&urdf_dir, &meshes, &other] {
            std::fs::create_dir_all(d).unwrap();
        }
        for f in [
            meshes.join("a.stl"),
            other.join("b.obj"),
            urdf_dir.join("c.stl"),
        ] {
            std::fs::write(f, "").unwrap();
        }
        let paths = MeshPaths::new(&urdf_dir.join("bot.urdf"), &[]);
        // The URDF inside its package; a package beside an ancestor.
        assert!(
            paths
                .resolve("package://bot/meshes/a.stl")
                .unwrap()
                .ends_with("bot/meshes/a.stl")
        );
        assert!(
            paths
                .resolve("package://parts/b.obj")
                .unwrap()
                .ends_with("parts/b.obj")
        );
        assert_eq!(paths.resolve("c.stl").unwrap(), urdf_dir.join("c.stl"));
        let e = paths.resolve("package://nope/x.stl").unwrap_err();
        assert!(e.starts_with("package 'nope' not found"), "{e}");
        assert!(e.ends_with("give --package nope=DIR"), "{e}");
        let e = paths.resolve("package://bot/meshes/zz.stl").unwrap_err();
        assert!(e.starts_with("mesh file not found: "), "{e}");
        assert!(
            paths
                .resolve("http://x/y.stl")
                .unwrap_err()
                .contains("unsupported URL scheme")
        );
        let given = MeshPaths::new(
            &urdf_dir.join("bot.urdf"),
            &[PackageDir {
                name: "nope".into(),
                dir: other.clone(),
            }],
        );
        assert_eq!(
            given.resolve("package://nope/b.obj").unwrap(),
            other.join("b.obj")
        );
        std::fs::remove_dir_all(&root).unwrap();
    }
}
