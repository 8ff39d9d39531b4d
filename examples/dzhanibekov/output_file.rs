//! Output files written whole or not at all: the bytes go to a temporary
//! file beside the target, which is renamed over the target only when
//! everything has been written and flushed; on any failure (or a panic, or
//! an early return) the temporary file is removed and the target is left
//! as it was.
//!
//! Hand-written (some 60 lines) rather than the `tempfile` crate: the demo
//! needs only create-beside, rename and remove-on-drop, and the workspace
//! does not otherwise depend on it.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

use super::DemoError;

/// A temporary file beside `target`, renamed over it by [`PendingFile::commit`].
///
/// ```text
/// target = dir/name  →  dir/.name.<pid>.tmp  →  rename on success, remove otherwise
/// ```
pub struct PendingFile {
    temporary: PathBuf,
    target: PathBuf,
    committed: bool,
}

impl PendingFile {
    /// Creates the temporary file for `target` and a buffered writer to it.
    ///
    /// # Errors
    /// [`DemoError::Write`] naming `target` when the file cannot be created.
    pub fn create(target: &Path) -> Result<(PendingFile, BufWriter<File>), DemoError> {
        let name = target
            .file_name()
            .map_or_else(|| "output".into(), |n| n.to_string_lossy().into_owned());
        let temporary = target.with_file_name(format!(".{name}.{}.tmp", std::process::id()));
        let file = File::create(&temporary).map_err(|source| DemoError::Write {
            path: target.to_path_buf(),
            source,
        })?;
        let pending = PendingFile {
            temporary,
            target: target.to_path_buf(),
            committed: false,
        };
        Ok((pending, BufWriter::new(file)))
    }

    /// Flushes and syncs `writer`, then renames the temporary file over the target.
    ///
    /// # Errors
    /// [`DemoError::Write`] naming the target; the temporary file is removed.
    pub fn commit(mut self, writer: BufWriter<File>) -> Result<(), DemoError> {
        let error = |source| DemoError::Write {
            path: self.target.clone(),
            source,
        };
        let file = writer.into_inner().map_err(|e| error(e.into_error()))?;
        file.sync_all().map_err(error)?;
        drop(file);
        std::fs::rename(&self.temporary, &self.target).map_err(error)?;
        self.committed = true;
        Ok(())
    }
}

impl Drop for PendingFile {
    fn drop(&mut self) {
        if !self.committed {
            let _ = std::fs::remove_file(&self.temporary);
        }
    }
}

/// Fails unless the directory `path` is to be written in exists (checked
/// before a long run, so that its output is not lost at the end).
///
/// # Errors
/// [`DemoError::Write`] naming `path`.
pub fn check_directory(path: &Path) -> Result<(), DemoError> {
    let dir = match path.parent() {
        Some(dir) if !dir.as_os_str().is_empty() => dir,
        _ => Path::new("."),
    };
    if dir.is_dir() {
        Ok(())
    } else {
        Err(DemoError::Write {
            path: path.to_path_buf(),
            source: std::io::Error::new(
                std::io::ErrorKind::NotFound,
                format!("no directory {}", dir.display()),
            ),
        })
    }
}

/// Writes `bytes` to `path` whole or not at all.
///
/// # Errors
/// [`DemoError::Write`] naming `path`.
pub fn write_whole(path: &Path, bytes: &[u8]) -> Result<(), DemoError> {
    let (pending, mut writer) = PendingFile::create(path)?;
    writer.write_all(bytes).map_err(|source| DemoError::Write {
        path: path.to_path_buf(),
        source,
    })?;
    pending.commit(writer)
}
