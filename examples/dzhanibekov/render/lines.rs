//! Drawing thick depth-tested 3-D lines and arrows.

use glam::DVec3;

use super::clip::{ScreenVertex, clip_project_segment};
use super::renderer::Bounds;
use super::{Camera, Image, Renderer};

/// Default relative depth bias for lines and arrows: they are depth-tested as
/// if they were this fraction of their depth closer to the eye (1 % of the
/// depth), so lines lying on a surface are not lost to z-fighting.
pub const LINE_DEPTH_BIAS: f64 = 0.01;

impl Renderer {
    /// Draws a depth-tested 3-D line segment `width_px` pixels wide
    /// (at least 1; nothing is drawn for a non-finite width), clipped against
    /// the near plane. The line is depth-biased
    /// toward the eye by [`Renderer::line_depth_bias`] so lines lying on a
    /// surface stay visible while lines inside or behind a body are hidden.
    pub fn draw_line(
        &mut self,
        image: &mut Image,
        camera: &Camera,
        a_world: DVec3,
        b_world: DVec3,
        width_px: f64,
        color: u32,
    ) {
        let Some(bounds) = self.bounds(image) else {
            return;
        };
        let Some((sa, sb)) = clip_project_segment(camera, a_world, b_world) else {
            return;
        };
        let bias = 1.0 + self.line_depth_bias;
        self.fill_segment(image, &bounds, sa, sb, width_px, color, bias);
    }

    /// Draws an arrow from `from_world` to `to_world`: a thick depth-tested
    /// shaft (as [`Renderer::draw_line`]) and a filled triangular head
    /// `head_px` pixels long at the tip, depth-tested at the tip's depth.
    /// If the tip is behind the near plane only the visible shaft is drawn;
    /// a non-finite `width_px` draws nothing and a non-finite `head_px` no
    /// head.
    #[allow(clippy::too_many_arguments)]
    pub fn draw_arrow(
        &mut self,
        image: &mut Image,
        camera: &Camera,
        from_world: DVec3,
        to_world: DVec3,
        width_px: f64,
        head_px: f64,
        color: u32,
    ) {
        let Some(bounds) = self.bounds(image) else {
            return;
        };
        if !width_px.is_finite() {
            return;
        }
        let Some((sa, st)) = clip_project_segment(camera, from_world, to_world) else {
            return;
        };
        let bias = 1.0 + self.line_depth_bias;
        let tip_visible = camera.project(to_world).is_some();
        let (dx, dy) = (st.x - sa.x, st.y - sa.y);
        let len = (dx * dx + dy * dy).sqrt();
        let head_len = if head_px.is_finite() {
            head_px.clamp(0.0, len)
        } else {
            0.0
        };
        if !tip_visible || len < 1e-9 || head_len <= 0.0 {
            self.fill_segment(image, &bounds, sa, st, width_px, color, bias);
            return;
        }
        let (ux, uy) = (dx / len, dy / len);
        let base = sa.lerp(&st, (len - head_len) / len);
        self.fill_segment(image, &bounds, sa, base, width_px, color, bias);
        let half = (0.4 * head_len).max(0.75 * width_px.max(1.0));
        let w_tip = st.w * bias;
        let head = [
            ScreenVertex { w: w_tip, ..st },
            ScreenVertex {
                x: base.x - uy * half,
                y: base.y + ux * half,
                w: w_tip,
            },
            ScreenVertex {
                x: base.x + uy * half,
                y: base.y - ux * half,
                w: w_tip,
            },
        ];
        self.fill_triangle(image, &bounds, head, color, false);
    }

    /// Draws a screen-space segment as a quad of the given width, with
    /// `1/depth` interpolated along it and multiplied by `bias`.
    #[allow(clippy::too_many_arguments)]
    fn fill_segment(
        &mut self,
        image: &mut Image,
        bounds: &Bounds,
        a: ScreenVertex,
        b: ScreenVertex,
        width_px: f64,
        color: u32,
        bias: f64,
    ) {
        if !width_px.is_finite() {
            return;
        }
        let half = width_px.max(1.0) * 0.5;
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        let len = (dx * dx + dy * dy).sqrt();
        let (mut a, mut b) = (a, b);
        let (ux, uy) = if len > 1e-9 {
            (dx / len, dy / len)
        } else {
            // A point: draw a small square instead of nothing.
            a.x -= half;
            b.x += half;
            (1.0, 0.0)
        };
        let (nx, ny) = (-uy * half, ux * half);
        let (wa, wb) = (a.w * bias, b.w * bias);
        let corner = |p: &ScreenVertex, s: f64, w: f64| ScreenVertex {
            x: p.x + s * nx,
            y: p.y + s * ny,
            w,
        };
        let q0 = corner(&a, 1.0, wa);
        let q1 = corner(&b, 1.0, wb);
        let q2 = corner(&b, -1.0, wb);
        let q3 = corner(&a, -1.0, wa);
        self.fill_triangle(image, bounds, [q0, q1, q2], color, false);
        self.fill_triangle(image, bounds, [q0, q2, q3], color, false);
    }
}

#[cfg(test)]
mod tests {
    use super::super::test_util::*;
    use super::*;

    #[test]
    fn line_behind_triangle_hidden_in_front_visible() {
        let cam = centred_camera();
        let tri = [
            DVec3::new(-1.0, -1.0, 0.0),
            DVec3::new(1.0, -1.0, 0.0),
            DVec3::new(0.0, 1.0, 0.0),
        ];
        let (grey, red) = (0x0080_8080, 0x00FF_0000);
        for (z, expect_line) in [(-1.0, false), (1.0, true), (0.0, true)] {
            let (mut img, mut r) = canvas();
            draw_flat(&mut r, &mut img, &cam, &tri, grey);
            let (a, b) = (DVec3::new(-3.0, -0.2, z), DVec3::new(3.0, -0.2, z));
            r.draw_line(&mut img, &cam, a, b, 3.0, red);
            let (cx, cy) = cam.screen_position(DVec3::new(0.0, -0.2, z)).unwrap();
            let centre = img.pixel(cx as usize, cy as usize).unwrap();
            assert_eq!(centre == red, expect_line, "z = {z}");
            if !expect_line {
                assert_eq!(centre, grey);
            }
            // Away from the triangle the line is always visible.
            let (ox, oy) = cam.screen_position(DVec3::new(-2.5, -0.2, z)).unwrap();
            assert_eq!(img.pixel(ox as usize, oy as usize), Some(red), "z = {z}");
        }
    }

    #[test]
    fn arrow_has_head_at_tip() {
        let cam = screen_camera();
        let (mut img, mut r) = canvas();
        let red = 0x00FF_0000;
        r.draw_arrow(
            &mut img,
            &cam,
            sp(10.0, 32.0),
            sp(50.0, 32.0),
            2.0,
            10.0,
            red,
        );
        assert_eq!(img.pixel(20, 32), Some(red)); // shaft
        assert_eq!(img.pixel(20, 35), Some(BG)); // beside the thin shaft
        assert_eq!(img.pixel(41, 34), Some(red)); // wide head near its base
        assert_eq!(img.pixel(48, 32), Some(red)); // close to the tip
        assert_eq!(img.pixel(52, 32), Some(BG)); // beyond the tip
        // Degenerate arrows do not panic.
        r.draw_arrow(&mut img, &cam, sp(5.0, 5.0), sp(5.0, 5.0), 2.0, 10.0, red);
        r.draw_arrow(
            &mut img,
            &cam,
            sp(5.0, 5.0),
            sp(9.0, 5.0),
            f64::NAN,
            f64::INFINITY,
            red,
        );
    }
}
