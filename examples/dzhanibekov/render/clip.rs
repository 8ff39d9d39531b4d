//! Clipping and projection of primitives: projected [`ScreenVertex`]es,
//! the fixed-capacity [`Polygon`] with its Sutherland–Hodgman clip, and
//! near-plane clipping of segments.

use glam::DVec3;

use super::{Camera, NEAR_DEPTH};

/// Capacity of the fixed-size polygons produced by clipping a triangle
/// against the near plane (≤ 4 vertices) and the four guard-band planes.
const MAX_POLY: usize = 10;

/// A projected vertex: screen position in pixels and `w = 1/depth`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(super) struct ScreenVertex {
    pub(super) x: f64,
    pub(super) y: f64,
    pub(super) w: f64,
}

impl ScreenVertex {
    pub(super) fn is_finite(&self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.w.is_finite()
    }

    pub(super) fn lerp(&self, other: &Self, t: f64) -> Self {
        Self {
            x: self.x + (other.x - self.x) * t,
            y: self.y + (other.y - self.y) * t,
            w: self.w + (other.w - self.w) * t,
        }
    }
}

/// A small fixed-capacity convex polygon used for clipping (no allocation).
#[derive(Clone, Copy)]
pub(super) struct Polygon<T: Copy + Default> {
    verts: [T; MAX_POLY],
    len: usize,
}

impl<T: Copy + Default> Polygon<T> {
    pub(super) fn new() -> Self {
        Self {
            verts: [T::default(); MAX_POLY],
            len: 0,
        }
    }

    pub(super) fn from_slice(vs: &[T]) -> Self {
        let mut p = Self::new();
        for &v in vs {
            p.push(v);
        }
        p
    }

    /// Appends a vertex; silently ignored when full (cannot happen for the
    /// clipping sequences used here).
    pub(super) fn push(&mut self, v: T) {
        if let Some(slot) = self.verts.get_mut(self.len) {
            *slot = v;
            self.len += 1;
        }
    }

    pub(super) fn as_slice(&self) -> &[T] {
        self.verts.get(..self.len).unwrap_or(&[])
    }

    /// Sutherland–Hodgman clip keeping the part where `dist ≥ 0`.
    pub(super) fn clip(&self, dist: impl Fn(&T) -> f64, lerp: impl Fn(&T, &T, f64) -> T) -> Self {
        let vs = self.as_slice();
        let mut out = Self::new();
        let Some(&last) = vs.last() else {
            return out;
        };
        let mut prev = last;
        let mut d_prev = dist(&prev);
        for &cur in vs {
            let d_cur = dist(&cur);
            if (d_prev >= 0.0) != (d_cur >= 0.0) {
                out.push(lerp(&prev, &cur, d_prev / (d_prev - d_cur)));
            }
            if d_cur >= 0.0 {
                out.push(cur);
            }
            prev = cur;
            d_prev = d_cur;
        }
        out
    }
}

/// Projects a view-space point that has already been clipped to the near
/// plane (so its depth is at least `NEAR_DEPTH`, up to rounding).
pub(super) fn project_clipped(camera: &Camera, v: DVec3) -> ScreenVertex {
    let depth = (camera.distance - v.z).max(NEAR_DEPTH);
    ScreenVertex {
        x: camera.center_px.0 + camera.focal_px * v.x / depth,
        y: camera.center_px.1 - camera.focal_px * v.y / depth,
        w: 1.0 / depth,
    }
}

/// Clips the world segment `a`–`b` to the near plane and projects it.
pub(super) fn clip_project_segment(
    camera: &Camera,
    a: DVec3,
    b: DVec3,
) -> Option<(ScreenVertex, ScreenVertex)> {
    let mut va = camera.world_to_view(a);
    let mut vb = camera.world_to_view(b);
    if !(va.is_finite() && vb.is_finite() && camera.distance.is_finite()) {
        return None;
    }
    let da = camera.distance - va.z - NEAR_DEPTH;
    let db = camera.distance - vb.z - NEAR_DEPTH;
    if da < 0.0 && db < 0.0 {
        return None;
    }
    if da < 0.0 {
        va += (vb - va) * (da / (da - db));
    } else if db < 0.0 {
        vb += (va - vb) * (db / (db - da));
    }
    let sa = project_clipped(camera, va);
    let sb = project_clipped(camera, vb);
    (sa.is_finite() && sb.is_finite()).then_some((sa, sb))
}
