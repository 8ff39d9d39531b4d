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

/// Camera on the +z axis, 10 m from the origin, 30 px focal length,
/// centred on a 64×64 image.
pub(super) fn centred_camera() -> Camera {
    Camera {
        view_from_world: DQuat::IDENTITY,
        distance: 10.0,
        focal_px: 30.0,
        center_px: (32.0, 32.0),
    }
}

/// A 64×64 image of `BG` and a renderer clipped to all of it.
pub(super) fn canvas() -> (Image, Renderer) {
    let mut r = Renderer::new(64, 64);
    r.begin(ClipRect::full(64, 64));
    (Image::new(64, 64, BG), r)
}

/// Draws the triangle `verts[0..3]` in flat `color` under the default light.
pub(super) fn draw_flat(
    r: &mut Renderer,
    img: &mut Image,
    camera: &Camera,
    verts: &[DVec3],
    color: u32,
) {
    r.draw_mesh(
        img,
        camera,
        verts,
        &[[0, 1, 2]],
        flat(color),
        &Light::default(),
    );
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
