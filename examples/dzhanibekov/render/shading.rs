//! Surface [`Material`]s, the camera-fixed [`Light`] and flat Blinn–Phong
//! shading of mesh faces.

use glam::DVec3;

use super::{channels, rgb};

/// Surface parameters for flat Blinn–Phong shading.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// Base colour, `0x00RRGGBB`.
    pub color: u32,
    /// Ambient factor (fraction of the base colour always present).
    pub ambient: f64,
    /// Lambert diffuse factor.
    pub diffuse: f64,
    /// Strength of the white specular highlight (0 disables it).
    pub specular: f64,
    /// Blinn–Phong exponent (larger = smaller, sharper highlight).
    pub shininess: f64,
}

impl Default for Material {
    /// A light grey-blue, mostly diffuse material with a modest highlight.
    fn default() -> Self {
        Self {
            color: 0x00B4_B8C8,
            ambient: 0.25,
            diffuse: 0.75,
            specular: 0.25,
            shininess: 32.0,
        }
    }
}

/// A directional light fixed to the camera.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    /// Direction *toward* the light in view coordinates (need not be
    /// normalised; a zero vector leaves only ambient light).
    pub direction_view: DVec3,
}

impl Default for Light {
    /// Light from the upper left, in front of the scene.
    fn default() -> Self {
        Self {
            direction_view: DVec3::new(-0.4, 0.6, 0.7).normalize(),
        }
    }
}

/// Flat Blinn–Phong shading of a face with view-space normal `normal` seen
/// from direction `to_eye`.
pub(super) fn shade(material: &Material, light: &Light, normal: DVec3, to_eye: DVec3) -> u32 {
    let n = normal.normalize_or_zero();
    let l = light.direction_view.normalize_or_zero();
    let lambert = n.dot(l).max(0.0);
    let highlight = if lambert > 0.0 && material.specular > 0.0 {
        let h = (l + to_eye.normalize_or_zero()).normalize_or_zero();
        n.dot(h).max(0.0).powf(material.shininess.max(1.0)) * material.specular
    } else {
        0.0
    };
    let k = material.ambient + material.diffuse * lambert;
    let (r, g, b) = channels(material.color);
    // `clamp` maps out-of-range values into 0..=255; NaN casts to 0.
    let ch = |c: u8| (f64::from(c) * k + 255.0 * highlight + 0.5).clamp(0.0, 255.0) as u8;
    rgb(ch(r), ch(g), ch(b))
}

#[cfg(test)]
mod tests {
    use glam::DQuat;

    use super::super::Camera;
    use super::super::test_util::*;
    use super::*;

    fn luminance(c: u32) -> u32 {
        let (r, g, b) = channels(c);
        u32::from(r) + u32::from(g) + u32::from(b)
    }

    #[test]
    fn face_toward_light_is_brighter() {
        let cam = Camera {
            view_from_world: DQuat::IDENTITY,
            distance: 10.0,
            focal_px: 20.0,
            center_px: (32.0, 32.0),
        };
        let light = Light {
            direction_view: DVec3::new(1.0, 0.0, 1.0),
        };
        let base = [
            DVec3::new(-1.0, -1.0, 0.0),
            DVec3::new(1.0, -1.0, 0.0),
            DVec3::new(0.0, 1.0, 0.0),
        ];
        // Tilted toward +x (toward the light) on the left, away on the right.
        let place = |angle: f64, dx: f64| {
            base.map(|p| DQuat::from_rotation_y(angle) * p + DVec3::new(dx, 0.0, 0.0))
        };
        // With and without the specular term (Lambert alone must do it).
        let no_spec = Material {
            specular: 0.0,
            ..Material::default()
        };
        for m in [Material::default(), no_spec] {
            let (mut img, mut r) = canvas();
            r.draw_mesh(&mut img, &cam, &place(0.7, -1.5), &[[0, 1, 2]], m, &light);
            r.draw_mesh(&mut img, &cam, &place(-0.7, 1.5), &[[0, 1, 2]], m, &light);
            let toward = img.pixel(29, 32).unwrap();
            let away = img.pixel(35, 32).unwrap();
            assert_ne!(toward, BG);
            assert_ne!(away, BG);
            assert!(
                luminance(toward) > luminance(away) + 60,
                "{toward:06x} vs {away:06x}"
            );
        }
    }

    #[test]
    fn shading_clamps_and_handles_degenerate_inputs() {
        let m = Material {
            color: WHITE,
            ambient: 3.0,
            diffuse: 1.0,
            specular: 5.0,
            shininess: 8.0,
        };
        let l = Light::default();
        assert_eq!(shade(&m, &l, l.direction_view, l.direction_view), WHITE);
        let dark = Material { ambient: -1.0, ..m };
        assert_eq!(
            shade(
                &dark,
                &Light {
                    direction_view: DVec3::ZERO
                },
                DVec3::Z,
                DVec3::Z
            ),
            0
        );
        let _ = shade(&m, &l, DVec3::NAN, DVec3::NAN);
    }
}
