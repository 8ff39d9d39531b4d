//! A line of numbers in a representation as a rotation, and back: every
//! conversion goes through a unit quaternion. `numbers → DQuat` checks
//! that the numbers describe a rotation, `DQuat → numbers` writes it in
//! the representation's canonical form.

use glam::{DMat3, DQuat, DVec3};
use kreisel_kinematics::{
    AxisAngle, EulerSequence, KinematicsError, ORTHONORMALITY_TOLERANCE, canonical_quat,
    quat_from_rotation_vector, rotation_matrix_from_quat, rotation_vector_from_quat,
    try_normalize_quat, try_quat_from_rotation_matrix,
};

use crate::line_problem::LineProblem;
use crate::numbers::Numbers;
use crate::representation::Representation;

impl Representation {
    /// The rotation that a line of numbers describes.
    ///
    /// With `degrees`, Euler angles and the axis–angle angle are in degrees
    /// (a rotation vector is always in radians).
    ///
    /// # Errors
    /// [`LineProblem::WrongCount`] for the wrong count of numbers,
    /// [`LineProblem::NotARotation`] for a zero quaternion, a matrix that is
    /// not orthonormal within [`ORTHONORMALITY_TOLERANCE`] or is a
    /// reflection, and an axis–angle pair with a zero axis and a non-zero
    /// angle, [`LineProblem::RotationVectorLength`] for a rotation vector whose
    /// length overflows. The numbers should be finite (as
    /// [`crate::numbers::parse_numbers`] ensures); non-finite ones are
    /// rejected too.
    pub fn quat_from_numbers(self, numbers: &Numbers, degrees: bool) -> Result<DQuat, LineProblem> {
        let n = self.checked_slice(numbers)?;
        let angle = |a: f64| if degrees { a.to_radians() } else { a };
        let q = match self {
            Representation::Quat => try_normalize_quat(DQuat::from_xyzw(n[1], n[2], n[3], n[0]))?,
            Representation::QuatXyzw => {
                try_normalize_quat(DQuat::from_xyzw(n[0], n[1], n[2], n[3]))?
            }
            Representation::Matrix => {
                // Row-major text; glam stores columns: column c = (M_0c, M_1c, M_2c).
                let m = DMat3::from_cols(
                    DVec3::new(n[0], n[3], n[6]),
                    DVec3::new(n[1], n[4], n[7]),
                    DVec3::new(n[2], n[5], n[8]),
                );
                try_quat_from_rotation_matrix(m, ORTHONORMALITY_TOLERANCE)?
            }
            Representation::RotVec => {
                // Finite components can still have a length beyond f64::MAX.
                let q = quat_from_rotation_vector(DVec3::new(n[0], n[1], n[2]));
                if !q.is_finite() {
                    return Err(LineProblem::RotationVectorLength);
                }
                q
            }
            Representation::AxisAngle => {
                let axis = DVec3::new(n[0], n[1], n[2]);
                let rotation = AxisAngle::try_new(axis, angle(n[3])).map_err(|e| match e {
                    // Report the angle as the user wrote it (degrees or radians).
                    KinematicsError::ZeroAxis { .. } => KinematicsError::ZeroAxis { angle: n[3] },
                    other => other,
                })?;
                rotation.to_quat()
            }
            Representation::Euler(sequence) => {
                let angles = DVec3::new(angle(n[0]), angle(n[1]), angle(n[2]));
                if !angles.is_finite() {
                    return Err(KinematicsError::NonFinite {
                        what: "Euler angles",
                    }
                    .into());
                }
                sequence.to_quat(angles)
            }
        };
        Ok(q)
    }

    /// The numbers of a line, `n`, checked to be as many as this
    /// representation holds.
    fn checked_slice(self, numbers: &Numbers) -> Result<&[f64], LineProblem> {
        let n = numbers.as_slice();
        if numbers.count() != self.count() || n.len() != self.count() {
            return Err(LineProblem::WrongCount {
                representation: self,
                expected: self.count(),
                found: numbers.count(),
            });
        }
        Ok(n)
    }

    /// A line of numbers in this representation rewritten in `to`: what
    /// `kreisel convert` does with each line.
    ///
    /// ```text
    /// numbers → unit quaternion (quat_from_numbers) → numbers (numbers_from_quat)
    /// quat / quat-xyzw → euler:SEQ:  numbers → Euler angles (euler_angles_of_quat)
    /// ```
    ///
    /// A quaternion goes to Euler angles without being normalised: the
    /// formulas are scale-invariant, so this skips a square root, four
    /// divisions and their roundings.
    ///
    /// # Errors
    /// As [`Representation::quat_from_numbers`].
    pub fn convert_numbers(
        self,
        numbers: &Numbers,
        to: Representation,
        degrees: bool,
    ) -> Result<Numbers, LineProblem> {
        if let (Representation::Quat | Representation::QuatXyzw, Representation::Euler(sequence)) =
            (self, to)
        {
            let n = self.checked_slice(numbers)?;
            let q = match self {
                Representation::Quat => DQuat::from_xyzw(n[1], n[2], n[3], n[0]),
                _ => DQuat::from_xyzw(n[0], n[1], n[2], n[3]),
            };
            return Ok(Numbers::from_array(euler_angles_of_quat(
                sequence, q, degrees,
            )?));
        }
        let q = self.quat_from_numbers(numbers, degrees)?;
        Ok(to.numbers_from_quat(q, degrees))
    }

    /// The numbers of a unit quaternion in this representation.
    ///
    /// Quaternions are canonical (`w ≥ 0`, as [`canonical_quat`]); the
    /// axis–angle angle is in `[0, π]` (axis `1,0,0` for the identity); Euler
    /// angles are in the ranges of [`EulerSequence::from_quat`] (at exact
    /// gimbal lock the third angle is 0). With `degrees`, Euler angles and
    /// the axis–angle angle are written in degrees.
    pub fn numbers_from_quat(self, q: DQuat, degrees: bool) -> Numbers {
        let angle = |a: f64| if degrees { a.to_degrees() } else { a };
        match self {
            Representation::Quat => {
                let q = canonical_quat(q);
                Numbers::from_array([q.w, q.x, q.y, q.z])
            }
            Representation::QuatXyzw => {
                let q = canonical_quat(q);
                Numbers::from_array([q.x, q.y, q.z, q.w])
            }
            Representation::Matrix => {
                // The columns of Mᵀ are the rows of M.
                Numbers::from_array(rotation_matrix_from_quat(q).transpose().to_cols_array())
            }
            Representation::RotVec => Numbers::from_array(rotation_vector_from_quat(q).to_array()),
            Representation::AxisAngle => {
                let a = AxisAngle::from_quat(q);
                Numbers::from_array([a.axis.x, a.axis.y, a.axis.z, angle(a.angle)])
            }
            Representation::Euler(sequence) => {
                let a = sequence.from_quat(q).angles;
                Numbers::from_array([angle(a.x), angle(a.y), angle(a.z)])
            }
        }
    }
}

/// The Euler angles that `kreisel convert --from quat --to euler:SEQ` writes
/// for a quaternion of any non-zero length (radians, or degrees with
/// `degrees`): [`EulerSequence::try_from_quat`], no normalisation.
///
/// # Errors
/// [`KinematicsError::NonFinite`] or [`KinematicsError::ZeroQuaternion`]
/// for a quaternion that is not a rotation.
#[inline]
pub fn euler_angles_of_quat(
    sequence: EulerSequence,
    q: DQuat,
    degrees: bool,
) -> Result<[f64; 3], KinematicsError> {
    let [angles] = euler_angles_of_quats(sequence, [q], degrees).map_err(|(_, e)| e)?;
    Ok(angles)
}

/// [`euler_angles_of_quat`] of `N` quaternions at once
/// ([`EulerSequence::try_from_quats`]: the same numbers, bit for bit,
/// computed side by side in SIMD registers).
///
/// # Errors
/// The first quaternion that is not a rotation: its index and error, as
/// [`euler_angles_of_quat`].
#[inline]
pub fn euler_angles_of_quats<const N: usize>(
    sequence: EulerSequence,
    quats: [DQuat; N],
    degrees: bool,
) -> Result<[[f64; 3]; N], (usize, KinematicsError)> {
    let found = sequence.try_from_quats(quats)?;
    Ok(found.map(|found| {
        let a = found.angles;
        if degrees {
            [a.x.to_degrees(), a.y.to_degrees(), a.z.to_degrees()]
        } else {
            a.to_array()
        }
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use kreisel_kinematics::rotation_angle_between;

    #[test]
    fn every_pair_round_trips() {
        let q = DQuat::from_xyzw(0.3, -0.5, 0.1, 0.8).normalize();
        for from in Representation::all() {
            for degrees in [false, true] {
                let numbers = from.numbers_from_quat(q, degrees);
                assert_eq!(numbers.count(), from.count());
                let back = from.quat_from_numbers(&numbers, degrees).unwrap();
                assert!(rotation_angle_between(q, back) < 1e-15, "{from} {degrees}");
            }
        }
    }

    #[test]
    fn matrix_is_row_major_and_active() {
        // 90° about z: x → y, so the first column is (0, 1, 0).
        let q = DQuat::from_rotation_z(core::f64::consts::FRAC_PI_2);
        let m = Representation::Matrix.numbers_from_quat(q, false);
        let expect = [0.0, -1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0];
        for (a, b) in m.as_slice().iter().zip(expect) {
            assert!((a - b).abs() < 1e-15, "{m:?}");
        }
        let back = Representation::Matrix
            .quat_from_numbers(&Numbers::from_array(expect), false)
            .unwrap();
        assert!(rotation_angle_between(q, back) < 1e-16);
    }

    #[test]
    fn wrong_count_and_zero_axis_in_degrees() {
        let e = Representation::Quat
            .quat_from_numbers(&Numbers::from_array([1.0, 0.0, 0.0]), false)
            .unwrap_err();
        assert_eq!(e.to_string(), "expected 4 numbers for quat, found 3");
        let huge = Numbers::from_array([1.5e308, 1.5e308, 0.0]);
        let e = Representation::RotVec
            .quat_from_numbers(&huge, false)
            .unwrap_err();
        assert!(matches!(e, LineProblem::RotationVectorLength), "{e}");
        let e = Representation::AxisAngle
            .quat_from_numbers(&Numbers::from_array([0.0, 0.0, 0.0, 90.0]), true)
            .unwrap_err();
        assert_eq!(e.to_string(), "rotation axis is zero but the angle is 90");
    }
}
