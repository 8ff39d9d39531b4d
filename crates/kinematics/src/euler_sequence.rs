//! The 24 Euler conventions: three axes and a frame (intrinsic or extrinsic).

use core::fmt;
use core::str::FromStr;

use glam::DVec3;

use crate::KinematicsError;

/// A coordinate axis of the body or world frame.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Axis {
    /// The x axis, index 0.
    X = 0,
    /// The y axis, index 1.
    Y = 1,
    /// The z axis, index 2.
    Z = 2,
}

impl Axis {
    /// All three axes in order x, y, z.
    pub const ALL: [Axis; 3] = [Axis::X, Axis::Y, Axis::Z];

    /// The index of the axis: 0 for x, 1 for y, 2 for z.
    ///
    /// ```
    /// use kreisel_kinematics::Axis;
    /// assert_eq!(Axis::Z.index(), 2);
    /// ```
    #[inline]
    pub const fn index(self) -> usize {
        self as usize
    }

    /// The unit vector along the axis.
    ///
    /// ```
    /// use glam::DVec3;
    /// use kreisel_kinematics::Axis;
    /// assert_eq!(Axis::Y.unit(), DVec3::Y);
    /// ```
    #[inline]
    pub const fn unit(self) -> DVec3 {
        match self {
            Axis::X => DVec3::X,
            Axis::Y => DVec3::Y,
            Axis::Z => DVec3::Z,
        }
    }

    /// Levi-Civita sign `ε_{self, next, third}`: `+1.0` when `next` follows
    /// `self` cyclically (x→y→z→x), `−1.0` otherwise.
    #[inline]
    pub(crate) const fn parity(self, next: Axis) -> f64 {
        match (self, next) {
            (Axis::X, Axis::Y) | (Axis::Y, Axis::Z) | (Axis::Z, Axis::X) => 1.0,
            _ => -1.0,
        }
    }

    const fn from_letter(c: u8) -> Option<(Axis, bool)> {
        match c {
            b'X' => Some((Axis::X, true)),
            b'Y' => Some((Axis::Y, true)),
            b'Z' => Some((Axis::Z, true)),
            b'x' => Some((Axis::X, false)),
            b'y' => Some((Axis::Y, false)),
            b'z' => Some((Axis::Z, false)),
            _ => None,
        }
    }

    const fn letter(self, upper: bool) -> char {
        match (self, upper) {
            (Axis::X, true) => 'X',
            (Axis::Y, true) => 'Y',
            (Axis::Z, true) => 'Z',
            (Axis::X, false) => 'x',
            (Axis::Y, false) => 'y',
            (Axis::Z, false) => 'z',
        }
    }
}

/// The components of `v` along `a`, `b` and the remaining axis `t`, and the
/// Levi-Civita sign `ε_{abt}`. `a` and `b` must differ (for `a = b`, `v` is
/// returned unchanged with `ε = 1`).
///
/// A `match` rather than indexing, so the hot Euler conversions carry no
/// bounds checks.
#[inline]
pub(crate) fn gather(a: Axis, b: Axis, v: DVec3) -> (DVec3, f64) {
    use Axis::{X, Y, Z};
    match (a, b) {
        (X, Y) => (v, 1.0),
        (Y, Z) => (DVec3::new(v.y, v.z, v.x), 1.0),
        (Z, X) => (DVec3::new(v.z, v.x, v.y), 1.0),
        (X, Z) => (DVec3::new(v.x, v.z, v.y), -1.0),
        (Z, Y) => (DVec3::new(v.z, v.y, v.x), -1.0),
        (Y, X) => (DVec3::new(v.y, v.x, v.z), -1.0),
        _ => (v, 1.0),
    }
}

/// The inverse of [`gather`]: the vector whose components along `a`, `b`
/// and the remaining axis are `u.x`, `u.y`, `u.z`.
#[inline]
pub(crate) fn scatter(a: Axis, b: Axis, u: DVec3) -> DVec3 {
    use Axis::{X, Y, Z};
    match (a, b) {
        (Y, Z) => DVec3::new(u.z, u.x, u.y),
        (Z, X) => DVec3::new(u.y, u.z, u.x),
        (X, Z) => DVec3::new(u.x, u.z, u.y),
        (Z, Y) => DVec3::new(u.z, u.y, u.x),
        (Y, X) => DVec3::new(u.y, u.x, u.z),
        _ => u,
    }
}

/// Whether the elemental rotations turn about the moving or the fixed axes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Frame {
    /// Rotations about the axes of the rotating body (scipy's uppercase, e.g. `ZXZ`).
    ///
    /// ```text
    /// world_from_body = R_a(α) · R_b(β) · R_c(γ)
    /// ```
    Intrinsic,
    /// Rotations about the fixed world axes (scipy's lowercase, e.g. `zxz`).
    ///
    /// ```text
    /// world_from_body = R_c(γ) · R_b(β) · R_a(α)
    /// ```
    Extrinsic,
}

/// One of the 24 Euler conventions: an axis sequence and a [`Frame`].
///
/// Named as scipy names them: uppercase letters are intrinsic (`"ZXZ"`, the
/// lecture notes' (φ, θ, ψ)), lowercase extrinsic (`"xyz"`). Sequences whose
/// first and third axes coincide are *proper* Euler angles (middle angle in
/// `[0, π]`, gimbal lock at 0 and π); the others are *Tait–Bryan* angles
/// (middle angle in `[−π/2, π/2]`, gimbal lock at ±π/2).
///
/// The extrinsic sequence `abc` with angles `(α, β, γ)` is the same rotation as
/// the intrinsic sequence `CBA` with angles `(γ, β, α)`.
///
/// ```
/// use kreisel_kinematics::{Axis, EulerSequence, Frame};
/// let zxz: EulerSequence = "ZXZ".parse()?;
/// assert_eq!(zxz, EulerSequence::new([Axis::Z, Axis::X, Axis::Z], Frame::Intrinsic));
/// assert!(zxz.is_proper());
/// assert_eq!(zxz.to_string(), "ZXZ");
/// assert!("ZZX".parse::<EulerSequence>().is_err());
/// # Ok::<(), kreisel_kinematics::KinematicsError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct EulerSequence {
    axes: [Axis; 3],
    frame: Frame,
}

impl EulerSequence {
    /// The 12 axis sequences, Tait–Bryan first, then proper Euler.
    const AXES: [[Axis; 3]; 12] = {
        use Axis::{X, Y, Z};
        [
            [X, Y, Z],
            [X, Z, Y],
            [Y, X, Z],
            [Y, Z, X],
            [Z, X, Y],
            [Z, Y, X],
            [X, Y, X],
            [X, Z, X],
            [Y, X, Y],
            [Y, Z, Y],
            [Z, X, Z],
            [Z, Y, Z],
        ]
    };

    /// All 24 conventions: the 12 intrinsic ones, then the 12 extrinsic ones.
    ///
    /// ```
    /// use kreisel_kinematics::EulerSequence;
    /// assert_eq!(EulerSequence::all().len(), 24);
    /// ```
    pub const fn all() -> [EulerSequence; 24] {
        let mut out = [EulerSequence {
            axes: [Axis::X, Axis::Y, Axis::Z],
            frame: Frame::Intrinsic,
        }; 24];
        let mut n = 0;
        while n < 12 {
            out[n].axes = Self::AXES[n];
            out[n + 12] = EulerSequence {
                axes: Self::AXES[n],
                frame: Frame::Extrinsic,
            };
            n += 1;
        }
        out
    }

    /// Builds a sequence, checking that consecutive axes differ.
    ///
    /// # Errors
    /// [`KinematicsError::InvalidSequence`] when two consecutive axes are equal
    /// (e.g. `X, X, Y`), which is no valid Euler convention.
    ///
    /// ```
    /// use kreisel_kinematics::{Axis, EulerSequence, Frame};
    /// assert!(EulerSequence::try_new([Axis::X, Axis::X, Axis::Y], Frame::Intrinsic).is_err());
    /// ```
    pub fn try_new(axes: [Axis; 3], frame: Frame) -> Result<Self, KinematicsError> {
        if axes[0] == axes[1] || axes[1] == axes[2] {
            let upper = frame == Frame::Intrinsic;
            return Err(KinematicsError::InvalidSequence {
                text: axes.iter().map(|a| a.letter(upper)).collect(),
                reason: "consecutive axes must differ",
            });
        }
        Ok(Self { axes, frame })
    }

    /// Builds a sequence.
    ///
    /// # Panics
    /// When two consecutive axes are equal; use [`EulerSequence::try_new`] for
    /// input that is not known to be valid.
    ///
    /// ```
    /// use kreisel_kinematics::{Axis, EulerSequence, Frame};
    /// let s = EulerSequence::new([Axis::X, Axis::Y, Axis::Z], Frame::Extrinsic);
    /// assert_eq!(s.to_string(), "xyz");
    /// ```
    pub fn new(axes: [Axis; 3], frame: Frame) -> Self {
        match Self::try_new(axes, frame) {
            Ok(s) => s,
            Err(e) => panic!("{e}"),
        }
    }

    /// The three axes, in the order the angles are given.
    #[inline]
    pub const fn axes(self) -> [Axis; 3] {
        self.axes
    }

    /// Intrinsic or extrinsic.
    #[inline]
    pub const fn frame(self) -> Frame {
        self.frame
    }

    /// `true` for proper Euler angles (first axis = third axis, e.g. `ZXZ`),
    /// `false` for Tait–Bryan angles (three different axes, e.g. `XYZ`).
    ///
    /// ```
    /// use kreisel_kinematics::EulerSequence;
    /// assert!(!"xyz".parse::<EulerSequence>()?.is_proper());
    /// # Ok::<(), kreisel_kinematics::KinematicsError>(())
    /// ```
    #[inline]
    pub const fn is_proper(self) -> bool {
        self.axes[0] as usize == self.axes[2] as usize
    }

    /// The middle angle at which the sequence is in gimbal lock and the other
    /// two angles are not separately defined.
    ///
    /// ```text
    /// proper:      θ ∈ {0, π}
    /// Tait–Bryan:  θ ∈ {−π/2, π/2}
    /// ```
    ///
    /// ```
    /// use kreisel_kinematics::EulerSequence;
    /// let s: EulerSequence = "ZYX".parse()?;
    /// assert_eq!(s.gimbal_lock_angles(), [-core::f64::consts::FRAC_PI_2, core::f64::consts::FRAC_PI_2]);
    /// # Ok::<(), kreisel_kinematics::KinematicsError>(())
    /// ```
    pub const fn gimbal_lock_angles(self) -> [f64; 2] {
        if self.is_proper() {
            [0.0, core::f64::consts::PI]
        } else {
            [-core::f64::consts::FRAC_PI_2, core::f64::consts::FRAC_PI_2]
        }
    }

    /// The same rotations written as an intrinsic sequence: the extrinsic
    /// `abc` becomes `CBA` (with the angle order reversed by the caller).
    #[inline]
    pub(crate) const fn intrinsic_axes(self) -> [Axis; 3] {
        match self.frame {
            Frame::Intrinsic => self.axes,
            Frame::Extrinsic => [self.axes[2], self.axes[1], self.axes[0]],
        }
    }
}

impl fmt::Display for EulerSequence {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let upper = self.frame == Frame::Intrinsic;
        for a in self.axes {
            write!(f, "{}", a.letter(upper))?;
        }
        Ok(())
    }
}

impl FromStr for EulerSequence {
    type Err = KinematicsError;

    /// Parses scipy's names: three letters from `XYZ` (intrinsic) or from
    /// `xyz` (extrinsic), consecutive letters different.
    fn from_str(text: &str) -> Result<Self, Self::Err> {
        let invalid = |reason| KinematicsError::InvalidSequence {
            text: text.to_owned(),
            reason,
        };
        let bytes = text.as_bytes();
        if bytes.len() != 3 {
            return Err(invalid("expected three axis letters such as ZXZ or xyz"));
        }
        let mut axes = [Axis::X; 3];
        let mut cases = [true; 3];
        for (n, &c) in bytes.iter().enumerate() {
            let (axis, upper) =
                Axis::from_letter(c).ok_or_else(|| invalid("axis letters must be x, y or z"))?;
            axes[n] = axis;
            cases[n] = upper;
        }
        if cases[0] != cases[1] || cases[1] != cases[2] {
            return Err(invalid(
                "mixed case: use all uppercase (intrinsic) or all lowercase (extrinsic)",
            ));
        }
        let frame = if cases[0] {
            Frame::Intrinsic
        } else {
            Frame::Extrinsic
        };
        Self::try_new(axes, frame).map_err(|_| invalid("consecutive axes must differ"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parse_and_display_round_trip_all_24() {
        let all = EulerSequence::all();
        for s in all {
            let text = s.to_string();
            assert_eq!(text.parse::<EulerSequence>(), Ok(s));
        }
        let mut names: Vec<String> = all.iter().map(|s| s.to_string()).collect();
        names.sort();
        names.dedup();
        assert_eq!(names.len(), 24);
    }

    #[test]
    fn rejects_bad_names() {
        for bad in ["", "ZX", "ZXZZ", "ZxZ", "ZZX", "XYY", "abc", "ZXZ "] {
            assert!(bad.parse::<EulerSequence>().is_err(), "{bad:?}");
        }
    }

    #[test]
    fn parity_is_levi_civita() {
        assert_eq!(Axis::X.parity(Axis::Y), 1.0);
        assert_eq!(Axis::Y.parity(Axis::Z), 1.0);
        assert_eq!(Axis::Z.parity(Axis::X), 1.0);
        assert_eq!(Axis::Y.parity(Axis::X), -1.0);
        assert_eq!(Axis::X.parity(Axis::Z), -1.0);
        for a in Axis::ALL {
            for b in Axis::ALL {
                if a == b {
                    continue;
                }
                let v = DVec3::new(1.0, 2.0, 3.0);
                let (u, eps) = gather(a, b, v);
                assert_eq!(eps, a.parity(b));
                assert_eq!((u.x, u.y), (v[a.index()], v[b.index()]));
                assert_eq!(scatter(a, b, u), v);
                // (a, b, third) is right-handed times ε.
                let third = a.unit().cross(b.unit()) * eps;
                assert_eq!(u.z, v.dot(third));
            }
        }
    }
}
