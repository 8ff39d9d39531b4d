//! A fixed workload of Euler conversions for instruction counting, so that
//! kreisel and glam can be compared on a noisy machine:
//!
//! ```text
//! cargo build --release --example euler_throughput
//! valgrind --tool=callgrind --callgrind-out-file=/dev/null \
//!     target/release/examples/euler_throughput kreisel to-euler XYZ 100000
//! ```
//!
//! Arguments: `kreisel|glam|none` (`none`: only the input generation), `to-euler|to-quat`, a convention (`XYZ`,
//! `zxz`, … as in scipy), and the number of conversions. Prints a checksum
//! so that the work cannot be optimised away.

use std::hint::black_box;
use std::process::ExitCode;

use glam::{DQuat, DVec3, EulerRot};
use kreisel::kinematics::{EulerSequence, Frame};

fn glam_rot(seq: EulerSequence) -> Option<EulerRot> {
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
    let (_, intrinsic, extrinsic) = table.into_iter().find(|(n, _, _)| *n == name)?;
    Some(match seq.frame() {
        Frame::Intrinsic => intrinsic,
        Frame::Extrinsic => extrinsic,
    })
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [library, direction, seq, n] = args.as_slice() else {
        eprintln!("usage: euler_throughput kreisel|glam|none to-euler|to-quat SEQ N");
        return ExitCode::FAILURE;
    };
    let (Ok(seq), Ok(n)) = (seq.parse::<EulerSequence>(), n.parse::<u64>()) else {
        eprintln!("bad convention or count");
        return ExitCode::FAILURE;
    };
    let Some(rot) = glam_rot(seq) else {
        return ExitCode::FAILURE;
    };
    let mut sum = 0.0;
    for i in 0..n {
        let t = i as f64 * 1e-4;
        let angles = DVec3::new(t.sin() * 3.0, t.cos() * 0.7, (2.0 * t).sin() * 3.0);
        match (library.as_str(), direction.as_str()) {
            ("kreisel", "to-euler") => {
                let q = black_box(DQuat::from_xyzw(angles.x, angles.y, angles.z, 1.0));
                sum += seq.from_quat(q.normalize()).angles.x;
            }
            ("glam", "to-euler") => {
                let q = black_box(DQuat::from_xyzw(angles.x, angles.y, angles.z, 1.0));
                sum += q.normalize().to_euler(rot).0;
            }
            ("kreisel", "to-quat") => sum += seq.to_quat(black_box(angles)).w,
            ("glam", "to-quat") => {
                let a = black_box(angles);
                sum += DQuat::from_euler(rot, a.x, a.y, a.z).w;
            }
            // The cost of making the inputs, to subtract from the others.
            ("none", _) => sum += black_box(angles).x,
            _ => {
                eprintln!("unknown library or direction");
                return ExitCode::FAILURE;
            }
        }
    }
    println!("checksum {sum}");
    ExitCode::SUCCESS
}
