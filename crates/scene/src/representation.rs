//! The rotation representations by name (`quat`, `matrix`, `euler:ZXZ`,
//! …, the `--from`/`--to REPR` of `kreisel convert`): the enum, its names
//! and the count of numbers a line of each holds. Their numbers are in
//! [`crate::rotation_lines`].

use core::fmt;
use core::str::FromStr;

use kreisel_kinematics::EulerSequence;

use crate::escape::escape_invisible;

/// The names of the representations, as listed in error messages.
pub const VALID_NAMES: &str = "quat, quat-xyzw, matrix, rotvec, axis-angle, euler:SEQ \
     (SEQ one of XYZ XZY YXZ YZX ZXY ZYX XYX XZX YXY YZY ZXZ ZYZ, uppercase intrinsic, \
     or the same in lowercase, extrinsic)";

/// A way of writing a rotation as a line of numbers.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Representation {
    /// `w, x, y, z`: a quaternion, scalar first; any non-zero length on input.
    Quat,
    /// `x, y, z, w`: a quaternion, scalar last (scipy's and ROS's order).
    QuatXyzw,
    /// `m00, m01, m02, m10, …, m22`: the active rotation matrix
    /// (`v_world = M v_body`), row-major.
    Matrix,
    /// `x, y, z`: the rotation vector `axis · angle`, always in radians.
    RotVec,
    /// `x, y, z, angle`: an axis (any non-zero length) and an angle.
    AxisAngle,
    /// Three Euler angles in one of the 24 conventions.
    Euler(EulerSequence),
}

impl Representation {
    /// Every representation: the five fixed ones, then `euler:SEQ` for
    /// each of the 24 sequences ([`EulerSequence::all`]).
    ///
    /// ```
    /// use kreisel_scene::representation::Representation;
    /// assert_eq!(Representation::all().count(), 29);
    /// assert!(Representation::all().all(|r| r.to_string().parse() == Ok(r)));
    /// ```
    pub fn all() -> impl Iterator<Item = Representation> {
        [
            Representation::Quat,
            Representation::QuatXyzw,
            Representation::Matrix,
            Representation::RotVec,
            Representation::AxisAngle,
        ]
        .into_iter()
        .chain(EulerSequence::all().map(Representation::Euler))
    }

    /// How many numbers a line of this representation holds.
    pub const fn count(self) -> usize {
        match self {
            Representation::Quat | Representation::QuatXyzw | Representation::AxisAngle => 4,
            Representation::Matrix => 9,
            Representation::RotVec | Representation::Euler(_) => 3,
        }
    }
}

impl fmt::Display for Representation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Representation::Quat => f.write_str("quat"),
            Representation::QuatXyzw => f.write_str("quat-xyzw"),
            Representation::Matrix => f.write_str("matrix"),
            Representation::RotVec => f.write_str("rotvec"),
            Representation::AxisAngle => f.write_str("axis-angle"),
            Representation::Euler(sequence) => write!(f, "euler:{sequence}"),
        }
    }
}

impl FromStr for Representation {
    type Err = String;

    /// Parses `quat`, `quat-xyzw`, `matrix`, `rotvec`, `axis-angle` or
    /// `euler:SEQ`; the error message lists the valid names.
    fn from_str(text: &str) -> Result<Self, Self::Err> {
        match text {
            "quat" => Ok(Representation::Quat),
            "quat-xyzw" => Ok(Representation::QuatXyzw),
            "matrix" => Ok(Representation::Matrix),
            "rotvec" => Ok(Representation::RotVec),
            "axis-angle" => Ok(Representation::AxisAngle),
            _ => match text.strip_prefix("euler:") {
                Some(sequence) => sequence.parse().map(Representation::Euler).map_err(|e| {
                    format!(
                        "{}; valid representations: {VALID_NAMES}",
                        escape_invisible(&e.to_string())
                    )
                }),
                None => Err(format!(
                    "unknown representation; valid representations: {VALID_NAMES}"
                )),
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for r in Representation::all() {
            assert_eq!(r.to_string().parse::<Representation>(), Ok(r));
        }
        for bad in [
            "",
            "quaternion",
            "euler",
            "euler:",
            "euler:ZZX",
            "euler:ZxZ",
            "Quat",
        ] {
            let e = bad.parse::<Representation>().unwrap_err();
            assert!(e.contains("quat-xyzw") && e.contains("euler:SEQ"), "{e}");
        }
    }
}
