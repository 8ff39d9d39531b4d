//! The global palette (step 1 of the overview in [`super`]) and the 15-bit
//! lookup-table mapper (step 2): stratified pixel sampling, exact frequent
//! colours as seeds, per-cell representatives, and the lazily filled table.
//! The remaining palette slots are filled by [`super::median_cut`].

use super::median_cut::median_cut;
use super::{MAX_PALETTE_COLORS, PALETTE_SAMPLE_LIMIT};

/// Maximum number of exact, frequent colours copied verbatim into the palette.
const MAX_SEEDS: usize = 64;

/// A colour becomes a seed if it makes up at least one sample in this many (0.04 %).
const SEED_SHARE: usize = 2500;

/// Number of cells of the 15-bit colour lookup table.
const LUT_CELLS: usize = 1 << 15;

/// Marks a lookup-table cell that has not been filled yet.
const LUT_UNSET: u16 = u16::MAX;

/// Marks a histogram cell that received no sample.
const NO_SAMPLE: u32 = u32::MAX;

/// Index of the 15-bit lookup-table cell of a `0x00RRGGBB` pixel.
#[inline]
fn cell_key(px: u32) -> usize {
    (((px >> 9) & 0x7C00) | ((px >> 6) & 0x03E0) | ((px >> 3) & 0x001F)) as usize
}

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

/// Global palette plus what the lookup table needs to fill its cells.
pub(super) struct Palette {
    /// Palette colours as `0x00RRGGBB`; the first `seeds` entries are exact frequent colours.
    pub(super) colors: Vec<u32>,
    /// Number of leading entries of `colors` that are exact seed colours, most frequent first.
    seeds: usize,
    /// Representative colour per 15-bit cell (see [`cell_representatives`]), or [`NO_SAMPLE`].
    cell_rep: Vec<u32>,
}

impl Palette {
    pub(super) fn build<F: AsRef<[u32]>>(frames: &[F], npix: usize) -> Palette {
        let mut sample = sample_pixels(frames, npix);
        sample.sort_unstable();
        // Distinct colours with their counts, most frequent first.
        let mut distinct: Vec<(u32, u32)> = Vec::new();
        for &c in &sample {
            match distinct.last_mut() {
                Some((last, n)) if *last == c => *n += 1,
                _ => distinct.push((c, 1)),
            }
        }
        distinct.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));

        let cell_rep = cell_representatives(&distinct);

        if distinct.len() <= MAX_PALETTE_COLORS {
            let colors: Vec<u32> = distinct.iter().map(|&(c, _)| c).collect();
            return Palette {
                seeds: colors.len(),
                colors,
                cell_rep,
            };
        }

        let threshold = (sample.len() / SEED_SHARE).max(4);
        let seeds = distinct
            .iter()
            .take(MAX_SEEDS)
            .take_while(|&&(_, n)| n as usize >= threshold)
            .count();
        let mut colors: Vec<u32> = distinct[..seeds].iter().map(|&(c, _)| c).collect();
        let rest = &distinct[seeds..];
        colors.extend(median_cut(rest, MAX_PALETTE_COLORS - seeds));
        Palette {
            colors,
            seeds,
            cell_rep,
        }
    }
}

/// Stratified random sample of at most [`PALETTE_SAMPLE_LIMIT`] pixels over all frames.
fn sample_pixels<F: AsRef<[u32]>>(frames: &[F], npix: usize) -> Vec<u32> {
    let total = frames.len().saturating_mul(npix);
    if total <= PALETTE_SAMPLE_LIMIT {
        return frames
            .iter()
            .flat_map(|f| f.as_ref().iter().map(|&p| p & 0x00FF_FFFF))
            .collect();
    }
    let step = total.div_ceil(PALETTE_SAMPLE_LIMIT);
    let mut out = Vec::with_capacity(PALETTE_SAMPLE_LIMIT);
    let mut rng: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut start = 0usize;
    while start < total {
        // xorshift64
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        let span = step.min(total - start) as u64;
        let pos = start + (rng % span) as usize;
        if let Some(&p) = frames
            .get(pos / npix)
            .and_then(|f| f.as_ref().get(pos % npix))
        {
            out.push(p & 0x00FF_FFFF);
        }
        start += step;
    }
    out
}

/// Per 15-bit cell: `[count, sum of red, sum of green, sum of blue]` of the samples.
pub(super) fn cell_sums(distinct: &[(u32, u32)]) -> Vec<[u64; 4]> {
    let mut acc = vec![[0u64; 4]; LUT_CELLS];
    for &(c, n) in distinct {
        let a = &mut acc[cell_key(c)];
        let n = u64::from(n);
        a[0] += n;
        for (k, v) in channels(c).into_iter().enumerate() {
            a[k + 1] += n * v as u64;
        }
    }
    acc
}

/// Representative colour of each 15-bit cell: its most frequent sampled
/// colour when that holds at least half of the cell's samples (a flat
/// colour), else the mean of the cell's samples; [`NO_SAMPLE`] for empty cells.
///
/// `distinct` must be sorted most frequent first.
fn cell_representatives(distinct: &[(u32, u32)]) -> Vec<u32> {
    let acc = cell_sums(distinct);
    let mut mode = vec![(NO_SAMPLE, 0u32); LUT_CELLS];
    for &(c, n) in distinct {
        let m = &mut mode[cell_key(c)];
        if m.0 == NO_SAMPLE {
            *m = (c, n);
        }
    }
    acc.iter()
        .zip(&mode)
        .map(|(a, &(m, mn))| {
            if a[0] == 0 {
                NO_SAMPLE
            } else if 2 * u64::from(mn) >= a[0] {
                m
            } else {
                let n = a[0] as f64;
                pack([a[1] as f64 / n, a[2] as f64 / n, a[3] as f64 / n])
            }
        })
        .collect()
}

/// Maps pixels to palette indices through a lazily filled 15-bit lookup table.
pub(super) struct Mapper {
    palette: Palette,
    lut: Vec<u16>,
}

impl Mapper {
    pub(super) fn new(palette: Palette) -> Mapper {
        let mut lut = vec![LUT_UNSET; LUT_CELLS];
        // Seeds are ordered most frequent first; the first seed in a cell wins.
        for (i, &c) in palette.colors[..palette.seeds].iter().enumerate() {
            let cell = &mut lut[cell_key(c)];
            if *cell == LUT_UNSET {
                *cell = i as u16;
            }
        }
        Mapper { palette, lut }
    }

    fn nearest(&self, target: u32) -> u16 {
        let t = channels(target);
        let mut best = (i32::MAX, 0u16);
        for (i, &c) in self.palette.colors.iter().enumerate() {
            let p = channels(c);
            let d = (0..3).map(|k| (p[k] - t[k]) * (p[k] - t[k])).sum::<i32>();
            if d < best.0 {
                best = (d, i as u16);
            }
        }
        best.1
    }

    pub(super) fn map_frame(&mut self, src: &[u32], dst: &mut [u8]) {
        for (d, &px) in dst.iter_mut().zip(src) {
            let key = cell_key(px);
            let mut v = self.lut[key];
            if v == LUT_UNSET {
                let rep = self.palette.cell_rep[key];
                let target = if rep == NO_SAMPLE {
                    // Centre of the cell.
                    (px & 0x00F8_F8F8) | 0x0004_0404
                } else {
                    rep
                };
                v = self.nearest(target);
                self.lut[key] = v;
            }
            *d = v as u8;
        }
    }
}

#[cfg(test)]
mod tests {
    use gif::{DisposalMethod, Repeat};

    use super::super::test_scenes::{CURVES, PANEL, TEXT, patch_frames};
    use super::super::test_support::{channel_err, compare, decode, encode};
    use super::*;

    #[test]
    fn flat_colour_regions_round_trip() {
        let (w, h, n) = (360usize, 160usize, 8usize);
        let (frames, patches) = patch_frames(n, w, h);
        let (bytes, stats) = encode(w as u16, h as u16, &frames, 7);
        let dec = decode(&bytes);
        assert_eq!((dec.width, dec.height), (w, h));
        assert_eq!(dec.repeat, Repeat::Infinite);
        assert_eq!(dec.frames.len(), n);
        assert_eq!(stats.frames, n);
        assert!(stats.palette_colors <= MAX_PALETTE_COLORS);
        assert!(dec.palette_len <= 256 && dec.palette_len > stats.palette_colors);
        for (i, f) in dec.frames.iter().enumerate() {
            assert_eq!(f.delay, 7, "delay of frame {i}");
            assert_eq!(f.dispose, DisposalMethod::Keep);
            if i > 0 {
                assert_eq!(f.transparent, Some(stats.transparent_index));
            }
        }
        for (t, canvas) in dec.canvases.iter().enumerate() {
            for p in &patches {
                let (x0, y0) = (p.x0 + t % 3, p.y0 + t % 2);
                for y in y0..y0 + p.size {
                    for x in x0..x0 + p.size {
                        let got = canvas[y * w + x];
                        let e = channel_err(p.color, got);
                        assert!(
                            e <= 8,
                            "frame {t}: {:06x} ({}px patch) -> {got:06x}, err {e}",
                            p.color,
                            p.size
                        );
                    }
                }
            }
        }
        let (flat_max, all_max, mean, flat_n) = compare(&frames, &dec);
        assert!(flat_n > n * w * h / 2);
        assert!(flat_max <= 8, "flat max err {flat_max}");
        assert!(all_max <= 24, "overall max err {all_max}");
        assert!(mean < 3.0, "mean err {mean}");
        // The dominant colours are exact.
        for (src, got) in frames.iter().zip(&dec.canvases) {
            for (s, g) in src.iter().zip(got) {
                if *s == PANEL || *s == TEXT || CURVES.contains(s) {
                    assert_eq!(s, g);
                }
            }
        }
    }

    #[test]
    fn palette_never_exceeds_limit_on_noise() {
        let (w, h) = (200usize, 150usize);
        let mut rng = 12345u32;
        let frames: Vec<Vec<u32>> = (0..3)
            .map(|_| {
                (0..w * h)
                    .map(|_| {
                        rng = rng.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
                        rng >> 8
                    })
                    .collect()
            })
            .collect();
        let (bytes, stats) = encode(w as u16, h as u16, &frames, 3);
        assert_eq!(stats.palette_colors, MAX_PALETTE_COLORS);
        assert_eq!(stats.transparent_index, 255);
        let dec = decode(&bytes);
        assert_eq!(dec.palette_len, 256);
        let (_, all_max, mean, _) = compare(&frames, &dec);
        // 255 colours for uniform noise: about 6 levels per channel.
        assert!(all_max <= 48, "max err {all_max}");
        assert!(mean < 20.0, "mean err {mean}");
    }

    #[test]
    fn palette_sample_is_bounded_and_covers_all_frames() {
        let colours = [0x102030u32, 0x405060, 0x708090, 0xA0B0C0];
        let frames: Vec<Vec<u32>> = colours.iter().map(|&c| vec![c; 1000 * 50]).collect();
        let sample = sample_pixels(&frames, 1000 * 50);
        assert!(sample.len() <= PALETTE_SAMPLE_LIMIT);
        assert!(sample.len() >= PALETTE_SAMPLE_LIMIT * 9 / 10);
        for &c in &colours {
            let share = sample.iter().filter(|&&p| p == c).count();
            assert!(share * 5 > sample.len(), "{c:06x} only {share} samples");
        }
        let small = vec![vec![0xFF00_0001u32; 10]; 3];
        assert_eq!(sample_pixels(&small, 10), vec![1; 30]);
    }

    #[test]
    fn lookup_table_key_uses_top_five_bits() {
        assert_eq!(cell_key(0x00FF_FFFF), LUT_CELLS - 1);
        assert_eq!(cell_key(0xFF07_0707), 0);
        assert_eq!(cell_key(0x0008_0000), 1 << 10);
        assert_eq!(cell_key(0x0000_0800), 1 << 5);
        assert_eq!(cell_key(0x0000_0008), 1);
    }
}
