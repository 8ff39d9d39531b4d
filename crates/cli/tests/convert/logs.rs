//! `--skip-columns N` and `--header` on an IMU-like log: the leading fields
//! pass through byte for byte, the rotation against the closed form of the
//! aerospace angles, the header, and one-line errors naming the line.

use std::fmt::Write as _;

use crate::support::{Run, convert, scratch};

/// A failed run's one line on standard error (exit status 1; the lines
/// before the bad one stay on standard output).
fn error_line(run: &Run) -> &str {
    assert_eq!(run.code, Some(1), "stdout: {}", run.stdout);
    let lines: Vec<&str> = run.stderr.lines().collect();
    assert_eq!(lines.len(), 1, "{}", run.stderr);
    lines[0]
}

/// The world_from_body quaternion (w, x, y, z) of yaw ψ, pitch θ, roll φ
/// (intrinsic ZYX: about z, then the new y, then the new x), closed form.
fn ypr_quat(yaw: f64, pitch: f64, roll: f64) -> [f64; 4] {
    let (sy, cy) = (0.5 * yaw).sin_cos();
    let (sp, cp) = (0.5 * pitch).sin_cos();
    let (sr, cr) = (0.5 * roll).sin_cos();
    [
        cy * cp * cr + sy * sp * sr,
        cy * cp * sr - sy * sp * cr,
        cy * sp * cr + sy * cp * sr,
        sy * cp * cr - cy * sp * sr,
    ]
}

/// A log as an IMU driver writes it: a comment, a header, then
/// `timestamp,sensor,qw,qx,qy,qz` with nanosecond-like timestamps that no
/// float round trip would keep, and the angles (degrees) each row holds.
fn imu_log() -> (String, Vec<(String, [f64; 3])>) {
    let mut text = String::from("# imu0 attitude, 100 Hz\ntimestamp,sensor,qw,qx,qy,qz\n");
    let mut rows = Vec::new();
    for k in 0..40 {
        let t = format!("1700000000.{:09}", k * 10_000_017);
        let sensor = if k % 3 == 0 { "imu-0" } else { "imu-1" };
        let yaw = -170.0 + 8.5 * f64::from(k);
        let pitch = -80.0 + 4.0 * f64::from(k);
        let roll = 175.0 - 9.0 * f64::from(k);
        let q = ypr_quat(yaw.to_radians(), pitch.to_radians(), roll.to_radians());
        // Mixed separators, as hand-edited logs have.
        let sep = if k % 2 == 0 { "," } else { ", " };
        writeln!(
            text,
            "{t}{sep}{sensor}{sep}{:?}{sep}{:?}{sep}{:?}{sep}{:?}",
            q[0], q[1], q[2], q[3]
        )
        .unwrap();
        rows.push((format!("{t},{sensor}"), [yaw, pitch, roll]));
    }
    (text, rows)
}

#[test]
fn an_imu_log_keeps_its_timestamps_and_ids_and_gets_a_header() {
    let (log, rows) = imu_log();
    let run = convert(
        "quat",
        "euler:ZYX",
        &["--degrees", "--skip-columns", "2", "--header"],
        log,
    );
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    let mut lines = run.stdout.lines();
    assert_eq!(
        lines.next(),
        Some("timestamp,sensor,yaw_deg,pitch_deg,roll_deg")
    );
    let mut worst: f64 = 0.0;
    for ((passed, angles), line) in rows.iter().zip(lines.by_ref()) {
        let fields: Vec<&str> = line.split(',').collect();
        assert_eq!(fields.len(), 5, "{line}");
        assert_eq!(fields[..2].join(","), *passed);
        for (got, want) in fields[2..].iter().zip(angles) {
            let got: f64 = got.parse().unwrap();
            worst = worst.max((got - want).abs());
        }
    }
    assert!(lines.next().is_none());
    eprintln!("IMU log: largest yaw/pitch/roll error {worst:.1e} deg");
    assert!(worst < 1e-11, "{worst:e}");
}

#[test]
fn whitespace_logs_and_no_header() {
    // Space-separated, no header: the fields come out comma-separated.
    let run = convert(
        "quat",
        "quat-xyzw",
        &["--skip-columns", "1"],
        "0.010 2 0 0 0\n\n# gap\n0.020\t0 0 0 1\n",
    );
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    assert_eq!(run.stdout, "0.010,0,0,0,1\n0.020,0,0,1,0\n");
    // A header without passed-through columns: just the names of --to.
    let run = convert(
        "rotvec",
        "axis-angle",
        &["--header", "--degrees"],
        "rx ry rz\n0 0 3.141592653589793\n",
    );
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    assert_eq!(run.stdout, "ax,ay,az,angle_deg\n0,0,1,180\n");
    // An empty id between commas passes through empty.
    let run = convert("quat", "rotvec", &["--skip-columns", "2"], "0.5,,1,0,0,0\n");
    assert_eq!(run.stdout, "0.5,,0,0,0\n", "{}", run.stderr);
}

#[test]
fn short_lines_and_bad_headers_name_the_line() {
    let log = "# log\nt,id,qw,qx,qy,qz\n0.1,a,1,0,0,0\n0.2,b,1,0,0,0\n0.3\n0.4,d,1,0,0,0\n";
    let run = convert("quat", "quat", &["--skip-columns", "2", "--header"], log);
    assert_eq!(
        error_line(&run),
        "kreisel: error: line 5: line has 1 columns, fewer than --skip-columns 2"
    );
    assert_eq!(
        run.stdout,
        "t,id,qw,qx,qy,qz\n0.1,a,1,0,0,0\n0.2,b,1,0,0,0\n"
    );
    // Only the passed-through fields: no rotation.
    let run = convert("quat", "quat", &["--skip-columns", "2"], "0.1,a\n");
    assert_eq!(
        error_line(&run),
        "kreisel: error: line 1: expected 4 numbers for quat, found 0"
    );
    // A header that names too few columns (forgot --skip-columns?).
    let run = convert("quat", "quat", &["--header"], "t,qw,qx,qy,qz\n0,1,0,0,0\n");
    assert_eq!(
        error_line(&run),
        "kreisel: error: line 1: header has 5 columns, expected 0 passed through (--skip-columns) + 4 for quat"
    );
    // A huge N is just more than the line has (no allocation for it).
    let run = convert(
        "quat",
        "quat",
        &["--skip-columns", "1000000000000"],
        "0.1,1,0,0,0\n",
    );
    assert_eq!(
        error_line(&run),
        "kreisel: error: line 1: line has 5 columns, fewer than --skip-columns 1000000000000"
    );
    let run = convert(
        "quat",
        "quat",
        &["--skip-columns", "1000000000000", "--header"],
        "t,qw,qx,qy,qz\n",
    );
    assert!(error_line(&run).contains("header has 5 columns"));
    let run = convert(
        "quat",
        "quat",
        &["--skip-columns", "18446744073709551615", "--header"],
        "t,qw,qx,qy,qz\n",
    );
    assert!(error_line(&run).contains("header has 5 columns"));
    // Without --header a header line is a bad number, on its line.
    let run = convert("quat", "quat", &["--skip-columns", "1"], "t,qw,qx,qy,qz\n");
    assert_eq!(
        error_line(&run),
        "kreisel: error: line 1: cannot parse `qw` as a number"
    );
}

#[test]
fn an_output_file_is_not_written_after_an_error() {
    let out = scratch("log_out.csv");
    let run = convert(
        "quat",
        "rotvec",
        &["--skip-columns", "1", "--output", out.to_str().unwrap()],
        "0.1,1,0,0,0\n0.2\n",
    );
    assert!(error_line(&run).contains("line 2: "));
    assert!(!out.exists());
    let run = convert(
        "quat",
        "rotvec",
        &[
            "--skip-columns",
            "1",
            "--header",
            "--output",
            out.to_str().unwrap(),
        ],
        "t qw qx qy qz\n0.1,1,0,0,0\n",
    );
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    assert_eq!(
        std::fs::read_to_string(&out).unwrap(),
        "t,rx,ry,rz\n0.1,0,0,0\n"
    );
}
