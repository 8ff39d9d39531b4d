//! `--transform` and `--about`: the results in the frame of a link the mesh
//! is placed in, and the tensor about a chosen point.
//!
//! The physics is kreisel-inertia's ([`MassProperties::placed`],
//! [`MassProperties::inertia_about_point`]); this file parses the options
//! and applies them to every body of a [`Report`].

use core::fmt;
use core::str::FromStr;

use glam::{DMat3, DQuat, DVec3};

use super::inertial_form::rpy_sequence;
use super::{Report, Summary};
use kreisel_scene::numbers::{Shortest, parse_numbers};

/// Where the mesh sits in a link frame, as a URDF `<origin xyz rpy>`.
///
/// ```text
/// p_link = R · p_mesh + xyz,   R = Rz(yaw) · Ry(pitch) · Rx(roll)
/// ```
///
/// ```
/// use glam::DVec3;
/// use kreisel_cli::inertia::Transform;
/// let t: Transform = "xyz=0 0 1 rpy=0 0 1.5707963267948966".parse()?;
/// // Yaw by 90°: the mesh's x axis is the link's y axis.
/// assert!((t.apply(DVec3::X) - DVec3::new(0.0, 1.0, 1.0)).length() < 1e-15);
/// # Ok::<(), String>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Transform {
    /// Translation, m (after the mesh is scaled to metres).
    pub xyz: DVec3,
    /// Roll, pitch, yaw, rad.
    pub rpy: DVec3,
}

impl Transform {
    /// The rotation `link_from_mesh`.
    pub fn rotation(&self) -> DQuat {
        rpy_sequence().to_quat(self.rpy)
    }

    /// A point in mesh coordinates (metres) in link coordinates.
    pub fn apply(&self, point: DVec3) -> DVec3 {
        self.rotation() * point + self.xyz
    }
}

impl fmt::Display for Transform {
    /// `xyz=X Y Z rpy=R P Y`, numbers in shortest round-trip form.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (t, r) = (self.xyz, self.rpy);
        write!(
            f,
            "xyz={} {} {} rpy={} {} {}",
            Shortest(t.x),
            Shortest(t.y),
            Shortest(t.z),
            Shortest(r.x),
            Shortest(r.y),
            Shortest(r.z)
        )
    }
}

impl FromStr for Transform {
    type Err = String;

    /// `xyz=X Y Z rpy=R P Y`: either part may be left out (zero), in any
    /// order; the numbers are separated by spaces or commas, and may be
    /// quoted as in a URDF `<origin xyz="…" rpy="…"/>` pasted as it is.
    fn from_str(text: &str) -> Result<Self, Self::Err> {
        let text = text.replace(['"', '\''], " ");
        const FORM: &str = "expected \"xyz=X Y Z rpy=ROLL PITCH YAW\" (metres, radians)";
        let (mut xyz, mut rpy) = (None, None);
        // Split before each `key=`: "xyz=1 2 3 rpy=0 0 1" → ["xyz=1 2 3", "rpy=0 0 1"].
        let mut parts = Vec::new();
        for token in text.split_whitespace() {
            // `xyz= 1 2 3` (a space after `=`, e.g. from a quote) is `xyz=1 2 3`.
            match token.split_once('=') {
                Some(_) => parts.push(token.to_owned()),
                None => match parts.last_mut() {
                    Some(last) => {
                        last.push(' ');
                        last.push_str(token);
                    }
                    None => return Err(format!("`{token}` has no key; {FORM}")),
                },
            }
        }
        if parts.is_empty() {
            return Err(format!("empty; {FORM}"));
        }
        for part in parts {
            let (key, values) = part.split_once('=').unwrap_or((&part, ""));
            let slot = match key {
                "xyz" => &mut xyz,
                "rpy" => &mut rpy,
                other => return Err(format!("unknown key `{other}`; {FORM}")),
            };
            if slot.is_some() {
                return Err(format!("`{key}` given twice; {FORM}"));
            }
            *slot = Some(three(values).map_err(|e| format!("{key}: {e}; {FORM}"))?);
        }
        Ok(Self {
            xyz: xyz.unwrap_or(DVec3::ZERO),
            rpy: rpy.unwrap_or(DVec3::ZERO),
        })
    }
}

/// Three finite numbers separated by commas and/or whitespace.
pub fn three(text: &str) -> Result<DVec3, String> {
    let numbers = parse_numbers(text.trim()).map_err(|e| e.to_string())?;
    match numbers.as_slice() {
        &[x, y, z] if numbers.count() == 3 => Ok(DVec3::new(x, y, z)),
        _ => Err(format!("expected 3 numbers, found {}", numbers.count())),
    }
}

/// The frame the results are given in and the point `--about` names.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct OutputFrame {
    /// `--transform`: the mesh's placement in a link frame.
    pub transform: Option<Transform>,
    /// `--about`: a point in the mesh file's coordinates and units.
    pub about: Option<DVec3>,
}

impl OutputFrame {
    /// `mesh` or `link`: whose axes the results use.
    pub fn axes_name(&self) -> &'static str {
        if self.transform.is_some() {
            "link"
        } else {
            "mesh"
        }
    }

    /// The `--about` point in the output frame, m (the mesh coordinates
    /// scaled, then placed by the transform).
    pub fn about_point(&self, scale: f64) -> Option<DVec3> {
        let point = self.about? * scale;
        Some(self.transform.map_or(point, |t| t.apply(point)))
    }

    /// The report with every body and the assembly placed in the link frame
    /// (unchanged without `--transform`).
    pub fn place(&self, report: Report) -> Report {
        let Some(t) = self.transform else {
            return report;
        };
        let (rotation, translation) = (t.rotation(), t.xyz);
        let place = |s: Summary| {
            let properties = s.properties.placed(rotation, translation);
            Summary {
                principal: properties.principal(),
                properties,
                ..s
            }
        };
        Report {
            bodies: report.bodies.into_iter().map(place).collect(),
            assembly: place(report.assembly),
            ..report
        }
    }

    /// The tensor of `s` about the `--about` point, output axes, kg m².
    pub fn inertia_about(&self, s: &Summary, scale: f64) -> Option<(DVec3, DMat3)> {
        let point = self.about_point(scale)?;
        let i = s.properties.inertia_about_point(point);
        Some((point, (i + i.transpose()) * 0.5))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn transforms_parse_in_any_order_and_default_to_zero() {
        let t: Transform = "xyz=1 2 3 rpy=0.1,0.2,0.3".parse().unwrap();
        assert_eq!(t.xyz, DVec3::new(1.0, 2.0, 3.0));
        assert_eq!(t.rpy, DVec3::new(0.1, 0.2, 0.3));
        let t: Transform = " rpy=0 0 1.5  xyz=-1e-3,0,0 ".parse().unwrap();
        assert_eq!((t.xyz.x, t.rpy.z), (-1e-3, 1.5));
        let t: Transform = r#"xyz="0 0 0.1" rpy='0 0 1'"#.parse().unwrap();
        assert_eq!((t.xyz.z, t.rpy.z), (0.1, 1.0));
        let t: Transform = "rpy=0 0 1".parse().unwrap();
        assert_eq!(t.xyz, DVec3::ZERO);
        assert_eq!(t.to_string(), "xyz=0 0 0 rpy=0 0 1");
    }

    #[test]
    fn malformed_transforms_say_what_is_wrong() {
        for (text, words) in [
            ("", "empty"),
            ("1 2 3", "`1` has no key"),
            ("xyz=1 2", "xyz: expected 3 numbers, found 2"),
            ("xyz=1 2 3 4", "found 4"),
            ("rpy=0 0 nan", "not finite"),
            ("rpy=a b c", "cannot parse `a`"),
            ("xyz=1 2 3 xyz=1 2 3", "given twice"),
            ("pos=1 2 3", "unknown key `pos`"),
            ("xyz=", "xyz:"),
        ] {
            let e = text.parse::<Transform>().unwrap_err();
            assert!(e.contains(words), "{text:?}: {e}");
        }
    }

    #[test]
    fn rotation_is_yaw_pitch_roll() {
        // Independent of the Euler code: quaternions about the fixed axes.
        let t = Transform {
            xyz: DVec3::new(0.5, 0.0, 0.0),
            rpy: DVec3::new(0.3, -0.4, 1.1),
        };
        let expect = DQuat::from_rotation_z(1.1)
            * DQuat::from_rotation_y(-0.4)
            * DQuat::from_rotation_x(0.3);
        assert!(t.rotation().abs_diff_eq(expect, 1e-15));
        let p = t.apply(DVec3::X);
        assert!((p - (expect * DVec3::X + DVec3::new(0.5, 0.0, 0.0))).length() < 1e-15);
    }
}
