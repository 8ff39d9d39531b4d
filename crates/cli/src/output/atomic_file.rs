//! Output files written whole or not at all.
//!
//! Every file the CLI writes (`--output` of `convert` and `simulate`,
//! `--plot` of `top`) goes to a temporary file beside the target and is
//! renamed onto it only when everything was written: a failed run (an I/O
//! error, a full disk, an invalid input line, a diverging simulation) leaves
//! no truncated file behind, and a file that existed before is kept as it
//! was. The rename is atomic on POSIX file systems (same directory, so the
//! same file system). Targets that are not regular files (`/dev/null`,
//! `/dev/stdout`, a named pipe) are written directly: they cannot be
//! replaced, and renaming onto a device node would destroy it.
//!
//! The temporary file is `.NAME.kreisel-PID-N.tmp` beside `NAME`. It is
//! removed when the run fails, and on SIGINT or SIGTERM
//! ([`remove_on_signals`]: the process then exits with status 130 or 143).
//! A SIGKILL cannot be caught: the next run writing the same output
//! removes the temporary files of processes that no longer exist. A
//! process is known to exist when `/proc/PID` does (Linux); where there
//! is no `/proc`, no such file is removed (delete them by hand).

use std::fs::{self, File, OpenOptions};
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU32, Ordering};
use std::sync::{Mutex, MutexGuard};

/// A temporary file that becomes `target` on [`PendingFile::commit`] and is
/// removed if dropped before that.
#[derive(Debug)]
pub struct PendingFile {
    /// The temporary file (`None` when writing straight to a non-regular target).
    temp: Option<PathBuf>,
    /// Where the output goes (symbolic links resolved).
    target: PathBuf,
}

/// Distinguishes the temporary files of one process.
static COUNTER: AtomicU32 = AtomicU32::new(0);

/// The temporary files of this process not yet committed or removed: what
/// a SIGINT or SIGTERM removes.
static PENDING: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// The list of pending temporary files (a panic elsewhere does not keep
/// them from being removed).
fn pending() -> MutexGuard<'static, Vec<PathBuf>> {
    PENDING
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
}

/// Forgets `temp` (committed or removed).
fn forget(list: &mut Vec<PathBuf>, temp: &Path) {
    list.retain(|p| p != temp);
}

/// From now on, a SIGINT or SIGTERM removes every pending temporary file
/// and ends the process with the shell's status for the signal (130,
/// 143); a file being renamed onto its target at that moment is put in
/// place first. A thread waits for the signals. Call once, from `main`.
///
/// # Errors
/// The operating system's reason if the handlers cannot be installed
/// (the run then goes on without them).
#[cfg(unix)]
pub fn remove_on_signals() -> io::Result<()> {
    use signal_hook::consts::{SIGINT, SIGTERM};
    let mut signals = signal_hook::iterator::Signals::new([SIGINT, SIGTERM])?;
    std::thread::Builder::new()
        .name("kreisel-signals".to_owned())
        .spawn(move || {
            if let Some(signal) = signals.forever().next() {
                // Held until the process ends: no new file, no rename.
                let list = pending();
                for temp in list.iter() {
                    let _ = fs::remove_file(temp);
                }
                std::process::exit(128 + signal);
            }
        })?;
    Ok(())
}

/// Without Unix signals: nothing to install.
///
/// # Errors
/// None.
#[cfg(not(unix))]
pub fn remove_on_signals() -> io::Result<()> {
    Ok(())
}

/// The process id in a temporary file name of target file name `name`
/// (`.NAME.kreisel-PID-N.tmp`), if `file` is one.
fn temp_pid(file: &str, name: &str) -> Option<u32> {
    let rest = file
        .strip_prefix('.')?
        .strip_prefix(name)?
        .strip_prefix(".kreisel-")?
        .strip_suffix(".tmp")?;
    let (pid, n) = rest.split_once('-')?;
    n.parse::<u32>().ok()?;
    pid.parse().ok()
}

/// Whether process `pid` exists: `/proc/PID` exists. `true` (keep its
/// files) where there is no `/proc` to ask.
fn alive(pid: u32) -> bool {
    let proc = Path::new("/proc");
    !proc.join("self").exists() || proc.join(pid.to_string()).exists()
}

/// Removes the temporary files for `name` in `dir` left by processes that
/// no longer exist (killed by SIGKILL, a power cut); a file that cannot be
/// removed stays.
fn remove_stale(dir: &Path, name: &str) {
    let Ok(entries) = fs::read_dir(dir) else {
        return;
    };
    let own = std::process::id();
    for entry in entries.flatten() {
        let file = entry.file_name();
        if let Some(pid) = file.to_str().and_then(|f| temp_pid(f, name))
            && pid != own
            && !alive(pid)
        {
            let _ = fs::remove_file(entry.path());
        }
    }
}

/// Opens a temporary file beside `target` for writing; the returned
/// [`PendingFile`] renames it onto `target` when committed.
///
/// # Errors
/// The operating system's reason when the directory of `target` does not
/// exist or is not writable.
pub fn create(target: &Path) -> io::Result<(File, PendingFile)> {
    // Write beside the real file, so that a symbolic link stays a link.
    let target = fs::canonicalize(target).unwrap_or_else(|_| target.to_owned());
    if let Ok(meta) = fs::metadata(&target)
        && !meta.is_file()
    {
        let file = OpenOptions::new()
            .write(true)
            .truncate(true)
            .open(&target)?;
        return Ok((file, PendingFile { temp: None, target }));
    }
    let dir = match target.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_owned(),
        _ => PathBuf::from("."),
    };
    let name = target
        .file_name()
        .map_or_else(|| "output".into(), |n| n.to_string_lossy().into_owned());
    remove_stale(&dir, &name);
    loop {
        let n = COUNTER.fetch_add(1, Ordering::Relaxed);
        let temp = dir.join(format!(".{name}.kreisel-{}-{n}.tmp", std::process::id()));
        // Registered before it exists: a signal never misses it.
        let mut list = pending();
        list.push(temp.clone());
        match OpenOptions::new().write(true).create_new(true).open(&temp) {
            Ok(file) => {
                drop(list);
                let pending = PendingFile {
                    temp: Some(temp),
                    target,
                };
                return Ok((file, pending));
            }
            Err(e) => {
                forget(&mut list, &temp);
                if e.kind() != io::ErrorKind::AlreadyExists {
                    return Err(e);
                }
            }
        }
    }
}

impl PendingFile {
    /// Replaces the target by the temporary file (call after the writer was
    /// flushed).
    ///
    /// # Errors
    /// The operating system's reason if the rename fails (the temporary file
    /// is removed then, and the target kept).
    pub fn commit(mut self) -> io::Result<()> {
        match self.temp.take() {
            None => Ok(()),
            Some(temp) => {
                let mut list = pending();
                forget(&mut list, &temp);
                fs::rename(&temp, &self.target).inspect_err(|_| {
                    let _ = fs::remove_file(&temp);
                })
            }
        }
    }
}

impl Drop for PendingFile {
    fn drop(&mut self) {
        if let Some(temp) = self.temp.take() {
            let mut list = pending();
            forget(&mut list, &temp);
            let _ = fs::remove_file(temp);
        }
    }
}

/// Writes `bytes` to `target` whole or not at all.
///
/// # Errors
/// The operating system's reason when the temporary file cannot be created,
/// written or renamed; `target` is unchanged then.
pub fn write_file(target: &Path, bytes: &[u8]) -> io::Result<()> {
    let (mut file, pending) = create(target)?;
    file.write_all(bytes)?;
    file.flush()?;
    drop(file);
    pending.commit()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir =
            std::env::temp_dir().join(format!("kreisel-atomic-{}-{name}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        fs::create_dir_all(&dir).unwrap();
        dir
    }

    fn entries(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> = fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    }

    #[test]
    fn a_failed_write_keeps_the_old_file_and_leaves_no_temporary() {
        let dir = scratch("failed");
        let target = dir.join("out.csv");
        fs::write(&target, "old\n").unwrap();
        {
            let (mut file, pending) = create(&target).unwrap();
            file.write_all(b"half a li").unwrap();
            // The run fails here: the pending file is dropped uncommitted.
            drop(pending);
        }
        assert_eq!(fs::read_to_string(&target).unwrap(), "old\n");
        assert_eq!(entries(&dir), ["out.csv"]);
        write_file(&target, b"new\n").unwrap();
        assert_eq!(fs::read_to_string(&target).unwrap(), "new\n");
        assert_eq!(entries(&dir), ["out.csv"]);
    }

    #[test]
    fn stale_temporaries_of_dead_processes_are_removed() {
        let dir = scratch("stale");
        let target = dir.join("out.csv");
        // A pid above Linux's largest (2^22): no such process.
        let dead = dir.join(".out.csv.kreisel-4194305-0.tmp");
        let live = dir.join(format!(".out.csv.kreisel-{}-99.tmp", std::process::id()));
        let other = dir.join(".other.csv.kreisel-4194305-0.tmp");
        for f in [&dead, &live, &other] {
            fs::write(f, "x").unwrap();
        }
        write_file(&target, b"new\n").unwrap();
        let expected = if Path::new("/proc/self").exists() {
            vec![".other.csv.kreisel-4194305-0.tmp".to_owned()]
        } else {
            vec![
                ".other.csv.kreisel-4194305-0.tmp".to_owned(),
                ".out.csv.kreisel-4194305-0.tmp".to_owned(),
            ]
        };
        let mut left = entries(&dir);
        left.retain(|f| f != "out.csv" && !f.contains(&format!("-{}-", std::process::id())));
        assert_eq!(left, expected);
        // This process's own file (alive) is kept; nothing is pending.
        assert!(live.exists());
        assert!(pending().iter().all(|p| !p.starts_with(&dir)));
        assert_eq!(temp_pid(".out.csv.kreisel-12-3.tmp", "out.csv"), Some(12));
        assert_eq!(temp_pid(".out.csv.kreisel-12.tmp", "out.csv"), None);
        assert_eq!(temp_pid(".out.csv.kreisel-x-3.tmp", "out.csv"), None);
        assert_eq!(temp_pid(".out.csvx.kreisel-12-3.tmp", "out.csv"), None);
    }

    #[test]
    fn a_missing_directory_is_an_error_and_creates_nothing() {
        let dir = scratch("missing");
        let target = dir.join("no-such-dir").join("out.png");
        assert!(write_file(&target, b"x").is_err());
        assert!(entries(&dir).is_empty());
    }

    #[test]
    fn a_full_device_is_an_error() {
        // /dev/full is no regular file: written directly, and every write fails.
        let full = Path::new("/dev/full");
        if full.exists() {
            let e = write_file(full, &[0; 1 << 16]).unwrap_err();
            assert_eq!(e.raw_os_error(), Some(28), "{e}"); // ENOSPC
        }
    }

    #[test]
    fn a_symbolic_link_stays_a_link() {
        let dir = scratch("link");
        let real = dir.join("real.csv");
        fs::write(&real, "old\n").unwrap();
        let link = dir.join("link.csv");
        #[cfg(unix)]
        {
            std::os::unix::fs::symlink(&real, &link).unwrap();
            write_file(&link, b"new\n").unwrap();
            assert!(
                fs::symlink_metadata(&link)
                    .unwrap()
                    .file_type()
                    .is_symlink()
            );
            assert_eq!(fs::read_to_string(&real).unwrap(), "new\n");
        }
    }
}
