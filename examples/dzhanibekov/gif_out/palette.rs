//! The global palette (step 1 of the overview in [`super`]) and the mapping
//! of pixels to it (step 2), on `color_quant`'s NeuQuant, the quantiser the
//! `gif` crate itself uses (`Frame::from_rgba_speed`): frames with at most
//! [`MAX_PALETTE_COLORS`] colours keep them exactly, others get a palette
//! learnt by NeuQuant from the pixels held back.
//!
//! Mapping asks NeuQuant for each pixel whose colour differs from the
//! pixel before it in the row and from the same pixel in the previous
//! frame; the demo's frames are mostly flat or unchanged, so few pixels ask.

use std::borrow::Cow;
use std::collections::HashMap;

use color_quant::NeuQuant;

use super::MAX_PALETTE_COLORS;

/// Pixels NeuQuant learns from (about), which bounds the time it takes
/// (some 2 µs a pixel here): it samples one pixel in up to 30 of those it is
/// given, and is given every frame held back, or every second, third, …
/// when they hold more than 30 times this.
const LEARNING_PIXELS: usize = 100_000;

/// `0x00RRGGBB` as the opaque RGBA bytes NeuQuant reads.
pub(super) fn rgba(px: u32) -> [u8; 4] {
    let [_, r, g, b] = px.to_be_bytes();
    [r, g, b, 0xFF]
}

/// The first three of RGBA bytes as `0x00RRGGBB`.
pub(super) fn from_rgba(p: &[u8]) -> u32 {
    u32::from_be_bytes([0, p[0], p[1], p[2]])
}

/// How colours find their palette index.
enum Lookup {
    /// Few colours: each keeps its own entry.
    Exact(HashMap<u32, u8>),
    /// Many: the nearest colour of NeuQuant's network.
    Learned(Box<NeuQuant>),
}

/// The global palette and the pixel-to-index mapping.
pub(super) struct Palette {
    /// The colours as the GIF's table wants them: r, g, b per entry.
    pub(super) table_rgb: Vec<u8>,
    lookup: Lookup,
}

impl Palette {
    /// The palette of `pixels`, the frames of `npix` pixels held back, as RGBA bytes.
    pub(super) fn build(pixels: &[u8], npix: usize) -> Palette {
        let mut exact: HashMap<u32, u8> = HashMap::new();
        let mut table_rgb = Vec::new();
        for p in pixels.chunks_exact(4) {
            let px = from_rgba(p);
            if exact.contains_key(&px) {
                continue;
            }
            if exact.len() == MAX_PALETTE_COLORS {
                let nq = learn(pixels, npix);
                return Palette {
                    table_rgb: nq.color_map_rgb(),
                    lookup: Lookup::Learned(Box::new(nq)),
                };
            }
            exact.insert(px, exact.len() as u8);
            table_rgb.extend_from_slice(&p[..3]);
        }
        Palette {
            table_rgb,
            lookup: Lookup::Exact(exact),
        }
    }

    /// Number of colours (the transparent index comes after them).
    pub(super) fn len(&self) -> usize {
        self.table_rgb.len() / 3
    }

    /// The index of `px`: its own for an exact palette (a colour not in
    /// it, seen first after the palette was built, takes the nearest
    /// entry), NeuQuant's nearest for a learnt one.
    fn index_of(&self, px: u32) -> u8 {
        match &self.lookup {
            Lookup::Learned(nq) => nq.index_of(&rgba(px)) as u8,
            Lookup::Exact(map) => map.get(&px).copied().unwrap_or_else(|| {
                let t = rgba(px);
                let distance = |e: &[u8]| -> i32 {
                    (0..3)
                        .map(|k| (i32::from(e[k]) - i32::from(t[k])).pow(2))
                        .sum()
                };
                self.table_rgb
                    .chunks_exact(3)
                    .enumerate()
                    .min_by_key(|(_, e)| distance(e))
                    .map_or(0, |(i, _)| i as u8)
            }),
        }
    }

    /// Maps `src` into `dst`; `prev_src` and `prev_dst` are the previous
    /// frame and its indices (empty for the first frame): an unchanged
    /// pixel keeps its index.
    pub(super) fn map_frame(&self, src: &[u32], prev_src: &[u32], prev_dst: &[u8], dst: &mut [u8]) {
        let mut last: Option<(u32, u8)> = None;
        for (i, (d, &px)) in dst.iter_mut().zip(src).enumerate() {
            *d = match (prev_src.get(i), last) {
                (Some(&p), _) if p == px => prev_dst[i],
                (_, Some((c, index))) if c == px => index,
                _ => self.index_of(px),
            };
            last = Some((px, *d));
        }
    }
}

/// NeuQuant's network of [`MAX_PALETTE_COLORS`] learnt from the frames.
fn learn(pixels: &[u8], npix: usize) -> NeuQuant {
    let every = (pixels.len() / 4).div_ceil(30 * LEARNING_PIXELS).max(1);
    let chosen: Cow<[u8]> = if every == 1 {
        Cow::Borrowed(pixels)
    } else {
        Cow::Owned(
            pixels
                .chunks_exact(4 * npix)
                .step_by(every)
                .flatten()
                .copied()
                .collect(),
        )
    };
    let samplefac = (chosen.len() / 4 / LEARNING_PIXELS).clamp(1, 30) as i32;
    NeuQuant::new(samplefac, MAX_PALETTE_COLORS, &chosen)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bytes(pixels: &[u32]) -> Vec<u8> {
        pixels.iter().flat_map(|&p| rgba(p)).collect()
    }

    #[test]
    fn few_colours_are_kept_exactly_and_strangers_take_the_nearest() {
        let colours = [0x00FF_FFFFu32, 0x0022_2222, 0x001F_77B4];
        let pixels: Vec<u32> = (0..300).map(|i| colours[i % 3]).collect();
        let palette = Palette::build(&bytes(&pixels), pixels.len());
        assert_eq!(palette.len(), 3);
        assert_eq!(
            palette.table_rgb,
            [255, 255, 255, 0x22, 0x22, 0x22, 0x1F, 0x77, 0xB4]
        );
        let mut dst = vec![0u8; 4];
        palette.map_frame(
            &[0x0022_2222, 0x00FE_FEFE, 0x001F_77B4, 0x0010_1010],
            &[],
            &[],
            &mut dst,
        );
        assert_eq!(dst, [1, 0, 2, 1]);
    }

    #[test]
    fn many_colours_are_learnt_into_the_limit() {
        let pixels: Vec<u32> = (0..200_000u32)
            .map(|i| i.wrapping_mul(2_654_435_761) >> 8)
            .collect();
        let palette = Palette::build(&bytes(&pixels), pixels.len());
        assert_eq!(palette.len(), MAX_PALETTE_COLORS);
        let mut dst = vec![0u8; pixels.len()];
        palette.map_frame(&pixels, &[], &[], &mut dst);
        assert!(dst.iter().all(|&i| usize::from(i) < MAX_PALETTE_COLORS));
    }

    #[test]
    fn unchanged_pixels_keep_their_previous_index() {
        let palette = Palette::build(&bytes(&[0x0000_0000, 0x00FF_FFFF]), 2);
        let mut dst = vec![0u8; 3];
        // The previous indices win where the pixel did not change.
        palette.map_frame(
            &[0, 0x00FF_FFFF, 0],
            &[0, 0x00FF_FFFF, 7],
            &[9, 8, 7],
            &mut dst,
        );
        assert_eq!(dst, [9, 8, 0]);
    }
}
