//! Synthetic frames for the unit tests: a stand-in for the demo renderer and
//! flat colour patches over a gradient, plus the colours they use.

use super::test_support::{channels, pack};

pub(super) const BACKGROUND: u32 = 0xF7F7F7;
pub(super) const PANEL: u32 = 0xFFFFFF;
pub(super) const TEXT: u32 = 0x222222;
pub(super) const CURVES: [u32; 3] = [0x1f77b4, 0xd62728, 0x2ca02c];
const METAL: [f64; 3] = [104.0, 122.0, 150.0];

fn blend(bg: u32, fg: u32, a: f64) -> u32 {
    let (b, f) = (channels(bg), channels(fg));
    pack([0, 1, 2].map(|k| f64::from(b[k]) + (f64::from(f[k]) - f64::from(b[k])) * a))
}

const DIGITS: [u16; 10] = [
    0b111_101_101_101_111,
    0b010_110_010_010_111,
    0b111_001_111_100_111,
    0b111_001_111_001_111,
    0b101_101_111_001_001,
    0b111_100_111_001_111,
    0b111_100_111_101_111,
    0b111_001_001_001_001,
    0b111_101_111_101_111,
    0b111_101_111_001_111,
];

fn draw_number(img: &mut [u32], w: usize, x0: usize, y0: usize, value: usize, scale: usize) {
    let text = format!("{value:04}");
    for (i, ch) in text.bytes().enumerate() {
        let bits = DIGITS[usize::from(ch - b'0')];
        for row in 0..5 {
            for col in 0..3 {
                if bits >> (14 - (row * 3 + col)) & 1 == 1 {
                    for dy in 0..scale {
                        for dx in 0..scale {
                            let x = x0 + i * 4 * scale + col * scale + dx;
                            let y = y0 + row * scale + dy;
                            img[y * w + x] = TEXT;
                        }
                    }
                }
            }
        }
    }
}

/// Stand-in for the demo renderer: shaded tumbling T-handle, strip chart
/// with anti-aliased scrolling curves, and a changing counter.
fn render_demo(t: usize, w: usize, h: usize) -> Vec<u32> {
    let mut img = vec![BACKGROUND; w * h];
    let (cx, cy) = (w as f64 * 0.28, h as f64 * 0.5);
    let s = h as f64 / 300.0;
    let ang = t as f64 * 0.11;
    let tumble = (t as f64 * 0.07).cos();
    let (sa, ca) = ang.sin_cos();
    let body_x1 = (w as f64 * 0.58) as usize;
    for y in 0..h {
        for x in 0..body_x1 {
            let (mut cov, mut acc) = (0.0, [0.0; 3]);
            for (ox, oy) in [(0.25, 0.25), (0.75, 0.25), (0.25, 0.75), (0.75, 0.75)] {
                let (px, py) = (x as f64 + ox - cx, y as f64 + oy - cy);
                let u = (ca * px + sa * py) / s;
                let v = (-sa * px + ca * py) / s;
                let half_bar = 95.0 * tumble.abs().max(0.25);
                let across = if u.abs() <= half_bar && (v + 40.0).abs() <= 15.0 {
                    Some((v + 40.0) / 15.0)
                } else if u.abs() <= 13.0 && v > -40.0 && v <= 75.0 {
                    Some(u / 13.0)
                } else {
                    None
                };
                if let Some(a) = across {
                    let nz = (1.0 - a * a).max(0.0).sqrt();
                    let light = 0.30 + 0.55 * (nz * 0.8 + 0.35 * a * tumble).max(0.0);
                    let spec = (nz * 0.9 + 0.1 * a).max(0.0).powi(24) * 0.5;
                    for k in 0..3 {
                        acc[k] += (METAL[k] * light * 1.35 + 255.0 * spec).min(255.0);
                    }
                    cov += 0.25;
                }
            }
            if cov > 0.0 {
                let c = pack(acc.map(|v| v / (cov * 4.0)));
                img[y * w + x] = blend(BACKGROUND, c, cov);
            }
        }
    }
    // Strip chart panel.
    let (px0, px1, py0, py1) = (body_x1 + 10, w - 10, 20, h - 20);
    for y in py0..py1 {
        for x in px0..px1 {
            let edge = y == py0 || y + 1 == py1 || x == px0 || x + 1 == px1;
            let grid = (y - py0) % 40 == 0;
            img[y * w + x] = if edge {
                0xB0B0B0
            } else if grid {
                0xE8E8E8
            } else {
                PANEL
            };
        }
    }
    for (k, &color) in CURVES.iter().enumerate() {
        let base = py0 as f64 + (py1 - py0) as f64 * (0.25 + 0.25 * k as f64);
        let f = |x: f64| {
            base + 28.0 * ((x + 4.0 * t as f64) * (0.035 + 0.01 * k as f64) + k as f64).sin()
        };
        for x in px0 + 1..px1 - 1 {
            let xc = x as f64 + 0.5;
            let yc = f(xc);
            let slope = (f(xc + 0.5) - f(xc - 0.5)).abs();
            let norm = (1.0 + slope * slope).sqrt();
            let lo = (yc - slope - 2.0).floor().max(py0 as f64 + 1.0) as usize;
            let hi = (yc + slope + 3.0).ceil().min(py1 as f64 - 1.0) as usize;
            for y in lo..hi {
                let d = ((y as f64 + 0.5 - yc) / norm).abs();
                let a = (1.4 - d).clamp(0.0, 1.0);
                if a > 0.0 {
                    img[y * w + x] = blend(img[y * w + x], color, a);
                }
            }
        }
    }
    draw_number(&mut img, w, 8, 8, t * 17 % 10_000, 3);
    draw_number(&mut img, w, px0, h - 16, 2024, 2);
    img
}

pub(super) fn demo(n: usize, w: usize, h: usize) -> Vec<Vec<u32>> {
    (0..n).map(|t| render_demo(t, w, h)).collect()
}

/// A flat square of one colour at its frame-0 position (it moves by `t % 3, t % 2`).
pub(super) struct Patch {
    pub(super) color: u32,
    pub(super) x0: usize,
    pub(super) y0: usize,
    pub(super) size: usize,
}

/// Flat patches of the colours that must survive: background, text,
/// curve colours and a grey-blue shading ramp (some patches big enough
/// to be seeds, some too small), moving over a rainbow gradient that
/// forces real quantisation.
pub(super) fn patch_frames(n: usize, w: usize, h: usize) -> (Vec<Vec<u32>>, Vec<Patch>) {
    let mut colors = vec![PANEL, BACKGROUND, TEXT, 0x000000, 0xFAFAFA];
    colors.extend(CURVES);
    for i in 0..24 {
        let l = 0.25 + 0.75 * i as f64 / 23.0;
        colors.push(pack(METAL.map(|c| (c * l * 1.6).min(255.0))));
    }
    let frames = (0..n)
        .map(|t| {
            let mut img = vec![PANEL; w * h];
            for y in 0..h {
                for x in 0..w / 3 {
                    let r = (x * 255 / (w / 3)) as u32;
                    let g = ((y + t * 3) * 255 / (h + 3 * n)) as u32;
                    let b = ((x + y) % 256) as u32;
                    img[y * w + x] = (r << 16) | (g << 8) | b;
                }
            }
            for (i, &c) in colors.iter().enumerate() {
                let size = if i % 2 == 0 { 20 } else { 7 };
                let x0 = w / 3 + 4 + (i % 8) * 24 + t % 3;
                let y0 = 4 + (i / 8) * 24 + t % 2;
                for y in y0..y0 + size {
                    img[y * w + x0..y * w + x0 + size].fill(c);
                }
            }
            img
        })
        .collect();
    let patches = colors
        .iter()
        .enumerate()
        .map(|(i, &color)| Patch {
            color,
            x0: w / 3 + 4 + (i % 8) * 24,
            y0: 4 + (i / 8) * 24,
            size: if i % 2 == 0 { 20 } else { 7 },
        })
        .collect();
    (frames, patches)
}
