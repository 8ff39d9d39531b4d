//! Drawing triangle meshes: back-face culling, shading, near-plane clipping
//! and filling of the clipped faces.

use glam::DVec3;

use super::clip::{Polygon, ScreenVertex, project_clipped};
use super::renderer::Bounds;
use super::shading::shade;
use super::{Camera, Image, Light, Material, NEAR_DEPTH, Renderer};

impl Renderer {
    /// Draws a triangle mesh: z-buffered, flat-shaded, back faces culled.
    ///
    /// `triangles` index into `vertices_world` and are counter-clockwise when
    /// seen from outside. Triangles with out-of-range indices, non-finite or
    /// collinear vertices, or lying behind the near plane are skipped;
    /// triangles crossing the near plane are clipped.
    pub fn draw_mesh(
        &mut self,
        image: &mut Image,
        camera: &Camera,
        vertices_world: &[DVec3],
        triangles: &[[u32; 3]],
        material: Material,
        light: &Light,
    ) {
        let Some(bounds) = self.bounds(image) else {
            return;
        };
        if !(camera.distance.is_finite() && camera.focal_px.is_finite()) {
            return;
        }
        let mut view = std::mem::take(&mut self.view_cache);
        view.clear();
        view.extend(vertices_world.iter().map(|&p| camera.world_to_view(p)));
        let eye = DVec3::new(0.0, 0.0, camera.distance);
        for &[ia, ib, ic] in triangles {
            let (Some(&a), Some(&b), Some(&c)) = (
                view.get(ia as usize),
                view.get(ib as usize),
                view.get(ic as usize),
            ) else {
                continue;
            };
            if !(a.is_finite() && b.is_finite() && c.is_finite()) {
                continue;
            }
            let normal = (b - a).cross(c - a);
            // Back-facing (or edge-on / degenerate) as seen from the eye.
            if !normal.is_finite() || normal.dot(eye - a) <= 0.0 {
                continue;
            }
            let centroid = (a + b + c) / 3.0;
            let color = shade(&material, light, normal, eye - centroid);
            let clipped = Polygon::from_slice(&[a, b, c]).clip(
                |v| camera.distance - v.z - NEAR_DEPTH,
                |p, q, t| *p + (*q - *p) * t,
            );
            let mut screen = Polygon::<ScreenVertex>::new();
            for &v in clipped.as_slice() {
                screen.push(project_clipped(camera, v));
            }
            self.fill_polygon(image, &bounds, &screen, color);
        }
        self.view_cache = view;
    }

    /// Fills a convex screen polygon (a clipped mesh face) as a triangle
    /// fan, culling it if it is back-facing.
    fn fill_polygon(
        &mut self,
        image: &mut Image,
        bounds: &Bounds,
        poly: &Polygon<ScreenVertex>,
        color: u32,
    ) {
        let vs = poly.as_slice();
        if vs.len() < 3 || !vs.iter().all(ScreenVertex::is_finite) {
            return;
        }
        let Some((&first, rest)) = vs.split_first() else {
            return;
        };
        for pair in rest.windows(2) {
            if let [p, q] = pair {
                self.fill_triangle(image, bounds, [first, *p, *q], color, true);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use glam::DQuat;

    use super::super::test_util::*;
    use super::*;

    #[test]
    fn front_triangle_covers_centroid_only() {
        let cam = screen_camera();
        let verts = [sp(20.0, 40.0), sp(40.0, 40.0), sp(30.0, 20.0)];
        let (mut img, mut r) = canvas();
        draw_flat(&mut r, &mut img, &cam, &verts, WHITE);
        // Centroid (30, 33.3) → pixel (30, 33).
        assert_eq!(img.pixel(30, 33), Some(WHITE));
        assert_eq!(img.pixel(5, 5), Some(BG));
        assert_eq!(img.pixel(30, 45), Some(BG));
        assert_eq!(img.pixel(22, 22), Some(BG));
        assert!((r.depth_at(30, 33).unwrap() - 10.0).abs() < 1e-5);
        assert!(r.depth_at(5, 5).is_none());
    }

    #[test]
    fn back_facing_triangle_is_culled() {
        let cam = screen_camera();
        let verts = [sp(20.0, 40.0), sp(30.0, 20.0), sp(40.0, 40.0)];
        let (mut img, mut r) = canvas();
        draw_flat(&mut r, &mut img, &cam, &verts, WHITE);
        assert!(img.pixels.iter().all(|&p| p == BG));
    }

    #[test]
    fn nearer_triangle_wins_in_either_order() {
        let cam = centred_camera();
        let tri = |z: f64| {
            [
                DVec3::new(-1.0, -1.0, z),
                DVec3::new(1.0, -1.0, z),
                DVec3::new(0.0, 1.0, z),
            ]
        };
        let (red, green) = (0x00FF_0000, 0x0000_FF00);
        for near_first in [false, true] {
            let (mut img, mut r) = canvas();
            let mut draw = |z: f64, color: u32| {
                draw_flat(&mut r, &mut img, &cam, &tri(z), color);
            };
            if near_first {
                draw(1.0, green);
                draw(0.0, red);
            } else {
                draw(0.0, red);
                draw(1.0, green);
            }
            assert_eq!(img.pixel(32, 32), Some(green), "near_first = {near_first}");
        }
    }

    #[test]
    fn triangle_crossing_near_plane_is_clipped() {
        let cam = centred_camera();
        // One vertex far behind the eye; the visible part fans out hugely.
        let verts = [
            DVec3::new(-10.0, -1.0, 0.0),
            DVec3::new(10.0, -1.0, 0.0),
            DVec3::new(0.0, -1.0, 30.0),
        ];
        let mut drawn = Vec::new();
        for tri in [[0, 1, 2], [0, 2, 1]] {
            let (mut img, mut r) = canvas();
            r.draw_mesh(
                &mut img,
                &cam,
                &verts,
                &[tri],
                flat(WHITE),
                &Light::default(),
            );
            drawn.push(img.pixels.iter().filter(|&&p| p != BG).count());
        }
        // Exactly one winding faces the eye; it covers the lower half.
        assert_eq!(drawn.iter().filter(|&&n| n > 0).count(), 1, "{drawn:?}");
        assert!(drawn.iter().any(|&n| n >= 64 * 20), "{drawn:?}");
    }

    /// Unit cube centred at the origin, CCW from outside.
    fn cube() -> (Vec<DVec3>, Vec<[u32; 3]>) {
        let verts: Vec<DVec3> = (0..8)
            .map(|i| {
                DVec3::new(
                    if i & 1 == 0 { -0.5 } else { 0.5 },
                    if i & 2 == 0 { -0.5 } else { 0.5 },
                    if i & 4 == 0 { -0.5 } else { 0.5 },
                )
            })
            .collect();
        let quads = [
            [0, 4, 6, 2], // -x
            [1, 3, 7, 5], // +x
            [0, 1, 5, 4], // -y
            [2, 6, 7, 3], // +y
            [0, 2, 3, 1], // -z
            [4, 5, 7, 6], // +z
        ];
        let tris = quads
            .iter()
            .flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]])
            .collect();
        (verts, tris)
    }

    #[test]
    fn cube_winding_is_outward() {
        let (v, t) = cube();
        for tri in &t {
            let [a, b, c] = tri.map(|i| v[i as usize]);
            let n = (b - a).cross(c - a);
            assert!(n.dot((a + b + c) / 3.0) > 0.0);
        }
    }

    #[test]
    fn rotated_cube_is_crack_free_and_single_layer() {
        let (verts, tris) = cube();
        let q = DQuat::from_axis_angle(DVec3::new(1.0, 2.0, 0.5).normalize(), 0.9);
        let verts: Vec<DVec3> = verts.iter().map(|&p| q * p).collect();
        let cam = Camera {
            view_from_world: DQuat::IDENTITY,
            distance: 4.0,
            focal_px: 100.0,
            center_px: (32.3, 31.7),
        };
        let counts = hit_counts(64, &cam, &verts, &tris);
        assert!(counts.iter().all(|&c| c <= 1), "overlapping front faces");
        assert!(counts.iter().filter(|&&c| c == 1).count() > 500);
        // The silhouette of a convex body is convex: every row and column of
        // covered pixels must be one contiguous run (a crack would split it).
        let runs = |line: Vec<u32>| {
            line.windows(2).filter(|w| w[0] == 0 && w[1] == 1).count()
                + usize::from(line.first() == Some(&1))
        };
        for i in 0..64 {
            assert!(
                runs((0..64).map(|x| counts[i * 64 + x]).collect()) <= 1,
                "row {i}"
            );
            assert!(
                runs((0..64).map(|y| counts[y * 64 + i]).collect()) <= 1,
                "col {i}"
            );
        }
    }
}
