//! The streaming encoder: frames go to the GIF as they are pushed, so a GIF
//! of any length is written in bounded memory.
//!
//! A GIF's global palette precedes its first frame, so the palette cannot
//! depend on frames not yet rendered. [`GifStream`] holds back the first
//! frames, up to a budget of pixels ([`PALETTE_WINDOW_PIXELS`] by default,
//! 8 M pixels: 40 frames at the demo's 640 × 320), builds the palette from
//! them (step 1 of [`super`]), writes them, and from then on maps and writes
//! each frame as it arrives (steps 2 and 3). Colours that first appear later
//! map to the nearest palette colour. For the demo the first seconds show every colour of
//! the scene (background, chart, text, the handle's shading turning through
//! all its faces); `tests/dzhanibekov.rs` measures the error of this palette
//! against one built from all frames of a run.

use std::borrow::Cow;
use std::io::Write;

use gif::{DisposalMethod, Encoder, Frame, Repeat};

use super::palette::{Palette, from_rgba, rgba};
use super::{GifError, GifStats, MAX_PALETTE_COLORS, Rect, changed_rect, crop_changes, to_u16};

/// Pixels held back (4 bytes each) to build the palette from: 8 M, 32 MB.
pub const PALETTE_WINDOW_PIXELS: usize = 8 << 20;

/// A writer that counts the bytes that pass through it and, after its
/// first error (which it passes on), swallows everything: the `gif`
/// encoder writes its trailer when dropped and panics if that fails, and
/// a failed stream is dropped (its temporary file removed by the caller).
struct Counting<W> {
    inner: W,
    bytes: u64,
    failed: bool,
}

impl<W: Write> Write for Counting<W> {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        if self.failed {
            return Ok(buf.len());
        }
        match self.inner.write(buf) {
            Ok(n) => {
                self.bytes += n as u64;
                Ok(n)
            }
            Err(e) => {
                self.failed = true;
                Err(e)
            }
        }
    }

    fn flush(&mut self) -> std::io::Result<()> {
        if self.failed {
            return Ok(());
        }
        self.inner.flush().inspect_err(|_| self.failed = true)
    }
}

/// The encoder once the palette is known.
struct Active<W: Write> {
    encoder: Encoder<Counting<W>>,
    palette: Palette,
    /// The previous frame's pixels (empty before the first frame) and indices.
    prev_src: Vec<u32>,
    prev: Vec<u8>,
    cur: Vec<u8>,
    crop: Vec<u8>,
    transparent_index: u8,
    palette_colors: usize,
}

/// Where the stream is: frames held back for the palette, or encoding.
enum State<W: Write> {
    /// The frames held back, one after the other, as RGBA bytes.
    Collecting {
        out: W,
        held: Vec<u8>,
    },
    Encoding(Box<Active<W>>),
    /// After an error: nothing more is written.
    Failed,
}

/// An animated GIF written frame by frame (module docs).
///
/// ```text
/// memory ≈ palette window (≤ 8 M pixels × 4 B) + 7 bytes per pixel of one frame
/// ```
pub struct GifStream<W: Write> {
    width: u16,
    height: u16,
    npix: usize,
    delay: u16,
    window_pixels: usize,
    state: State<W>,
    frames: usize,
    encoded_pixels: u64,
    unchanged_frames: usize,
}

impl<W: Write> GifStream<W> {
    /// A stream of `width × height` frames shown `delay_centiseconds` each,
    /// whose palette is built from the first frames up to `window_pixels`
    /// pixels in all (at least one frame; `usize::MAX`: all frames, held in
    /// memory until [`GifStream::finish`]).
    ///
    /// # Errors
    /// [`GifError::ZeroSize`] for a zero dimension.
    pub fn new(
        out: W,
        width: u16,
        height: u16,
        delay_centiseconds: u16,
        window_pixels: usize,
    ) -> Result<Self, GifError> {
        if width == 0 || height == 0 {
            return Err(GifError::ZeroSize { width, height });
        }
        Ok(GifStream {
            width,
            height,
            npix: usize::from(width) * usize::from(height),
            delay: delay_centiseconds,
            window_pixels,
            state: State::Collecting {
                out,
                held: Vec::new(),
            },
            frames: 0,
            encoded_pixels: 0,
            unchanged_frames: 0,
        })
    }

    /// Frames held back for the palette (0 once encoding has started).
    pub fn held_frames(&self) -> usize {
        match &self.state {
            State::Collecting { held, .. } => held.len() / (4 * self.npix),
            _ => 0,
        }
    }

    /// Adds one frame of `width × height` pixels `0x00RRGGBB`.
    ///
    /// # Errors
    /// [`GifError::WrongFrameLength`] for a frame of the wrong size (nothing
    /// of it is written), [`GifError::Encoding`] or [`GifError::Io`] from
    /// the encoder and the output; after one of those the stream is dead.
    pub fn push(&mut self, frame: &[u32]) -> Result<(), GifError> {
        if frame.len() != self.npix {
            return Err(GifError::WrongFrameLength {
                index: self.frames,
                expected: self.npix,
                found: frame.len(),
            });
        }
        self.frames += 1;
        match &mut self.state {
            State::Collecting { held, .. } => {
                held.extend(frame.iter().flat_map(|&px| rgba(px)));
                if held.len() / 4 >= self.window_pixels {
                    self.start()?;
                }
                Ok(())
            }
            State::Encoding(active) => {
                let r = encode(active, frame, self.width, self.delay);
                self.account(r)
            }
            State::Failed => Err(dead()),
        }
    }

    /// Writes the frames held back and the trailer, flushes the output and
    /// returns it with the statistics.
    ///
    /// # Errors
    /// [`GifError::NoFrames`] if no frame was pushed, else as [`GifStream::push`].
    pub fn finish(mut self) -> Result<(W, GifStats), GifError> {
        if self.frames == 0 {
            return Err(GifError::NoFrames);
        }
        if matches!(self.state, State::Collecting { .. }) {
            self.start()?;
        }
        let State::Encoding(active) = std::mem::replace(&mut self.state, State::Failed) else {
            return Err(dead());
        };
        let Active {
            encoder,
            transparent_index,
            palette_colors,
            ..
        } = *active;
        let mut counting = encoder.into_inner()?;
        counting.flush()?;
        Ok((
            counting.inner,
            GifStats {
                bytes_written: counting.bytes,
                frames: self.frames,
                palette_colors,
                transparent_index,
                encoded_pixels: self.encoded_pixels,
                unchanged_frames: self.unchanged_frames,
            },
        ))
    }

    /// Builds the palette from the frames held back, starts the encoder and
    /// writes those frames.
    fn start(&mut self) -> Result<(), GifError> {
        let State::Collecting { out, held } = std::mem::replace(&mut self.state, State::Failed)
        else {
            return Err(dead());
        };
        let palette = Palette::build(&held, self.npix);
        let palette_colors = palette.len();
        let transparent_index = u8::try_from(palette_colors).map_err(|_| GifError::Encoding {
            message: format!(
                "palette has {palette_colors} colours, at most {MAX_PALETTE_COLORS} allowed"
            ),
        })?;
        let mut table = palette.table_rgb.clone();
        table.extend_from_slice(&[0, 0, 0]); // the transparent entry
        let counting = Counting {
            inner: out,
            bytes: 0,
            failed: false,
        };
        let mut encoder = Encoder::new(counting, self.width, self.height, &table)?;
        encoder.set_repeat(Repeat::Infinite)?;
        let mut active = Box::new(Active {
            encoder,
            palette,
            prev_src: Vec::new(),
            prev: vec![0u8; self.npix],
            cur: vec![0u8; self.npix],
            crop: Vec::new(),
            transparent_index,
            palette_colors,
        });
        let mut frame = Vec::with_capacity(self.npix);
        for f in held.chunks_exact(4 * self.npix) {
            frame.clear();
            frame.extend(f.chunks_exact(4).map(from_rgba));
            let r = encode(&mut active, &frame, self.width, self.delay);
            self.account(r)?;
        }
        self.state = State::Encoding(active);
        Ok(())
    }

    /// Adds the outcome of one encoded frame to the statistics.
    fn account(&mut self, r: Result<(u64, bool), GifError>) -> Result<(), GifError> {
        match r {
            Ok((pixels, unchanged)) => {
                self.encoded_pixels += pixels;
                self.unchanged_frames += usize::from(unchanged);
                Ok(())
            }
            Err(e) => {
                self.state = State::Failed;
                Err(e)
            }
        }
    }
}

/// The error of a stream that already failed.
fn dead() -> GifError {
    GifError::Encoding {
        message: "the GIF stream failed earlier".to_owned(),
    }
}

/// Maps and writes one frame (step 3 of [`super`]): the first in full, the
/// others as the changed rectangle with unchanged pixels transparent.
/// Returns the pixels written and whether the frame was unchanged.
fn encode<W: Write>(
    a: &mut Active<W>,
    frame: &[u32],
    width: u16,
    delay: u16,
) -> Result<(u64, bool), GifError> {
    let w = usize::from(width);
    a.palette.map_frame(frame, &a.prev_src, &a.prev, &mut a.cur);
    let mut unchanged = false;
    let (rect, transparent) = if a.prev_src.is_empty() {
        a.crop.clear();
        a.crop.extend_from_slice(&a.cur);
        let full = Rect {
            x0: 0,
            y0: 0,
            x1: w,
            y1: a.cur.len() / w,
        };
        (full, None)
    } else {
        let rect = match changed_rect(&a.prev, &a.cur, w) {
            Some(r) => {
                crop_changes(&a.prev, &a.cur, w, r, a.transparent_index, &mut a.crop);
                r
            }
            None => {
                unchanged = true;
                a.crop.clear();
                a.crop.push(a.transparent_index);
                Rect {
                    x0: 0,
                    y0: 0,
                    x1: 1,
                    y1: 1,
                }
            }
        };
        (rect, Some(a.transparent_index))
    };
    let gif_frame = Frame {
        delay,
        dispose: DisposalMethod::Keep,
        transparent,
        left: to_u16(rect.x0)?,
        top: to_u16(rect.y0)?,
        width: to_u16(rect.x1 - rect.x0)?,
        height: to_u16(rect.y1 - rect.y0)?,
        buffer: Cow::Borrowed(&a.crop[..]),
        ..Frame::default()
    };
    let pixels = u64::from(gif_frame.width) * u64::from(gif_frame.height);
    a.encoder.write_frame(&gif_frame)?;
    std::mem::swap(&mut a.prev, &mut a.cur);
    a.prev_src.clear();
    a.prev_src.extend_from_slice(frame);
    Ok((pixels, unchanged))
}

#[cfg(test)]
mod tests {
    use super::super::test_scenes::{CURVES, PANEL, TEXT};
    use super::super::test_support::decode;
    use super::*;

    /// A long stream holds at most its window of frames; the later frames
    /// are written as they come and decode to what was pushed (their
    /// colours are in the palette of the first frames).
    #[test]
    fn memory_is_the_window_whatever_the_length() {
        let (w, h) = (24usize, 10usize);
        let window = 5 * w * h;
        let mut stream = GifStream::new(Vec::new(), w as u16, h as u16, 3, window).unwrap();
        let mut frames = Vec::new();
        for t in 0..500 {
            let mut f = vec![PANEL; w * h];
            f[t % (w * h)] = CURVES[t % 3];
            f[(7 * t) % (w * h)] = TEXT;
            stream.push(&f).unwrap();
            assert!(stream.held_frames() < 5, "{t}");
            frames.push(f);
        }
        let (bytes, stats) = stream.finish().unwrap();
        assert_eq!(stats.frames, 500);
        assert_eq!(stats.bytes_written, bytes.len() as u64);
        let dec = decode(&bytes);
        assert_eq!(dec.canvases, frames);
    }

    /// A colour first seen after the palette is built maps to the nearest
    /// palette colour; a short stream builds its palette at `finish`.
    #[test]
    fn late_colours_map_to_the_nearest_and_short_streams_work() {
        let (w, h) = (4usize, 4usize);
        let mut stream = GifStream::new(Vec::new(), w as u16, h as u16, 3, w * h).unwrap();
        stream.push(&[PANEL; 16]).unwrap();
        stream.push(&[TEXT; 16]).unwrap();
        stream.push(&[0x00FE_FEFE; 16]).unwrap(); // not in the palette
        let (bytes, _) = stream.finish().unwrap();
        let dec = decode(&bytes);
        assert_eq!(dec.canvases[2], vec![PANEL; 16]);
        let mut short = GifStream::new(Vec::new(), 2, 2, 3, usize::MAX).unwrap();
        short.push(&[TEXT; 4]).unwrap();
        assert_eq!(short.held_frames(), 1);
        let (bytes, stats) = short.finish().unwrap();
        assert_eq!((stats.frames, decode(&bytes).canvases[0][0]), (1, TEXT));
    }

    /// Bad frames are refused without killing the stream; no frames, a zero
    /// size and a failing writer are errors, never panics.
    #[test]
    fn errors_are_reported() {
        let mut stream = GifStream::new(Vec::new(), 2, 2, 3, 8).unwrap();
        assert!(matches!(
            stream.push(&[0; 3]),
            Err(GifError::WrongFrameLength {
                index: 0,
                expected: 4,
                found: 3
            })
        ));
        stream.push(&[0; 4]).unwrap();
        assert_eq!(stream.finish().unwrap().1.frames, 1);
        let empty = GifStream::new(Vec::new(), 2, 2, 3, 8).unwrap();
        assert!(matches!(empty.finish(), Err(GifError::NoFrames)));
        assert!(matches!(
            GifStream::new(Vec::new(), 0, 2, 3, 8),
            Err(GifError::ZeroSize { .. })
        ));
        struct Full;
        impl Write for Full {
            fn write(&mut self, _: &[u8]) -> std::io::Result<usize> {
                Err(std::io::Error::other("disk full"))
            }
            fn flush(&mut self) -> std::io::Result<()> {
                Ok(())
            }
        }
        let mut stream = GifStream::new(Full, 2, 2, 3, 4).unwrap();
        assert!(matches!(stream.push(&[0; 4]), Err(GifError::Io(_))));
        assert!(stream.push(&[0; 4]).is_err());
        assert!(stream.finish().is_err());
    }
}
