//! The columns of a log line for `kreisel convert --skip-columns N
//! --header`: the leading fields passed through unchanged, and the header
//! line written for the output.
//!
//! ```text
//! line    = field{N} rotation           fields and numbers separated by commas and/or whitespace
//! output  = field,…,field,n1,…,nk       the N fields as written (trimmed), then the rotation
//! header  = name{N} name{count of --from}   → name,…,name,<names of --to>
//! ```
//!
//! Output names ([`names`]): `quat` qw,qx,qy,qz; `quat-xyzw` qx,qy,qz,qw;
//! `matrix` m00…m22 (row-major); `rotvec` rx,ry,rz; `axis-angle`
//! ax,ay,az,angle; `euler:ZYX` yaw,pitch,roll and `euler:xyz`
//! roll,pitch,yaw (the aerospace angles); any other `euler:SEQ` the axis
//! letter and position, `Z1,X2,Z3`. With `--degrees` the angles end in
//! `_deg` (`yaw_deg`, `angle_deg`; rotvec stays in radians).

use kreisel_scene::line_problem::LineProblem;
use kreisel_scene::representation::Representation;

/// How the lines of a log are laid out.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Layout {
    /// Leading fields passed through unchanged (timestamps, ids).
    pub skip_columns: usize,
    /// The first line that is neither blank nor a comment is a header.
    pub header: bool,
}

/// Whether `c` separates fields (commas and whitespace, as the numbers).
fn is_space(c: char) -> bool {
    c.is_whitespace()
}

/// The first `n` fields of a (trimmed, non-blank) line and the rest.
///
/// A field ends at a comma or whitespace; a comma right after a field's
/// separator makes an empty field (`0.5,,1,0,0,0` passes `0.5` and an
/// empty id through).
///
/// # Errors
/// [`LineProblem::TooFewColumns`] when the line has fewer than `n` fields.
pub fn split_leading(text: &str, n: usize) -> Result<(Vec<&str>, &str), LineProblem> {
    // n is untrusted (`--skip-columns 1000000000`): grow as fields are found.
    let mut fields = Vec::with_capacity(n.min(16));
    let mut rest = text;
    for found in 0..n {
        rest = rest.trim_start_matches(is_space);
        if rest.is_empty() {
            return Err(LineProblem::TooFewColumns { skip: n, found });
        }
        let end = rest
            .find(|c: char| c == ',' || is_space(c))
            .unwrap_or(rest.len());
        fields.push(&rest[..end]);
        rest = rest[end..].trim_start_matches(is_space);
        rest = rest.strip_prefix(',').unwrap_or(rest);
    }
    Ok((fields, rest.trim_start_matches(is_space)))
}

/// The column names of `representation` in the output (see the module docs).
pub fn names(representation: Representation, degrees: bool) -> Vec<String> {
    let angle = |name: &str| {
        if degrees {
            format!("{name}_deg")
        } else {
            name.to_owned()
        }
    };
    let plain = |list: &[&str]| list.iter().map(|s| (*s).to_owned()).collect();
    match representation {
        Representation::Quat => plain(&["qw", "qx", "qy", "qz"]),
        Representation::QuatXyzw => plain(&["qx", "qy", "qz", "qw"]),
        Representation::Matrix => (0..9).map(|k| format!("m{}{}", k / 3, k % 3)).collect(),
        Representation::RotVec => plain(&["rx", "ry", "rz"]),
        Representation::AxisAngle => vec!["ax".into(), "ay".into(), "az".into(), angle("angle")],
        Representation::Euler(sequence) => {
            let text = sequence.to_string();
            match text.as_str() {
                "ZYX" => vec![angle("yaw"), angle("pitch"), angle("roll")],
                "xyz" => vec![angle("roll"), angle("pitch"), angle("yaw")],
                _ => text
                    .chars()
                    .enumerate()
                    .map(|(k, axis)| angle(&format!("{axis}{}", k + 1)))
                    .collect(),
            }
        }
    }
}

/// The output header for the header line `text` (trimmed, non-blank):
/// its first `skip_columns` names, then the names of `to`.
///
/// The names are separated by commas when the line has any (so a name may
/// hold spaces, `time (s)`), else by whitespace.
///
/// # Errors
/// [`LineProblem::HeaderCount`] when the header does not name
/// `skip_columns` + the count of `from` columns.
pub fn header(
    text: &str,
    skip_columns: usize,
    from: Representation,
    to: Representation,
    degrees: bool,
) -> Result<String, LineProblem> {
    let fields: Vec<&str> = if text.contains(',') {
        text.split(',').map(str::trim).collect()
    } else {
        text.split_whitespace().collect()
    };
    if fields.len() != skip_columns.saturating_add(from.count()) {
        return Err(LineProblem::HeaderCount {
            found: fields.len(),
            skip: skip_columns,
            representation: from,
            expected: from.count(),
        });
    }
    let mut out: Vec<String> = fields[..skip_columns]
        .iter()
        .map(|s| (*s).to_owned())
        .collect();
    out.extend(names(to, degrees));
    Ok(out.join(","))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn leading_fields_split_at_commas_and_spaces() {
        let (fields, rest) = split_leading("12.5, imu0 1,0,0,0", 2).unwrap();
        assert_eq!((fields, rest), (vec!["12.5", "imu0"], "1,0,0,0"));
        let (fields, rest) = split_leading("0.5,,1,0,0,0", 2).unwrap();
        assert_eq!((fields, rest), (vec!["0.5", ""], "1,0,0,0"));
        let (fields, rest) = split_leading("1 0 0 0", 0).unwrap();
        assert_eq!((fields.len(), rest), (0, "1 0 0 0"));
        assert!(matches!(
            split_leading("12.5, imu0", 3),
            Err(LineProblem::TooFewColumns { skip: 3, found: 2 })
        ));
    }

    proptest::proptest! {
        /// Fields joined by any separator split back into the same fields
        /// and the same rest.
        #[test]
        fn leading_fields_split_back(
            fields in proptest::collection::vec("[A-Za-z0-9._:+-]{1,12}", 0..6),
            separator in proptest::sample::select(vec![",", ", ", " ", "\t", " , "]),
        ) {
            let rest = "0.5,0.5,0.5,0.5";
            let mut line = fields.join(separator);
            if !fields.is_empty() {
                line.push_str(separator);
            }
            line.push_str(rest);
            let (split, after) = split_leading(&line, fields.len()).unwrap();
            proptest::prop_assert_eq!(split, fields.iter().map(String::as_str).collect::<Vec<_>>());
            proptest::prop_assert_eq!(after, rest);
        }
    }

    #[test]
    fn names_of_every_representation() {
        let n = |r: &str, d| names(r.parse().unwrap(), d).join(",");
        assert_eq!(n("quat", true), "qw,qx,qy,qz");
        assert_eq!(n("quat-xyzw", false), "qx,qy,qz,qw");
        assert_eq!(n("matrix", false), "m00,m01,m02,m10,m11,m12,m20,m21,m22");
        assert_eq!(n("rotvec", true), "rx,ry,rz");
        assert_eq!(n("axis-angle", true), "ax,ay,az,angle_deg");
        assert_eq!(n("euler:ZYX", false), "yaw,pitch,roll");
        assert_eq!(n("euler:xyz", true), "roll_deg,pitch_deg,yaw_deg");
        assert_eq!(n("euler:ZXZ", false), "Z1,X2,Z3");
        assert_eq!(n("euler:zyx", false), "z1,y2,x3");
    }

    #[test]
    fn header_keeps_the_passed_names_and_checks_the_count() {
        let q = Representation::Quat;
        let e: Representation = "euler:ZYX".parse().unwrap();
        assert_eq!(
            header("time (s), id, qw, qx, qy, qz", 2, q, e, true).unwrap(),
            "time (s),id,yaw_deg,pitch_deg,roll_deg"
        );
        assert_eq!(
            header("t qw qx qy qz", 1, q, q, false).unwrap(),
            "t,qw,qx,qy,qz"
        );
        let err = header("t,qw,qx,qy,qz", 2, q, q, false).unwrap_err();
        assert_eq!(
            err.to_string(),
            "header has 5 columns, expected 2 passed through (--skip-columns) + 4 for quat"
        );
    }
}
