//! Test helpers shared by the unit tests of [`super`] and its submodules:
//! encoding, decoding back to per-frame canvases, colour-error measures,
//! and the colour arithmetic of the synthetic scenes.

use gif::{ColorOutput, DecodeOptions, DisposalMethod, Repeat};

use super::{GifStats, write_gif};

/// Splits `0x00RRGGBB` into `[r, g, b]`.
pub(super) fn channels(c: u32) -> [i32; 3] {
    [
        ((c >> 16) & 0xFF) as i32,
        ((c >> 8) & 0xFF) as i32,
        (c & 0xFF) as i32,
    ]
}

/// Packs `[r, g, b]`, rounded and clamped to `0..=255`, into `0x00RRGGBB`.
pub(super) fn pack(rgb: [f64; 3]) -> u32 {
    let ch = |v: f64| v.round().clamp(0.0, 255.0) as u32;
    (ch(rgb[0]) << 16) | (ch(rgb[1]) << 8) | ch(rgb[2])
}

/// One decoded frame: its rectangle, timing and RGBA pixels.
pub(super) struct DecodedFrame {
    pub(super) left: usize,
    pub(super) top: usize,
    pub(super) width: usize,
    pub(super) height: usize,
    pub(super) delay: u16,
    pub(super) dispose: DisposalMethod,
    pub(super) transparent: Option<u8>,
    pub(super) rgba: Vec<u8>,
}

pub(super) struct Decoded {
    pub(super) width: usize,
    pub(super) height: usize,
    pub(super) repeat: Repeat,
    pub(super) palette_len: usize,
    pub(super) frames: Vec<DecodedFrame>,
    /// Canvas after each frame, `0x00RRGGBB`.
    pub(super) canvases: Vec<Vec<u32>>,
}

pub(super) fn decode(bytes: &[u8]) -> Decoded {
    let mut opts = DecodeOptions::new();
    opts.set_color_output(ColorOutput::RGBA);
    let mut dec = opts.read_info(bytes).expect("header decodes");
    let width = usize::from(dec.width());
    let height = usize::from(dec.height());
    let palette_len = dec.global_palette().map_or(0, |p| p.len() / 3);
    let mut canvas = vec![0u32; width * height];
    let mut frames = Vec::new();
    let mut canvases = Vec::new();
    while let Some(f) = dec.read_next_frame().expect("frame decodes") {
        let df = DecodedFrame {
            left: usize::from(f.left),
            top: usize::from(f.top),
            width: usize::from(f.width),
            height: usize::from(f.height),
            delay: f.delay,
            dispose: f.dispose,
            transparent: f.transparent,
            rgba: f.buffer.to_vec(),
        };
        assert!(df.left + df.width <= width && df.top + df.height <= height);
        assert_eq!(df.rgba.len(), df.width * df.height * 4);
        for y in 0..df.height {
            for x in 0..df.width {
                let p = &df.rgba[(y * df.width + x) * 4..][..4];
                if p[3] != 0 {
                    canvas[(df.top + y) * width + df.left + x] =
                        (u32::from(p[0]) << 16) | (u32::from(p[1]) << 8) | u32::from(p[2]);
                }
            }
        }
        canvases.push(canvas.clone());
        frames.push(df);
    }
    Decoded {
        width,
        height,
        repeat: dec.repeat(),
        palette_len,
        frames,
        canvases,
    }
}

pub(super) fn channel_err(a: u32, b: u32) -> i32 {
    let (a, b) = (channels(a), channels(b));
    (0..3).map(|k| (a[k] - b[k]).abs()).max().unwrap_or(0)
}

/// Whether the 3×3 neighbourhood of (x, y) is one flat colour.
fn is_flat(img: &[u32], w: usize, h: usize, x: usize, y: usize) -> bool {
    if x == 0 || y == 0 || x + 1 >= w || y + 1 >= h {
        return false;
    }
    let c = img[y * w + x];
    (y - 1..=y + 1).all(|yy| (x - 1..=x + 1).all(|xx| img[yy * w + xx] == c))
}

/// Max channel error over flat pixels and over all pixels, plus mean error.
pub(super) fn compare(frames: &[Vec<u32>], dec: &Decoded) -> (i32, i32, f64, usize) {
    let (w, h) = (dec.width, dec.height);
    let (mut flat_max, mut all_max, mut sum, mut flat_n) = (0, 0, 0u64, 0usize);
    for (src, got) in frames.iter().zip(&dec.canvases) {
        for y in 0..h {
            for x in 0..w {
                let e = channel_err(src[y * w + x], got[y * w + x]);
                all_max = all_max.max(e);
                sum += e as u64;
                if is_flat(src, w, h, x, y) {
                    flat_max = flat_max.max(e);
                    flat_n += 1;
                }
            }
        }
    }
    let mean = sum as f64 / (frames.len() * w * h) as f64;
    (flat_max, all_max, mean, flat_n)
}

pub(super) fn encode(w: u16, h: u16, frames: &[Vec<u32>], delay: u16) -> (Vec<u8>, GifStats) {
    let mut out = Vec::new();
    let stats = write_gif(&mut out, w, h, frames, delay).expect("encodes");
    assert_eq!(stats.bytes_written, out.len() as u64);
    (out, stats)
}
