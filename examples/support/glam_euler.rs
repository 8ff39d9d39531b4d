//! glam's name for each of kreisel's 24 Euler conventions, shared by the
//! comparison examples and benches (`#[path]`-included, not an example).

use glam::EulerRot;
use kreisel::kinematics::{EulerSequence, Frame};

/// The glam `EulerRot` that describes the same rotations as `seq`
/// (glam's `XYZ` is intrinsic, `XYZEx` extrinsic, as kreisel's `XYZ`/`xyz`).
pub fn glam_rot(seq: EulerSequence) -> EulerRot {
    use EulerRot::*;
    let table = [
        ("XYZ", XYZ, XYZEx),
        ("XZY", XZY, XZYEx),
        ("YXZ", YXZ, YXZEx),
        ("YZX", YZX, YZXEx),
        ("ZXY", ZXY, ZXYEx),
        ("ZYX", ZYX, ZYXEx),
        ("XYX", XYX, XYXEx),
        ("XZX", XZX, XZXEx),
        ("YXY", YXY, YXYEx),
        ("YZY", YZY, YZYEx),
        ("ZXZ", ZXZ, ZXZEx),
        ("ZYZ", ZYZ, ZYZEx),
    ];
    let name = seq.to_string().to_uppercase();
    let (_, intrinsic, extrinsic) = table
        .into_iter()
        .find(|(n, _, _)| *n == name)
        .unwrap_or(table[0]);
    match seq.frame() {
        Frame::Intrinsic => intrinsic,
        Frame::Extrinsic => extrinsic,
    }
}
