//! The numbers of an `<inertial>` element: mass, origin, orientation and
//! tensor, in full or principal form, optionally rounded, always loadable.
//!
//! Full form: the origin at the centre of mass with the output frame's axes
//! (`rpy = 0 0 0`) and the whole tensor. Principal form (`--principal`): the
//! origin rotated onto the principal axes (URDF `rpy`, SDFormat `pose`, MJCF
//! `quat`) and the diagonal `ixx ≤ iyy ≤ izz` with zero products, for
//! simulators that diagonalise the tensor themselves (a rotation matrix is
//! right-handed, so the axes are the right-handed frame of [`PrincipalAxes`]).
//!
//! Loadable by construction: MuJoCo (and Gazebo) refuse a tensor whose
//! principal moments break `A + B ≥ C`, and MuJoCo computes them itself from
//! `fullinertia`. A flat body (a sheet, a shell of a plane polygon) has
//! `A + B = C` exactly, so rounding alone puts it on either side: measured
//! on 40 tilted sheets, 10 were refused with `A + B − C ≈ −3e-16`. The
//! smallest principal moment is raised until `A + B − C` and `A` are at
//! least [`MARGIN_ULPS`] ulps of `C` (never more than that beyond the
//! rounding it undoes: a relative change of ~1e-14), so that any
//! eigen-solver's own rounding keeps the inequality; other tensors are
//! written unchanged.
//!
//! With `digits` (`--digits N`) every number is rounded to N significant
//! digits, and a product of inertia below the last digit of the largest
//! moment (round-off such as `6.4e-23` next to `1e-5`) becomes exactly 0;
//! so do centre-of-mass components below the last digit of the largest one
//! and angles below the last digit of π. Rounding can break the inequality
//! (a sheet, a thin rod tilted against the axes): then the smallest moment
//! is raised before rounding, step by step, until the *rounded* numbers pass
//! the same test — what is written is checked, not what was meant.

use glam::{DMat3, DQuat, DVec3};
use kreisel_inertia::PrincipalAxes;
use kreisel_kinematics::{Axis, EulerSequence, Frame};

use super::rounding::{significant, snapped, snapped_all};

/// How far (in ulps of the largest moment) `A + B` must exceed `C`, and `A`
/// exceed 0, in a written tensor: covers the rounding of rebuilding the
/// tensor and of the reader's eigen-decomposition (a few ulps each).
pub const MARGIN_ULPS: f64 = 64.0;

/// How many times a rounded tensor is raised before giving up on
/// validity (each step at least doubles the raise: far more than enough).
const MAX_RAISES: usize = 200;

/// How an inertial is written (`--principal`, `--digits`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct InertialForm {
    /// The principal form: the origin rotated onto the principal axes and a
    /// diagonal tensor; otherwise the full tensor in the output frame's axes.
    pub principal: bool,
    /// Significant digits of every number (1 to 17); `None`: shortest
    /// round-trip form, nothing lost.
    pub digits: Option<u32>,
}

/// The numbers an `<inertial>` element holds, as they are written.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Inertial {
    /// Mass, kg.
    pub mass: f64,
    /// The inertial frame's origin (the centre of mass) in the output frame, m.
    pub xyz: DVec3,
    /// The inertial frame's orientation as URDF/SDFormat roll, pitch, yaw, rad:
    /// `output_from_inertial = Rz(yaw) · Ry(pitch) · Rx(roll)`; zero in full form.
    pub rpy: DVec3,
    /// The same orientation as MJCF's `quat` (w, x, y, z; `output_from_inertial`).
    pub quat: DQuat,
    /// The tensor about the centre of mass in the inertial frame's axes,
    /// kg m² (diagonal in principal form: the principal moments ascending,
    /// except where the smallest was raised past the middle one to keep
    /// `A + B ≥ C`, which needs the two smallest equal to the precision written).
    pub inertia: DMat3,
}

/// URDF's `rpy`: extrinsic x-y-z, `R = Rz(yaw) Ry(pitch) Rx(roll)`.
pub fn rpy_sequence() -> EulerSequence {
    EulerSequence::new([Axis::X, Axis::Y, Axis::Z], Frame::Extrinsic)
}

impl InertialForm {
    /// The written numbers of a body with `mass`, `center_of_mass` and
    /// `inertia` about the centre of mass, both in the output frame (the
    /// link frame, or the mesh frame).
    ///
    /// ```text
    /// full:       xyz = c,  rpy = 0,                 I_written = I  (raised if needed)
    /// principal:  xyz = c,  R(rpy) = principal axes,  I_written = diag(I₁, I₂, I₃),
    ///             R · diag · Rᵀ = I
    /// ```
    ///
    /// Independent of any report: the single-mesh writers and the URDF
    /// filler call it alike. The rpy reproduces the axes to a few ulps also
    /// at pitch ±π/2 (where roll and yaw are not unique and roll is chosen 0).
    ///
    /// ```
    /// use glam::{DMat3, DVec3};
    /// use kreisel_cli::inertia::InertialForm;
    /// // Round-off products like 6.4e-23 become 0 at 6 digits.
    /// let mut i = DMat3::from_diagonal(DVec3::new(4.7105e-6, 1.07163e-5, 6.36557e-6));
    /// i.x_axis.y = 6.4e-23;
    /// i.y_axis.x = 6.4e-23;
    /// let form = InertialForm { principal: false, digits: Some(6) };
    /// let written = form.inertial(0.0296, DVec3::new(0.0, 0.0, 0.046), i);
    /// assert_eq!(written.inertia.x_axis.y, 0.0);
    /// assert_eq!(written.inertia.y_axis.y, 1.07163e-5);
    /// ```
    pub fn inertial(self, mass: f64, center_of_mass: DVec3, inertia: DMat3) -> Inertial {
        let principal = PrincipalAxes::from_tensor(inertia);
        let digits = self.digits;
        let mass = digits.map_or(mass, |n| significant(mass, n));
        let xyz = digits.map_or(center_of_mass, |n| {
            DVec3::from_array(snapped_all(center_of_mass.to_array(), 0.0, n))
        });
        if !self.principal {
            return Inertial {
                mass,
                xyz,
                rpy: DVec3::ZERO,
                quat: DQuat::IDENTITY,
                inertia: match digits {
                    None => loadable_tensor(inertia, &principal),
                    Some(n) => rounded_tensor(inertia, &principal, n),
                },
            };
        }
        let moments = match digits {
            None => loadable_moments(principal.moments),
            Some(n) => rounded_moments(principal.moments, n),
        };
        let exact = principal.orientation;
        let rpy = rpy_sequence().from_quat(exact).angles;
        let (rpy, quat) = match digits {
            None => (rpy, exact),
            Some(n) => {
                // Each rounded from the exact orientation: the closest
                // N-digit angles, and the closest N-digit quaternion (which
                // readers normalise).
                let rpy = rpy.map(|a| snapped(a, core::f64::consts::PI, n));
                let q = exact;
                let [w, x, y, z] = snapped_all([q.w, q.x, q.y, q.z], 1.0, n);
                (rpy, DQuat::from_xyzw(x, y, z, w))
            }
        };
        Inertial {
            mass,
            xyz,
            rpy,
            quat,
            inertia: DMat3::from_diagonal(moments),
        }
    }
}

/// How much `A + B − C` and `A` fall short of [`MARGIN_ULPS`] ulps of `C`
/// (≤ 0: the moments are loadable).
pub fn shortfall(moments: DVec3) -> f64 {
    let margin = MARGIN_ULPS * f64::EPSILON * moments.z.abs();
    (moments.z - moments.x - moments.y + margin).max(margin - moments.x)
}

/// Whether a tensor's principal moments pass [`shortfall`].
///
/// ```text
/// A ≥ 64 ulp(C),   A + B − C ≥ 64 ulp(C)
/// ```
///
/// ```
/// use glam::{DMat3, DVec3};
/// use kreisel_cli::inertia::is_loadable;
/// assert!(is_loadable(DMat3::from_diagonal(DVec3::new(1.0, 1.0, 1.9))));
/// // A flat body exactly at A + B = C is too close to call for a reader.
/// assert!(!is_loadable(DMat3::from_diagonal(DVec3::new(1.0, 1.0, 2.0))));
/// ```
pub fn is_loadable(tensor: DMat3) -> bool {
    shortfall(PrincipalAxes::from_tensor(tensor).moments) <= 0.0
}

/// The moments with the smallest raised by the [`shortfall`], if any.
fn loadable_moments(m: DVec3) -> DVec3 {
    let lift = shortfall(m);
    if lift <= 0.0 {
        m
    } else {
        DVec3::new(m.x + lift, m.y, m.z)
    }
}

/// The tensor unchanged when loadable, else rebuilt from its axes with the
/// smallest moment raised.
fn loadable_tensor(tensor: DMat3, p: &PrincipalAxes) -> DMat3 {
    let moments = loadable_moments(p.moments);
    if moments == p.moments {
        return tensor;
    }
    let r = p.axes;
    let t = r * DMat3::from_diagonal(moments) * r.transpose();
    (t + t.transpose()) * 0.5
}

/// The tensor's elements rounded: diagonal to `digits`, products snapped
/// against the largest moment.
fn round_elements(t: DMat3, largest: f64, digits: u32) -> DMat3 {
    let d = |x: f64| significant(x, digits);
    let o = |x: f64| snapped(x, largest, digits);
    let (xy, xz, yz) = (o(t.y_axis.x), o(t.z_axis.x), o(t.z_axis.y));
    DMat3::from_cols(
        DVec3::new(d(t.x_axis.x), xy, xz),
        DVec3::new(xy, d(t.y_axis.y), yz),
        DVec3::new(xz, yz, d(t.z_axis.z)),
    )
}

/// Raises `lift` for the next try: by the shortfall, at least one last digit
/// of the largest moment, and at least doubling (so the loop ends).
fn next_lift(lift: f64, short: f64, largest: f64, digits: u32) -> f64 {
    let step = 2.0 * super::rounding::resolution(largest, digits);
    lift + short.max(step).max(lift)
}

/// The tensor rounded to `digits`, with the smallest moment raised (before
/// rounding) until the rounded tensor is loadable.
fn rounded_tensor(tensor: DMat3, p: &PrincipalAxes, digits: u32) -> DMat3 {
    let largest = p.moments.z;
    let e1 = p.axes.x_axis;
    let along = DMat3::from_cols(e1 * e1.x, e1 * e1.y, e1 * e1.z);
    let mut lift = 0.0;
    let mut written = round_elements(tensor, largest, digits);
    for _ in 0..MAX_RAISES {
        let short = shortfall(PrincipalAxes::from_tensor(written).moments);
        if short <= 0.0 {
            break;
        }
        lift = next_lift(lift, short, largest, digits);
        written = round_elements(tensor + along * lift, largest, digits);
    }
    written
}

/// The moments rounded to `digits`, the smallest raised (before rounding)
/// until the rounded moments are loadable.
fn rounded_moments(m: DVec3, digits: u32) -> DVec3 {
    let round = |m: DVec3| m.map(|x| significant(x, digits));
    let mut lift = 0.0;
    let mut written = round(m);
    for _ in 0..MAX_RAISES {
        let short = shortfall(written);
        if short <= 0.0 {
            break;
        }
        lift = next_lift(lift, short, m.z, digits);
        written = round(DVec3::new(m.x + lift, m.y, m.z));
    }
    written
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sheet(tilt: DQuat) -> DMat3 {
        // A square sheet in its own xy plane: A = B = 1, C = A + B.
        let r = DMat3::from_quat(tilt);
        r * DMat3::from_diagonal(DVec3::new(1.0 / 3.0, 1.0 / 3.0, 2.0 / 3.0)) * r.transpose()
    }

    #[test]
    fn full_form_keeps_a_loadable_tensor_unchanged() {
        let i = DMat3::from_diagonal(DVec3::new(1.0, 2.0, 2.5));
        let w = InertialForm::default().inertial(2.0, DVec3::X, i);
        assert_eq!(
            (w.mass, w.xyz, w.rpy, w.inertia),
            (2.0, DVec3::X, DVec3::ZERO, i)
        );
        assert_eq!(w.quat, DQuat::IDENTITY);
    }

    #[test]
    fn rounded_sheets_stay_loadable() {
        let mut raised = 0;
        for k in 0..40 {
            let tilt =
                DQuat::from_euler(glam::EulerRot::ZYX, 0.37 * k as f64, 0.21 * k as f64, 0.1);
            let i = sheet(tilt);
            for digits in [1, 2, 3, 6, 12, 17] {
                let p = PrincipalAxes::from_tensor(i);
                let plain = round_elements(i, p.moments.z, digits);
                raised += usize::from(!is_loadable(plain));
                for principal in [false, true] {
                    let w = InertialForm {
                        principal,
                        digits: Some(digits),
                    }
                    .inertial(1.0, DVec3::ZERO, i);
                    assert!(
                        is_loadable(w.inertia),
                        "{k} {digits} {principal}: {}",
                        w.inertia
                    );
                }
            }
        }
        // The raise was needed: plain rounding breaks some sheets.
        assert!(raised > 0);
    }
}
