//! Reading a whole file into memory, at most a stated number of bytes.
//!
//! A path may name something endless (a symlink to `/dev/zero`, a FIFO) or
//! a file far larger than any mesh or description: read whole, it would take
//! memory until the process is killed. [`read_limited`] stops one byte past
//! the limit and fails with [`std::io::ErrorKind::FileTooLarge`] and a
//! message stating the limit, so memory stays bounded by the limit.
//!
//! | input | limit | why |
//! | --- | --- | --- |
//! | a mesh file read whole ([`MESH_FILE_LIMIT`]) | 1 GiB | about 10 million triangles as text: beyond what a link or a part needs, and within the memory of a small machine (parsing takes a few times the file) |
//! | a robot description or scene ([`TEXT_FILE_LIMIT`]) | 64 MiB | published URDFs are under 1 MB; the XML tree takes several times the text |
//!
//! Binary STL files whose length matches their header are streamed, not
//! read whole, and are not limited.

use std::io::{self, Read};
use std::path::Path;

/// Largest mesh file read whole into memory, bytes (1 GiB).
pub const MESH_FILE_LIMIT: u64 = 1 << 30;

/// Largest robot description or scene file, bytes (64 MiB).
pub const TEXT_FILE_LIMIT: u64 = 64 << 20;

/// `limit` bytes in words: `1 GiB`, `64 MiB`, or `N bytes`.
fn size_in_words(limit: u64) -> String {
    match limit {
        l if l >= 1 << 30 && l % (1 << 30) == 0 => format!("{} GiB", l >> 30),
        l if l >= 1 << 20 && l % (1 << 20) == 0 => format!("{} MiB", l >> 20),
        l => format!("{l} bytes"),
    }
}

/// The error of an input longer than `limit` bytes; `what` names the input
/// (`a mesh file`).
pub fn too_large(what: &str, limit: u64) -> io::Error {
    io::Error::new(
        io::ErrorKind::FileTooLarge,
        format!(
            "larger than {}, the limit for {what} (is it a device or an endless stream?)",
            size_in_words(limit)
        ),
    )
}

/// Reads everything `reader` gives, but fails after `limit` bytes.
///
/// ```
/// use kreisel_inertia::io::read_limited_from;
/// assert_eq!(read_limited_from(&b"abc"[..], 3, "a test")?, b"abc");
/// let e = read_limited_from(std::io::repeat(0), 1 << 20, "a test").unwrap_err();
/// assert_eq!(e.kind(), std::io::ErrorKind::FileTooLarge);
/// assert_eq!(
///     e.to_string(),
///     "larger than 1 MiB, the limit for a test (is it a device or an endless stream?)"
/// );
/// # Ok::<(), std::io::Error>(())
/// ```
///
/// # Errors
/// The reader's own errors, and [`io::ErrorKind::FileTooLarge`] (see
/// [`too_large`]) when it holds more than `limit` bytes.
pub fn read_limited_from(reader: impl Read, limit: u64, what: &str) -> io::Result<Vec<u8>> {
    let mut bytes = Vec::new();
    reader
        .take(limit.saturating_add(1))
        .read_to_end(&mut bytes)?;
    if bytes.len() as u64 > limit {
        return Err(too_large(what, limit));
    }
    Ok(bytes)
}

/// Reads the file at `path` whole, but fails after `limit` bytes.
///
/// ```
/// use kreisel_inertia::io::read_limited;
/// let path = std::env::temp_dir().join(format!("kreisel-read-limited-{}", std::process::id()));
/// std::fs::write(&path, b"12345")?;
/// assert_eq!(read_limited(&path, 5, "a test")?, b"12345");
/// let e = read_limited(&path, 4, "a test").unwrap_err();
/// assert_eq!(e.kind(), std::io::ErrorKind::FileTooLarge);
/// std::fs::remove_file(&path)?;
/// # Ok::<(), std::io::Error>(())
/// ```
///
/// # Errors
/// The operating system's errors opening or reading the file, and
/// [`io::ErrorKind::FileTooLarge`] when it holds more than `limit` bytes.
pub fn read_limited(path: &Path, limit: u64, what: &str) -> io::Result<Vec<u8>> {
    read_limited_from(std::fs::File::open(path)?, limit, what)
}

/// Reads a text file (a robot description, a scene) whole as UTF-8, at
/// most [`TEXT_FILE_LIMIT`] bytes; `what` names the input in that error
/// (`a URDF file`).
///
/// ```
/// use kreisel_inertia::io::read_limited_text;
/// let path = std::env::temp_dir().join(format!("kreisel-read-text-{}", std::process::id()));
/// std::fs::write(&path, "<robot/>")?;
/// assert_eq!(read_limited_text(&path, "a URDF file")?, "<robot/>");
/// std::fs::write(&path, [0xff, 0xfe])?;
/// let e = read_limited_text(&path, "a URDF file").unwrap_err();
/// assert_eq!(e.kind(), std::io::ErrorKind::InvalidData);
/// std::fs::remove_file(&path)?;
/// # Ok::<(), std::io::Error>(())
/// ```
///
/// # Errors
/// As [`read_limited`], and [`io::ErrorKind::InvalidData`] for text that
/// is not UTF-8.
pub fn read_limited_text(path: &Path, what: &str) -> io::Result<String> {
    let bytes = read_limited(path, TEXT_FILE_LIMIT, what)?;
    String::from_utf8(bytes).map_err(|_| {
        io::Error::new(
            io::ErrorKind::InvalidData,
            "stream did not contain valid UTF-8",
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn limits_in_words() {
        assert_eq!(size_in_words(MESH_FILE_LIMIT), "1 GiB");
        assert_eq!(size_in_words(TEXT_FILE_LIMIT), "64 MiB");
        assert_eq!(size_in_words(1000), "1000 bytes");
    }

    #[test]
    #[cfg(unix)]
    fn an_endless_device_stops_at_the_limit() {
        let e = read_limited(Path::new("/dev/zero"), 1 << 20, "a mesh file").unwrap_err();
        assert_eq!(e.kind(), io::ErrorKind::FileTooLarge);
        assert!(e.to_string().starts_with("larger than 1 MiB"), "{e}");
    }
}
