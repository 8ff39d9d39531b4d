//! Animated-GIF writer for frames produced by the software renderer.
//!
//! Frames arrive as row-major `0x00RRGGBB` pixels (the top byte is ignored).
//! The writer produces one looping GIF with a single global palette.
//! [`GifStream`] takes the frames one at a time and writes them as they come
//! (bounded memory for any number of frames; its palette comes from the
//! first frames, see [`stream`]); [`write_gif`] encodes a slice of frames
//! with the palette built from all of them.
//!
//! The bytes (LZW, blocks, the looping extension) are the `gif` crate's;
//! the palette is `color_quant`'s NeuQuant, the quantiser `gif` uses itself.
//!
//! 1. **Palette.** If the frames hold at most [`MAX_PALETTE_COLORS`]
//!    distinct colours they are used as they are; otherwise NeuQuant learns
//!    that many from about 100 000 of their pixels (its own sampling; about
//!    0.2 s). One further index is reserved for transparency.
//! 2. **Mapping.** Each pixel takes its exact entry or NeuQuant's nearest;
//!    a pixel equal to its left neighbour or to itself in the previous
//!    frame takes that pixel's index without asking.
//! 3. **Frame differencing.** After the first frame, pixels whose palette
//!    index did not change become the transparent index and the frame is
//!    cropped to the bounding box of changed pixels (disposal `Keep`). A frame
//!    without changes is still written, as a 1×1 transparent frame, so the
//!    timing is kept.
//!
//! Steps 1 and 2 live in the private submodule `palette`, the encoder and
//! step 3 in [`stream`], the round-trip tests in `round_trip_tests`; this
//! file holds the errors, the one-call [`write_gif`] and the rectangle
//! helpers of step 3.

mod palette;
#[cfg(test)]
mod round_trip_tests;
pub mod stream;
#[cfg(test)]
mod test_scenes;
#[cfg(test)]
mod test_support;

use std::io::Write;

pub use stream::GifStream;

/// Maximum number of colours in the global palette; one more index is reserved for transparency.
pub const MAX_PALETTE_COLORS: usize = 255;

/// Errors reported by [`write_gif`].
#[derive(Debug, thiserror::Error)]
pub enum GifError {
    /// The frame list was empty.
    #[error("no frames to encode")]
    NoFrames,
    /// The width or the height was zero.
    #[error("image size {width}x{height} has a zero dimension")]
    ZeroSize {
        /// Requested width in pixels.
        width: u16,
        /// Requested height in pixels.
        height: u16,
    },
    /// A frame did not hold exactly `width × height` pixels.
    #[error("frame {index} has {found} pixels, expected {expected}")]
    WrongFrameLength {
        /// Zero-based index of the offending frame.
        index: usize,
        /// Expected number of pixels (`width × height`).
        expected: usize,
        /// Number of pixels the frame actually had.
        found: usize,
    },
    /// The GIF encoder rejected the data.
    #[error("GIF encoding failed: {message}")]
    Encoding {
        /// Description of the failure.
        message: String,
    },
    /// Writing to the output failed.
    #[error("I/O error while writing GIF: {0}")]
    Io(#[from] std::io::Error),
}

impl From<gif::EncodingError> for GifError {
    fn from(err: gif::EncodingError) -> Self {
        match err {
            gif::EncodingError::Io(io) => GifError::Io(io),
            other => GifError::Encoding {
                message: other.to_string(),
            },
        }
    }
}

/// Summary of a successful [`write_gif`] call.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct GifStats {
    /// Number of bytes written to the output.
    pub bytes_written: u64,
    /// Number of frames written (equals the number of input frames).
    pub frames: usize,
    /// Number of colours in the global palette, not counting the transparent index.
    pub palette_colors: usize,
    /// Palette index used for "unchanged since the previous frame".
    pub transparent_index: u8,
    /// Sum of the areas of all written frame rectangles, in pixels.
    pub encoded_pixels: u64,
    /// Number of frames identical to their predecessor (written as 1×1 transparent frames).
    pub unchanged_frames: usize,
}

/// Encodes `frames` as an infinitely looping animated GIF and writes it to `out`.
///
/// Every frame must hold `width × height` pixels in row-major order, each
/// pixel `0x00RRGGBB` (the top byte is ignored). Every frame is shown for
/// `delay_centiseconds` hundredths of a second. The palette is built from
/// all frames ([`GifStream`] with an unlimited palette window); the output
/// is flushed at the end.
///
/// # Errors
///
/// [`GifError::NoFrames`], [`GifError::ZeroSize`] and
/// [`GifError::WrongFrameLength`] for bad input (checked before anything is
/// written), [`GifError::Encoding`] if the encoder rejects the data and
/// [`GifError::Io`] if writing to `out` fails.
pub fn write_gif<W: Write, F: AsRef<[u32]>>(
    out: W,
    width: u16,
    height: u16,
    frames: &[F],
    delay_centiseconds: u16,
) -> Result<GifStats, GifError> {
    validate(width, height, frames)?;
    let mut stream = GifStream::new(out, width, height, delay_centiseconds, usize::MAX)?;
    for f in frames {
        stream.push(f.as_ref())?;
    }
    Ok(stream.finish()?.1)
}

/// Checks the arguments and returns the number of pixels per frame.
fn validate<F: AsRef<[u32]>>(width: u16, height: u16, frames: &[F]) -> Result<usize, GifError> {
    if width == 0 || height == 0 {
        return Err(GifError::ZeroSize { width, height });
    }
    if frames.is_empty() {
        return Err(GifError::NoFrames);
    }
    let expected = usize::from(width)
        .checked_mul(usize::from(height))
        .ok_or_else(|| GifError::Encoding {
            message: format!("{width}x{height} pixels do not fit in memory"),
        })?;
    for (index, f) in frames.iter().enumerate() {
        let found = f.as_ref().len();
        if found != expected {
            return Err(GifError::WrongFrameLength {
                index,
                expected,
                found,
            });
        }
    }
    Ok(expected)
}

fn to_u16(v: usize) -> Result<u16, GifError> {
    u16::try_from(v).map_err(|_| GifError::Encoding {
        message: format!("frame coordinate {v} exceeds 65535"),
    })
}

/// Half-open rectangle `[x0, x1) × [y0, y1)` in pixels.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Rect {
    x0: usize,
    y0: usize,
    x1: usize,
    y1: usize,
}

/// Bounding box of the pixels whose index differs between `prev` and `cur`.
fn changed_rect(prev: &[u8], cur: &[u8], width: usize) -> Option<Rect> {
    let mut rect: Option<Rect> = None;
    for (y, (p, c)) in prev
        .chunks_exact(width)
        .zip(cur.chunks_exact(width))
        .enumerate()
    {
        if p == c {
            continue;
        }
        let first = p.iter().zip(c).position(|(a, b)| a != b);
        let last = p.iter().zip(c).rposition(|(a, b)| a != b);
        if let (Some(first), Some(last)) = (first, last) {
            rect = Some(match rect {
                None => Rect {
                    x0: first,
                    y0: y,
                    x1: last + 1,
                    y1: y + 1,
                },
                Some(r) => Rect {
                    x0: r.x0.min(first),
                    y0: r.y0,
                    x1: r.x1.max(last + 1),
                    y1: y + 1,
                },
            });
        }
    }
    rect
}

/// Copies `rect` of `cur` into `out`, with pixels equal in `prev` replaced by `transparent`.
fn crop_changes(
    prev: &[u8],
    cur: &[u8],
    width: usize,
    rect: Rect,
    transparent: u8,
    out: &mut Vec<u8>,
) {
    out.clear();
    for y in rect.y0..rect.y1 {
        let span = y * width + rect.x0..y * width + rect.x1;
        let (p, c) = (&prev[span.clone()], &cur[span]);
        out.extend(
            p.iter()
                .zip(c)
                .map(|(&p, &c)| if p == c { transparent } else { c }),
        );
    }
}

#[cfg(test)]
mod tests {
    use super::test_scenes::{CURVES, PANEL, TEXT};
    use super::test_support::{decode, encode};
    use super::*;

    #[test]
    fn unchanged_frames_become_one_transparent_pixel() {
        let (w, h) = (40usize, 30usize);
        let a: Vec<u32> = (0..w * h)
            .map(|i| if i % 7 == 0 { TEXT } else { PANEL })
            .collect();
        let mut b = a.clone();
        b[5 * w + 9] = CURVES[0];
        b[12 * w + 3] = CURVES[1];
        let frames = vec![a.clone(), a.clone(), b.clone(), b.clone(), a.clone()];
        let (bytes, stats) = encode(w as u16, h as u16, &frames, 10);
        assert_eq!(stats.unchanged_frames, 2);
        let dec = decode(&bytes);
        assert_eq!(dec.frames.len(), 5);
        let f1 = &dec.frames[1];
        assert_eq!((f1.width, f1.height), (1, 1));
        assert_eq!(f1.rgba[3], 0, "1x1 frame must be transparent");
        let f2 = &dec.frames[2];
        assert_eq!((f2.left, f2.top, f2.width, f2.height), (3, 5, 7, 8));
        for (src, got) in frames.iter().zip(&dec.canvases) {
            assert_eq!(src, got, "few colours must round-trip exactly");
        }
        assert_eq!(stats.palette_colors, 4);
    }

    #[test]
    fn top_byte_is_ignored_and_tiny_images_work() {
        let frames = vec![vec![0xFF12_3456u32], vec![0x0012_3456], vec![0xAB65_4321]];
        let (bytes, stats) = encode(1, 1, &frames, 0);
        assert_eq!(stats.unchanged_frames, 1);
        let dec = decode(&bytes);
        let got: Vec<u32> = dec.canvases.iter().map(|c| c[0]).collect();
        assert_eq!(got, vec![0x123456, 0x123456, 0x654321]);
    }

    #[test]
    fn bad_input_is_reported() {
        let good = vec![0u32; 6];
        let frames = vec![good.clone(), good.clone(), vec![0u32; 5]];
        match write_gif(Vec::new(), 3, 2, &frames, 5) {
            Err(GifError::WrongFrameLength {
                index,
                expected,
                found,
            }) => assert_eq!((index, expected, found), (2, 6, 5)),
            other => panic!("unexpected {other:?}"),
        }
        let none: Vec<Vec<u32>> = Vec::new();
        assert!(matches!(
            write_gif(Vec::new(), 3, 2, &none, 5),
            Err(GifError::NoFrames)
        ));
        assert!(matches!(
            write_gif(Vec::new(), 0, 2, std::slice::from_ref(&good), 5),
            Err(GifError::ZeroSize {
                width: 0,
                height: 2
            })
        ));
        assert!(matches!(
            write_gif(Vec::new(), 3, 0, std::slice::from_ref(&good), 5),
            Err(GifError::ZeroSize { .. })
        ));
        // Nothing is written on bad input.
        let mut out = Vec::new();
        assert!(write_gif(&mut out, 3, 2, &[vec![0u32; 7]], 5).is_err());
        assert!(out.is_empty());
    }

    struct FailingWriter;

    impl Write for FailingWriter {
        fn write(&mut self, _: &[u8]) -> std::io::Result<usize> {
            Err(std::io::Error::other("disk full"))
        }
        fn flush(&mut self) -> std::io::Result<()> {
            Ok(())
        }
    }

    #[test]
    fn io_errors_are_reported_not_panicked() {
        let frames = vec![vec![PANEL; 4 * 4], vec![TEXT; 4 * 4]];
        match write_gif(FailingWriter, 4, 4, &frames, 5) {
            Err(GifError::Io(e)) => assert_eq!(e.to_string(), "disk full"),
            other => panic!("unexpected {other:?}"),
        }
    }

    #[test]
    fn changed_rect_bounds_differences() {
        let w = 5;
        let prev = vec![0u8; w * 4];
        assert_eq!(changed_rect(&prev, &prev, w), None);
        let mut cur = prev.clone();
        cur[w + 3] = 1;
        cur[3 * w + 1] = 2;
        let r = changed_rect(&prev, &cur, w);
        assert_eq!(
            r,
            Some(Rect {
                x0: 1,
                y0: 1,
                x1: 4,
                y1: 4
            })
        );
        let mut out = Vec::new();
        if let Some(r) = r {
            crop_changes(&prev, &cur, w, r, 9, &mut out);
        }
        assert_eq!(out, vec![9, 9, 1, 9, 9, 9, 2, 9, 9]);
    }
}
