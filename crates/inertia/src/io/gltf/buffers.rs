//! Where glTF bytes come from: the GLB container, `data:` URIs and files
//! next to the `.gltf`.
//!
//! The GLB container is split here rather than by `gltf::Glb::from_slice`,
//! which subtracts 12 from the header length unchecked (a debug-build panic
//! on a header length below 12), and never by `Glb::from_reader`, which
//! allocates the header's length before reading. Every length read from the
//! file is checked against the bytes actually present.

use std::borrow::Cow;
use std::io::Read as _;
use std::path::{Path, PathBuf};

use ::gltf::Document;
use ::gltf::buffer::Source as BufferSource;

use super::super::Source;
use crate::InertiaError;

/// The JSON text and the binary chunk of a glTF file.
pub(super) struct Container<'a> {
    /// The JSON document.
    pub json: &'a [u8],
    /// The GLB `BIN` chunk, if any.
    pub bin: Option<&'a [u8]>,
}

/// Splits a GLB file into its chunks; any other bytes are taken as JSON.
pub(super) fn split(bytes: &[u8]) -> Result<Container<'_>, String> {
    if !bytes.starts_with(b"glTF") {
        return Ok(Container {
            json: bytes,
            bin: None,
        });
    }
    let word = |b: &[u8], at: usize| -> Option<u32> {
        let w = b.get(at..at + 4)?;
        Some(u32::from_le_bytes([w[0], w[1], w[2], w[3]]))
    };
    let (Some(version), Some(length)) = (word(bytes, 4), word(bytes, 8)) else {
        return Err("GLB header is truncated (12 bytes are needed)".to_owned());
    };
    if version != 2 {
        return Err(format!("GLB version {version} is not supported (only 2)"));
    }
    if length < 12 {
        return Err(format!(
            "GLB header declares {length} bytes, less than the header itself"
        ));
    }
    let mut rest = bytes.get(12..length as usize).ok_or_else(|| {
        format!(
            "GLB header declares {length} bytes, but the file has {}",
            bytes.len()
        )
    })?;
    let (mut json, mut bin) = (None, None);
    while !rest.is_empty() {
        let (Some(len), Some(kind)) = (word(rest, 0), rest.get(4..8)) else {
            return Err("GLB chunk header is truncated".to_owned());
        };
        let end = (len as usize).saturating_add(8);
        let body = rest.get(8..end).ok_or_else(|| {
            format!(
                "GLB chunk '{}' declares {len} bytes, but only {} remain",
                kind.escape_ascii(),
                rest.len() - 8
            )
        })?;
        match kind {
            b"JSON" if json.is_none() => json = Some(body),
            b"BIN\0" if bin.is_none() => bin = Some(body),
            _ if json.is_none() => return Err("the first GLB chunk is not JSON".to_owned()),
            _ => {} // Unknown chunk types are skipped, as the specification asks.
        }
        rest = rest.get(end..).unwrap_or_default();
    }
    let json = json.ok_or("GLB file has no JSON chunk")?;
    Ok(Container { json, bin })
}

/// The bytes of every buffer of `doc`, each exactly its declared `byteLength`.
///
/// URIs are `data:…;base64,…` or relative file paths (percent-decoded,
/// resolved against the source's base directory); other schemes and
/// absolute paths are refused, nothing is ever fetched from a network.
pub(super) fn load<'a>(
    doc: &Document,
    bin: Option<&'a [u8]>,
    src: &Source<'_>,
) -> Result<Vec<Cow<'a, [u8]>>, InertiaError> {
    let mut buffers = Vec::new();
    for buffer in doc.buffers() {
        let i = buffer.index();
        let declared = buffer.length();
        let data: Cow<'a, [u8]> = match buffer.source() {
            BufferSource::Bin => Cow::Borrowed(bin.ok_or_else(|| {
                src.error(format!(
                    "buffer {i} has no URI and there is no GLB binary chunk"
                ))
            })?),
            BufferSource::Uri(uri) if uri.starts_with("data:") => {
                Cow::Owned(decode_data_uri(uri).map_err(|r| src.error(format!("buffer {i}: {r}")))?)
            }
            BufferSource::Uri(uri) => Cow::Owned(read_file(uri, declared, src)?),
        };
        if data.len() < declared {
            return Err(src.error(format!(
                "buffer {i} has {} bytes, but its byteLength is {declared}",
                data.len()
            )));
        }
        buffers.push(match data {
            Cow::Borrowed(b) => Cow::Borrowed(&b[..declared]),
            Cow::Owned(mut v) => {
                v.truncate(declared);
                Cow::Owned(v)
            }
        });
    }
    Ok(buffers)
}

/// Reads at most `declared` bytes (at most [`crate::io::MESH_FILE_LIMIT`])
/// of the file a relative URI names.
fn read_file(uri: &str, declared: usize, src: &Source<'_>) -> Result<Vec<u8>, InertiaError> {
    let path = relative_path(uri).map_err(|r| src.error(r))?;
    let base = src.base_dir().ok_or_else(|| {
        src.error(format!(
            "external buffer '{uri}' cannot be found without the file's directory"
        ))
    })?;
    let path = base.join(path);
    let io = |source| InertiaError::Io {
        path: path.clone(),
        source,
    };
    let limit = crate::io::MESH_FILE_LIMIT;
    if declared as u64 > limit {
        return Err(io(crate::io::too_large("a glTF buffer", limit)));
    }
    let file = std::fs::File::open(&path).map_err(io)?;
    let mut data = Vec::new();
    file.take(declared as u64)
        .read_to_end(&mut data)
        .map_err(io)?;
    Ok(data)
}

/// The relative file path a buffer URI names.
fn relative_path(uri: &str) -> Result<PathBuf, String> {
    let scheme = uri
        .split_once(':')
        .is_some_and(|(s, _)| !s.contains('/') && !s.is_empty());
    if scheme || uri.starts_with('/') || uri.starts_with('\\') || uri.is_empty() {
        return Err(format!(
            "buffer URI '{uri}' is not a relative file path (only those and data: URIs are read)"
        ));
    }
    let file = uri.split(['#', '?']).next().unwrap_or(uri);
    let bytes =
        percent_decode(file).ok_or_else(|| format!("buffer URI '{uri}' has a bad % escape"))?;
    let path = String::from_utf8(bytes).map_err(|_| format!("buffer URI '{uri}' is not UTF-8"))?;
    Ok(Path::new(&path).to_path_buf())
}

/// Decodes `%XX` escapes.
fn percent_decode(s: &str) -> Option<Vec<u8>> {
    let mut out = Vec::with_capacity(s.len());
    let mut bytes = s.bytes();
    while let Some(b) = bytes.next() {
        if b == b'%' {
            let hi = char::from(bytes.next()?).to_digit(16)?;
            let lo = char::from(bytes.next()?).to_digit(16)?;
            out.push((hi * 16 + lo) as u8);
        } else {
            out.push(b);
        }
    }
    Some(out)
}

/// The bytes of a `data:[<media type>];base64,<data>` URI.
fn decode_data_uri(uri: &str) -> Result<Vec<u8>, String> {
    let (head, data) = uri
        .split_once(',')
        .ok_or("data URI has no ',' before its data")?;
    if !head.ends_with(";base64") {
        return Err("data URI is not base64-encoded".to_owned());
    }
    decode_base64(data)
}

/// Decodes standard or URL-safe base64, with or without `=` padding.
fn decode_base64(text: &str) -> Result<Vec<u8>, String> {
    let text = text
        .strip_suffix("==")
        .or_else(|| text.strip_suffix('='))
        .unwrap_or(text);
    let mut out = Vec::with_capacity(text.len() / 4 * 3 + 2);
    let (mut acc, mut bits) = (0u32, 0u32);
    for (i, c) in text.bytes().enumerate() {
        let v = match c {
            b'A'..=b'Z' => c - b'A',
            b'a'..=b'z' => c - b'a' + 26,
            b'0'..=b'9' => c - b'0' + 52,
            b'+' | b'-' => 62,
            b'/' | b'_' => 63,
            _ => {
                return Err(format!(
                    "invalid base64 character '{}' at position {i}",
                    c.escape_ascii()
                ));
            }
        };
        acc = (acc << 6) | u32::from(v);
        bits += 6;
        if bits >= 8 {
            bits -= 8;
            out.push((acc >> bits) as u8);
            acc &= (1 << bits) - 1;
        }
    }
    if bits >= 6 {
        return Err("base64 data ends with a dangling character".to_owned());
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_round_trips_known_vectors() {
        for (text, bytes) in [
            ("", &b""[..]),
            ("Zg==", b"f"),
            ("Zm8=", b"fo"),
            ("Zm9v", b"foo"),
            ("Zm9vYg", b"foob"),
            ("Zm9vYmFy", b"foobar"),
            ("//79", &[0xff, 0xfe, 0xfd][..]),
            ("__79", &[0xff, 0xfe, 0xfd][..]),
        ] {
            assert_eq!(decode_base64(text).as_deref(), Ok(bytes), "{text}");
        }
        assert!(decode_base64("Zm9v!").is_err());
        assert!(decode_base64("Zm9vY").is_err());
    }

    #[test]
    fn uris_outside_relative_files_are_refused() {
        for uri in [
            "http://x/a.bin",
            "file:///a.bin",
            "/abs/a.bin",
            "C:a.bin",
            "",
        ] {
            assert!(relative_path(uri).is_err(), "{uri}");
        }
        assert_eq!(relative_path("a%20b.bin"), Ok(PathBuf::from("a b.bin")));
        assert_eq!(relative_path("../x/a.bin"), Ok(PathBuf::from("../x/a.bin")));
        assert!(relative_path("a%2.bin").is_err());
        assert_eq!(relative_path("a.bin#frag"), Ok(PathBuf::from("a.bin")));
    }

    #[test]
    fn glb_lengths_are_checked() {
        assert!(split(b"glTF").is_err());
        let mut glb = b"glTF\x02\0\0\0\x04\0\0\0".to_vec();
        assert!(split(&glb).is_err()); // declared length below the header
        glb[8] = 200;
        assert!(split(&glb).is_err()); // declared length past the file
        glb[8] = 20;
        glb.extend_from_slice(b"\xff\0\0\0JSON");
        assert!(split(&glb).is_err()); // chunk length past the file
    }
}
