//! Helpers shared by the unit tests of the renderer modules.

use glam::{DQuat, DVec3};

use super::{Camera, ClipRect, Image, Light, Material, Renderer};

pub(super) const BG: u32 = 0x0000_0000;
pub(super) const WHITE: u32 = 0x00FF_FFFF;

/// Camera for which the world point `(x, −y, 0)` lands on screen `(x, y)`.
pub(super) fn screen_camera() -> Camera {
    Camera {
        view_from_world: DQuat::IDENTITY,
        distance: 10.0,
        focal_px: 10.0,
        center_px: (0.0, 0.0),
    }
}

/// World point (on the plane z = 0) that `screen_camera` maps to `(x, y)`.
pub(super) fn sp(x: f64, y: f64) -> DVec3 {
    DVec3::new(x, -y, 0.0)
}

/// Material whose shaded colour is exactly `color` regardless of normal.
pub(super) fn flat(color: u32) -> Material {
    Material {
        color,
        ambient: 1.0,
        diffuse: 0.0,
        specular: 0.0,
        shininess: 1.0,
    }
}

/// Draws each triangle alone (fresh depth) and counts per-pixel hits.
pub(super) fn hit_counts(
    size: usize,
    camera: &Camera,
    verts: &[DVec3],
    tris: &[[u32; 3]],
) -> Vec<u32> {
    let mut counts = vec![0u32; size * size];
    let mut r = Renderer::new(size, size);
    for tri in tris {
        let mut img = Image::new(size, size, BG);
        r.begin(ClipRect::full(size, size));
        r.draw_mesh(
            &mut img,
            camera,
            verts,
            &[*tri],
            flat(WHITE),
            &Light::default(),
        );
        for (c, &p) in counts.iter_mut().zip(&img.pixels) {
            *c += u32::from(p != BG);
        }
    }
    counts
}
