//! The [`Renderer`]: depth buffer, frame setup and the per-draw-call
//! drawable [`Bounds`]. Its drawing methods live in `mesh`, `lines` and
//! `raster`.

use glam::DVec3;

use super::raster::GUARD_PX;
use super::{Camera, ClipRect, Image, LINE_DEPTH_BIAS};

/// Software rasteriser owning a depth buffer for one image size.
///
/// Call [`Renderer::begin`] once per frame with the panel rectangle, then the
/// `draw_*` methods; they only touch pixels inside that rectangle.
#[derive(Clone, Debug)]
pub struct Renderer {
    pub(super) width: usize,
    height: usize,
    /// `1/depth` per pixel (single precision to halve memory traffic); 0 means "nothing drawn yet" (infinitely far).
    pub(super) depth: Vec<f32>,
    clip: ClipRect,
    /// Reused buffer of view-space mesh vertices.
    pub(super) view_cache: Vec<DVec3>,
    /// Relative depth bias for lines and arrows (see [`LINE_DEPTH_BIAS`]).
    pub line_depth_bias: f64,
}

/// The drawable pixel rectangle of one draw call: the clip rectangle
/// intersected with the image, the depth buffer and the guard band.
#[derive(Clone, Copy, Debug)]
pub(super) struct Bounds {
    pub(super) x0: usize,
    pub(super) y0: usize,
    pub(super) x1: usize,
    pub(super) y1: usize,
}

impl Renderer {
    /// A renderer for `width × height` images; the clip rectangle starts as
    /// the whole image.
    pub fn new(width: usize, height: usize) -> Self {
        Self {
            width,
            height,
            depth: vec![0.0; width.saturating_mul(height)],
            clip: ClipRect::full(width, height),
            view_cache: Vec::new(),
            line_depth_bias: LINE_DEPTH_BIAS,
        }
    }

    /// Width of the depth buffer in pixels.
    pub fn width(&self) -> usize {
        self.width
    }

    /// Height of the depth buffer in pixels.
    pub fn height(&self) -> usize {
        self.height
    }

    /// The current clip rectangle (already limited to the renderer size).
    pub fn clip(&self) -> ClipRect {
        self.clip
    }

    /// Starts a frame: sets the clip rectangle and clears the depth buffer
    /// inside it. Pixels of the image are not touched (fill the panel
    /// background with [`Image::fill_rect`]).
    pub fn begin(&mut self, clip: ClipRect) {
        self.clip = clip.intersect(&ClipRect::full(self.width, self.height));
        for row in self.clip.y..self.clip.bottom() {
            let start = row * self.width;
            if let Some(span) = self
                .depth
                .get_mut(start + self.clip.x..start + self.clip.right())
            {
                span.fill(0.0);
            }
        }
    }

    /// Depth of the nearest surface drawn at pixel `(x, y)` this frame, or
    /// `None` if nothing was drawn there (or outside the buffer).
    pub fn depth_at(&self, x: usize, y: usize) -> Option<f64> {
        if x >= self.width || y >= self.height {
            return None;
        }
        let w = *self.depth.get(y * self.width + x)?;
        (w > 0.0).then(|| 1.0 / f64::from(w))
    }

    /// Screen position of a world point for placing labels; same as
    /// [`Camera::screen_position`].
    pub fn screen_position(&self, camera: &Camera, p_world: DVec3) -> Option<(f64, f64)> {
        camera.screen_position(p_world)
    }

    /// The drawable rectangle for `image`, or `None` if nothing can be drawn
    /// (empty clip or an image whose pixel buffer is inconsistent).
    pub(super) fn bounds(&self, image: &Image) -> Option<Bounds> {
        let needed = image.width.checked_mul(image.height)?;
        if image.pixels.len() < needed {
            return None;
        }
        let r = self
            .clip
            .intersect(&ClipRect::full(image.width, image.height))
            .intersect(&ClipRect::full(GUARD_PX, GUARD_PX));
        (!r.is_empty()).then_some(Bounds {
            x0: r.x,
            y0: r.y,
            x1: r.right(),
            y1: r.bottom(),
        })
    }
}

#[cfg(test)]
mod tests {
    use glam::DQuat;

    use super::super::test_util::*;
    use super::super::{Light, Material};
    use super::*;

    #[test]
    fn begin_resets_depth() {
        let cam = screen_camera();
        let near = [sp(10.0, 50.0), sp(50.0, 50.0), sp(30.0, 10.0)].map(|p| p + DVec3::Z);
        let far = [sp(10.0, 50.0), sp(50.0, 50.0), sp(30.0, 10.0)];
        let (mut img, mut r) = canvas();
        draw_flat(&mut r, &mut img, &cam, &near, WHITE);
        r.begin(ClipRect::full(64, 64));
        draw_flat(&mut r, &mut img, &cam, &far, 0x0000_00FF);
        assert_eq!(img.pixel(30, 40), Some(0x0000_00FF));
    }

    #[test]
    fn nothing_drawn_outside_clip_rect() {
        let cam = Camera {
            view_from_world: DQuat::IDENTITY,
            distance: 10.0,
            focal_px: 50.0,
            center_px: (50.0, 50.0),
        };
        let clip = ClipRect::new(20, 30, 40, 25);
        let mut img = Image::new(100, 100, BG);
        let mut r = Renderer::new(100, 100);
        r.begin(clip);
        let big = [
            DVec3::new(-50.0, -50.0, 0.0),
            DVec3::new(50.0, -50.0, 0.0),
            DVec3::new(0.0, 50.0, 0.0),
        ];
        draw_flat(&mut r, &mut img, &cam, &big, WHITE);
        let red = 0x00FF_0000;
        r.draw_line(
            &mut img,
            &cam,
            DVec3::new(-9.0, -9.0, 1.0),
            DVec3::new(9.0, 9.0, 1.0),
            5.0,
            red,
        );
        r.draw_arrow(
            &mut img,
            &cam,
            DVec3::new(-9.0, 9.0, 1.0),
            DVec3::new(9.0, -9.0, 1.0),
            5.0,
            30.0,
            red,
        );
        for y in 0..100 {
            for x in 0..100 {
                let inside = clip.contains(x as f64, y as f64);
                let p = img.pixel(x, y).unwrap();
                assert_eq!(p != BG, inside, "pixel ({x}, {y})");
            }
        }
    }

    #[test]
    fn bad_geometry_neither_panics_nor_draws() {
        let cam = screen_camera();
        let nan = DVec3::new(f64::NAN, 0.0, 0.0);
        let verts = [
            sp(20.0, 40.0),
            sp(40.0, 40.0),
            sp(30.0, 20.0),
            nan,
            sp(25.0, 25.0), // collinear with 0 and 2's midpoint region below
            DVec3::new(1.0, 1.0, 20.0), // behind the eye
            DVec3::new(2.0, 1.0, 30.0),
            DVec3::new(1.0, 2.0, 25.0),
            DVec3::new(f64::INFINITY, 1.0, 0.0),
        ];
        let tris = [
            [0, 1, 3],        // NaN vertex
            [0, 1, 99],       // index out of range
            [0, 0, 1],        // repeated vertex
            [0, 2, 2],        // degenerate
            [0, 4, 4],        // degenerate
            [5, 6, 7],        // behind the camera
            [0, 1, 8],        // infinite vertex
            [u32::MAX, 0, 1], // index out of range
        ];
        let (mut img, mut r) = canvas();
        r.draw_mesh(
            &mut img,
            &cam,
            &verts,
            &tris,
            Material::default(),
            &Light::default(),
        );
        r.draw_line(&mut img, &cam, nan, sp(1.0, 1.0), 3.0, WHITE);
        r.draw_line(
            &mut img,
            &cam,
            DVec3::new(0.0, 0.0, 11.0),
            DVec3::new(1.0, 0.0, 12.0),
            3.0,
            WHITE,
        );
        r.draw_arrow(&mut img, &cam, sp(1.0, 1.0), nan, 3.0, 8.0, WHITE);
        r.draw_line(&mut img, &cam, sp(1.0, 1.0), sp(9.0, 9.0), f64::NAN, WHITE);
        // Off-screen geometry.
        r.draw_mesh(
            &mut img,
            &cam,
            &[sp(-50.0, 1.0), sp(-40.0, 1.0), sp(-45.0, -9.0)],
            &[[0, 1, 2]],
            Material::default(),
            &Light::default(),
        );
        assert!(img.pixels.iter().all(|&p| p == BG), "something was drawn");
        // A NaN camera draws nothing either.
        let bad_cam = Camera {
            focal_px: f64::NAN,
            ..cam
        };
        r.draw_mesh(
            &mut img,
            &bad_cam,
            &verts,
            &[[0, 1, 2]],
            Material::default(),
            &Light::default(),
        );
        r.draw_line(&mut img, &bad_cam, sp(1.0, 1.0), sp(9.0, 9.0), 3.0, WHITE);
        assert!(img.pixels.iter().all(|&p| p == BG), "bad camera drew");
        // An image whose buffer does not match its size is left alone.
        let mut broken = Image {
            width: 64,
            height: 64,
            pixels: vec![BG; 10],
        };
        r.draw_mesh(
            &mut broken,
            &cam,
            &verts,
            &[[0, 1, 2]],
            Material::default(),
            &Light::default(),
        );
        assert!(broken.pixels.iter().all(|&p| p == BG));
    }
}
