//! The perspective [`Camera`]: world → view rotation and projection to the
//! screen.

use glam::{DMat3, DQuat, DVec3};

use super::ClipRect;

/// Smallest depth (distance in front of the eye along the viewing axis) that
/// is drawn; geometry closer than this is clipped away.
pub const NEAR_DEPTH: f64 = 1e-3;

/// A perspective camera looking down the view-space `−z` axis.
///
/// View coordinates: `x` right, `y` up, `z` toward the viewer; the eye is at
/// view `(0, 0, distance)`, so the world origin appears at `center_px`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// Rotation taking world coordinates to view coordinates (unit quaternion).
    pub view_from_world: DQuat,
    /// Distance from the eye to the view-space origin.
    pub distance: f64,
    /// Focal length in pixels.
    pub focal_px: f64,
    /// Screen position (pixels) of the view axis, i.e. of the origin.
    pub center_px: (f64, f64),
}

impl Camera {
    /// A camera whose eye lies in direction `eye_direction_world` from the
    /// world origin, looking at the origin, with `up_world` appearing as up
    /// on screen (as nearly as possible). Degenerate directions fall back to
    /// any valid orientation (identity if the eye direction is unusable).
    pub fn looking_at_origin(
        eye_direction_world: DVec3,
        up_world: DVec3,
        distance: f64,
        focal_px: f64,
        center_px: (f64, f64),
    ) -> Self {
        Self {
            view_from_world: view_rotation(eye_direction_world, up_world),
            distance,
            focal_px,
            center_px,
        }
    }

    /// A camera centred on `panel` whose vertical field of view is
    /// `vertical_fov_rad` (radians) across the panel height.
    pub fn for_panel(
        view_from_world: DQuat,
        distance: f64,
        vertical_fov_rad: f64,
        panel: ClipRect,
    ) -> Self {
        let focal_px = panel.height as f64 * 0.5 / (vertical_fov_rad * 0.5).tan();
        Self {
            view_from_world,
            distance,
            focal_px,
            center_px: panel.center(),
        }
    }

    /// World → view coordinates.
    pub fn world_to_view(&self, p_world: DVec3) -> DVec3 {
        self.view_from_world * p_world
    }

    /// Projects a view-space point to `(x_px, y_px, depth)`, or `None` if it
    /// is not finite or not in front of the near plane
    /// (`depth ≤` [`NEAR_DEPTH`]).
    pub fn project_view(&self, p_view: DVec3) -> Option<(f64, f64, f64)> {
        let depth = self.distance - p_view.z;
        if depth.is_nan() || depth <= NEAR_DEPTH {
            return None;
        }
        let x = self.center_px.0 + self.focal_px * p_view.x / depth;
        let y = self.center_px.1 - self.focal_px * p_view.y / depth;
        (x.is_finite() && y.is_finite() && depth.is_finite()).then_some((x, y, depth))
    }

    /// Projects a world-space point to `(x_px, y_px, depth)`; see
    /// [`Camera::project_view`].
    pub fn project(&self, p_world: DVec3) -> Option<(f64, f64, f64)> {
        self.project_view(self.world_to_view(p_world))
    }

    /// Screen position (pixels, `y` down) of a world point, e.g. to place a
    /// text label; `None` if the point is behind the near plane. The result
    /// may lie outside the image.
    pub fn screen_position(&self, p_world: DVec3) -> Option<(f64, f64)> {
        self.project(p_world).map(|(x, y, _)| (x, y))
    }
}

/// Rotation taking world to view coordinates for an eye in direction
/// `eye_direction` from the origin with `up` as the preferred screen up.
fn view_rotation(eye_direction: DVec3, up: DVec3) -> DQuat {
    let back = eye_direction.normalize_or_zero();
    if back == DVec3::ZERO {
        return DQuat::IDENTITY;
    }
    let mut right = up.cross(back);
    if !right.is_finite() || right.length_squared() < 1e-24 {
        right = back.any_orthonormal_vector();
    }
    let right = right.normalize();
    let true_up = back.cross(right);
    let world_from_view = DQuat::from_mat3(&DMat3::from_cols(right, true_up, back));
    world_from_view.inverse().normalize()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn projection_formula() {
        let cam = Camera {
            view_from_world: DQuat::from_rotation_y(std::f64::consts::FRAC_PI_2),
            distance: 10.0,
            focal_px: 100.0,
            center_px: (50.0, 40.0),
        };
        // Rotating +90° about y maps world (1, 2, 3) to view (3, 2, −1).
        let v = cam.world_to_view(DVec3::new(1.0, 2.0, 3.0));
        assert!((v - DVec3::new(3.0, 2.0, -1.0)).length() < 1e-12);
        let (x, y, depth) = cam.project(DVec3::new(1.0, 2.0, 3.0)).unwrap();
        assert!((depth - 11.0).abs() < 1e-12);
        assert!((x - (50.0 + 100.0 * 3.0 / 11.0)).abs() < 1e-9);
        assert!((y - (40.0 - 100.0 * 2.0 / 11.0)).abs() < 1e-9);
        // View z = distance (the eye) and beyond are not projected.
        assert!(cam.project_view(DVec3::new(0.0, 0.0, 10.0)).is_none());
        assert!(cam.project_view(DVec3::new(1.0, 0.0, 12.0)).is_none());
        assert!(cam.project_view(DVec3::new(f64::NAN, 0.0, 0.0)).is_none());
        assert_eq!(cam.screen_position(DVec3::ZERO), Some((50.0, 40.0)));
    }

    #[test]
    fn looking_at_origin_is_right_handed() {
        let cam = Camera::looking_at_origin(DVec3::X, DVec3::Z, 5.0, 100.0, (0.0, 0.0));
        // Eye direction → toward the viewer, up → up, and y = z × x → right.
        assert!((cam.world_to_view(DVec3::X) - DVec3::Z).length() < 1e-12);
        assert!((cam.world_to_view(DVec3::Z) - DVec3::Y).length() < 1e-12);
        assert!((cam.world_to_view(DVec3::Y) - DVec3::X).length() < 1e-12);
        // Degenerate input still yields a valid rotation.
        let cam = Camera::looking_at_origin(DVec3::Y, DVec3::Y, 5.0, 100.0, (0.0, 0.0));
        assert!((cam.world_to_view(DVec3::Y) - DVec3::Z).length() < 1e-12);
        let cam = Camera::looking_at_origin(DVec3::ZERO, DVec3::Y, 5.0, 100.0, (0.0, 0.0));
        assert_eq!(cam.view_from_world, DQuat::IDENTITY);
    }

    #[test]
    fn for_panel_centres_on_panel() {
        let panel = ClipRect::new(100, 20, 200, 100);
        let cam = Camera::for_panel(DQuat::IDENTITY, 5.0, std::f64::consts::FRAC_PI_2, panel);
        assert_eq!(cam.center_px, (200.0, 70.0));
        assert!((cam.focal_px - 50.0).abs() < 1e-9);
    }
}
