//! The triangle rasteriser: guard-band clipping, snapping to the sub-pixel
//! grid, exact integer edge functions with a top-left fill rule, and the
//! `1/depth` test against the depth buffer.

use super::clip::{Polygon, ScreenVertex};
use super::renderer::Bounds;
use super::{Image, Renderer};

/// Sub-pixel precision of the rasteriser, in bits.
const SUBPIXEL_BITS: u32 = 8;
/// One pixel in sub-pixel units.
const SUBPIXEL_ONE: i64 = 1 << SUBPIXEL_BITS;
/// Half a pixel in sub-pixel units (offset of a pixel centre).
const SUBPIXEL_HALF: i64 = SUBPIXEL_ONE / 2;
/// Guard band in pixels: triangles reaching beyond `±GUARD_PX` are clipped in
/// 2-D first, which keeps all edge-function arithmetic well inside `i64`.
pub(super) const GUARD_PX: usize = 1 << 20;
/// Largest snapped coordinate magnitude, in sub-pixel units (a little slack
/// above the guard band for rounding in the 2-D clipper).
const SNAP_LIMIT: i64 = ((GUARD_PX as i64) + 1) << SUBPIXEL_BITS;

/// Snaps a screen coordinate (pixels) to the sub-pixel grid.
fn snap(v: f64) -> i64 {
    ((v * SUBPIXEL_ONE as f64).round() as i64).clamp(-SNAP_LIMIT, SNAP_LIMIT)
}

impl Renderer {
    /// Fills one screen triangle, first clipping it to the guard band if it
    /// reaches far outside the screen.
    pub(super) fn fill_triangle(
        &mut self,
        image: &mut Image,
        bounds: &Bounds,
        tri: [ScreenVertex; 3],
        color: u32,
        cull_back: bool,
    ) {
        if !tri.iter().all(ScreenVertex::is_finite) {
            return;
        }
        let g = GUARD_PX as f64;
        if tri.iter().all(|v| v.x.abs() <= g && v.y.abs() <= g) {
            self.fill_snapped(image, bounds, tri, color, cull_back);
            return;
        }
        let lerp = |p: &ScreenVertex, q: &ScreenVertex, t: f64| p.lerp(q, t);
        let poly = Polygon::from_slice(&tri)
            .clip(|v| g + v.x, lerp)
            .clip(|v| g - v.x, lerp)
            .clip(|v| g + v.y, lerp)
            .clip(|v| g - v.y, lerp);
        let vs = poly.as_slice();
        if let Some((&first, rest)) = vs.split_first() {
            for pair in rest.windows(2) {
                if let [p, q] = pair {
                    self.fill_snapped(image, bounds, [first, *p, *q], color, cull_back);
                }
            }
        }
    }

    /// The rasteriser proper: snaps the vertices (all within the guard band)
    /// to the sub-pixel grid and fills the pixels whose centres are inside,
    /// using exact integer edge functions and the top-left rule, with a
    /// `1/depth` (w) test against the depth buffer.
    fn fill_snapped(
        &mut self,
        image: &mut Image,
        bounds: &Bounds,
        tri: [ScreenVertex; 3],
        color: u32,
        cull_back: bool,
    ) {
        let mut p = tri.map(|v| (snap(v.x), snap(v.y), v.w));
        // Twice the signed area in screen coordinates (y down). A front face
        // (counter-clockwise as the viewer sees it) has a negative value; it
        // is re-ordered to a positive one, for which the inside is where all
        // three edge functions below are positive.
        let area = {
            let [(x0, y0, _), (x1, y1, _), (x2, y2, _)] = p;
            (x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0)
        };
        if area == 0 {
            return;
        }
        if area > 0 {
            // Clockwise on screen as seen by the viewer: a back face.
            if cull_back {
                return;
            }
        } else {
            p.swap(1, 2);
        }
        let [(x0, y0, w0), (x1, y1, w1), (x2, y2, w2)] = p;

        // Pixel bounding box (conservative by at most one pixel), clipped.
        let min_x = x0.min(x1).min(x2);
        let max_x = x0.max(x1).max(x2);
        let min_y = y0.min(y1).min(y2);
        let max_y = y0.max(y1).max(y2);
        let px_lo = |v: i64| (v - SUBPIXEL_HALF).div_euclid(SUBPIXEL_ONE);
        let xs = px_lo(min_x).max(bounds.x0 as i64);
        let xe = (px_lo(max_x) + 2).min(bounds.x1 as i64);
        let ys = px_lo(min_y).max(bounds.y0 as i64);
        let ye = (px_lo(max_y) + 2).min(bounds.y1 as i64);
        if xs >= xe || ys >= ye {
            return;
        }

        // Edge setup. For edge i→j: E(x, y) = (xj−xi)(y−yi) − (yj−yi)(x−xi);
        // a pixel is inside if E > 0, or E = 0 on a top or left edge. The
        // bias of −1 for other edges turns this into "E + bias ≥ 0".
        let start_x = xs * SUBPIXEL_ONE + SUBPIXEL_HALF;
        let start_y = ys * SUBPIXEL_ONE + SUBPIXEL_HALF;
        let edge = |(xi, yi): (i64, i64), (xj, yj): (i64, i64)| {
            let (dx, dy) = (xj - xi, yj - yi);
            let top_left = dy < 0 || (dy == 0 && dx > 0);
            let e = dx * (start_y - yi) - dy * (start_x - xi) - i64::from(!top_left);
            (e, -dy * SUBPIXEL_ONE, dx * SUBPIXEL_ONE)
        };
        let (mut e0_row, e0_dx, e0_dy) = edge((x1, y1), (x2, y2));
        let (mut e1_row, e1_dx, e1_dy) = edge((x2, y2), (x0, y0));
        let (mut e2_row, e2_dx, e2_dy) = edge((x0, y0), (x1, y1));

        // Plane of w = 1/depth over the snapped triangle (pixel units).
        let s = 1.0 / SUBPIXEL_ONE as f64;
        let (fx0, fy0) = (x0 as f64 * s, y0 as f64 * s);
        let (dx1, dy1) = (x1 as f64 * s - fx0, y1 as f64 * s - fy0);
        let (dx2, dy2) = (x2 as f64 * s - fx0, y2 as f64 * s - fy0);
        let det = dx1 * dy2 - dx2 * dy1;
        let (dw1, dw2) = (w1 - w0, w2 - w0);
        let dwdx = (dw1 * dy2 - dw2 * dy1) / det;
        let dwdy = (dx1 * dw2 - dx2 * dw1) / det;
        if !(dwdx.is_finite() && dwdy.is_finite()) {
            return;
        }

        // xs..xe and ys..ye lie inside bounds, hence inside both the image
        // and the depth buffer; the slices are still taken with `get_mut`.
        let (xs, xe, ys, ye) = (xs as usize, xe as usize, ys as usize, ye as usize);
        let row_len = (xe - xs) as i64;
        for py in ys..ye {
            // Exact span of pixels in this row passing all three edge tests.
            let (mut lo, mut hi) = (0, row_len);
            edge_span(e0_row, e0_dx, &mut lo, &mut hi);
            edge_span(e1_row, e1_dx, &mut lo, &mut hi);
            edge_span(e2_row, e2_dx, &mut lo, &mut hi);
            e0_row += e0_dy;
            e1_row += e1_dy;
            e2_row += e2_dy;
            if lo >= hi {
                continue;
            }
            // 0 ≤ lo < hi ≤ row_len, so a..b lies within xs..xe.
            let (a, b) = (xs + lo as usize, xs + hi as usize);
            let img_row = py * image.width;
            let z_row = py * self.width;
            let (Some(pixels), Some(depths)) = (
                image.pixels.get_mut(img_row + a..img_row + b),
                self.depth.get_mut(z_row + a..z_row + b),
            ) else {
                return;
            };
            let mut w = w0 + dwdx * (a as f64 + 0.5 - fx0) + dwdy * (py as f64 + 0.5 - fy0);
            for (pixel, depth) in pixels.iter_mut().zip(depths.iter_mut()) {
                let wf = w as f32;
                if wf > *depth {
                    *depth = wf;
                    *pixel = color;
                }
                w += dwdx;
            }
        }
    }
}

/// Narrows the pixel-offset range `lo..hi` of a row to the offsets `i` with
/// `e + i·step ≥ 0` (an edge function stepped along the row), exactly.
fn edge_span(e: i64, step: i64, lo: &mut i64, hi: &mut i64) {
    if step > 0 {
        if e < 0 {
            // Smallest i with e + i·step ≥ 0 is ceil(−e / step).
            *lo = (*lo).max((step - 1 - e) / step);
        }
    } else if e < 0 {
        // Non-increasing along the row and already negative: empty.
        *hi = 0;
    } else if step < 0 {
        // Largest i with e + i·step ≥ 0 is floor(e / −step).
        *hi = (*hi).min(e / -step + 1);
    }
}

#[cfg(test)]
mod tests {
    use super::super::test_util::{hit_counts, screen_camera, sp};

    #[test]
    fn square_from_two_triangles_covers_each_pixel_once() {
        // The shared diagonal y = x passes exactly through pixel centres.
        let cam = screen_camera();
        let verts = [
            sp(10.25, 10.25),
            sp(10.25, 30.25),
            sp(30.25, 30.25),
            sp(30.25, 10.25),
        ];
        let counts = hit_counts(40, &cam, &verts, &[[0, 1, 2], [0, 2, 3]]);
        for y in 0..40 {
            for x in 0..40 {
                let inside = (10..30).contains(&x) && (10..30).contains(&y);
                assert_eq!(counts[y * 40 + x], u32::from(inside), "pixel ({x}, {y})");
            }
        }
    }

    #[test]
    fn diamond_and_fan_have_no_cracks_or_double_hits() {
        let cam = screen_camera();
        // A diamond whose every edge runs through pixel centres.
        let verts = [sp(20.5, 5.5), sp(5.5, 20.5), sp(20.5, 35.5), sp(35.5, 20.5)];
        let counts = hit_counts(40, &cam, &verts, &[[0, 1, 3], [1, 2, 3]]);
        for y in 0..40 {
            for x in 0..40 {
                let d = (x as f64 + 0.5 - 20.5).abs() + (y as f64 + 0.5 - 20.5).abs();
                let c = counts[y * 40 + x];
                assert!(c <= 1, "double hit at ({x}, {y})");
                if d < 15.0 - 1e-9 {
                    assert_eq!(c, 1, "crack at ({x}, {y})");
                } else if d > 15.0 + 1e-9 {
                    assert_eq!(c, 0, "spill at ({x}, {y})");
                }
            }
        }
        // A fan of seven triangles around a vertex sitting on a pixel centre.
        let mut verts = vec![sp(20.5, 20.5)];
        let n = 7;
        for k in 0..n {
            let a = 0.3 + std::f64::consts::TAU * k as f64 / n as f64;
            verts.push(sp(20.5 + 12.0 * a.cos(), 20.5 - 12.0 * a.sin()));
        }
        let tris: Vec<[u32; 3]> = (0..n).map(|k| [0, 1 + k, 1 + (k + 1) % n]).collect();
        let counts = hit_counts(40, &cam, &verts, &tris);
        assert_eq!(counts[20 * 40 + 20], 1);
        for y in 0..40 {
            for x in 0..40 {
                let r = ((x as f64 - 20.0).powi(2) + (y as f64 - 20.0).powi(2)).sqrt();
                let c = counts[y * 40 + x];
                assert!(c <= 1, "double hit at ({x}, {y})");
                if r < 10.0 {
                    assert_eq!(c, 1, "crack at ({x}, {y})");
                }
            }
        }
    }
}
