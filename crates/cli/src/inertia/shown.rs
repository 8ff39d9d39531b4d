//! The numbers the text and JSON reports show for one body: the computed
//! ones, plus the tensor about the `--about` point, rounded by `--digits`
//! as the `<inertial>` writers round theirs (tensors and principal moments
//! through [`InertialForm`], so they stay loadable).

use glam::{DMat3, DQuat, DVec3};
use kreisel_inertia::PrincipalAxes;

use super::Summary;
use super::frame_change::OutputFrame;
use super::inertial_form::InertialForm;
use super::rounding::{significant, snapped_all};

/// One body's numbers as shown.
#[derive(Debug, Clone, PartialEq)]
pub struct Shown {
    /// Mass, kg.
    pub mass: f64,
    /// Density, kg/m³.
    pub density: f64,
    /// Volume, m³.
    pub volume: f64,
    /// Area, m².
    pub area: f64,
    /// Centre of mass in the output frame, m.
    pub center_of_mass: DVec3,
    /// Tensor about the centre of mass, output axes, kg m².
    pub inertia: DMat3,
    /// The `--about` point (output frame, m) and the tensor about it.
    pub about: Option<(DVec3, DMat3)>,
    /// Principal moments, axes and orientation.
    pub principal: PrincipalAxes,
}

impl Shown {
    /// The numbers of `s` (already in the output frame) for a mesh scaled
    /// by `scale`, rounded to `digits` when given.
    pub fn new(s: &Summary, frame: &OutputFrame, scale: f64, digits: Option<u32>) -> Self {
        let props = &s.properties;
        let about = frame.inertia_about(s, scale);
        let Some(n) = digits else {
            return Self {
                mass: props.mass,
                density: s.density,
                volume: s.volume,
                area: s.area,
                center_of_mass: props.center_of_mass,
                inertia: props.inertia,
                about,
                principal: s.principal,
            };
        };
        let full = InertialForm {
            principal: false,
            digits: Some(n),
        };
        let principal = InertialForm {
            principal: true,
            digits: Some(n),
        };
        let written = full.inertial(props.mass, props.center_of_mass, props.inertia);
        let diagonal = principal.inertial(props.mass, props.center_of_mass, props.inertia);
        let unit = |v: DVec3| DVec3::from_array(snapped_all(v.to_array(), 1.0, n));
        let q = s.principal.orientation;
        let [w, x, y, z] = snapped_all([q.w, q.x, q.y, q.z], 1.0, n);
        let axes = s.principal.axes;
        Self {
            mass: written.mass,
            density: significant(s.density, n),
            volume: significant(s.volume, n),
            area: significant(s.area, n),
            center_of_mass: written.xyz,
            inertia: written.inertia,
            about: about.map(|(point, tensor)| {
                let at = full.inertial(props.mass, point, tensor);
                (at.xyz, at.inertia)
            }),
            principal: PrincipalAxes {
                moments: diag(diagonal.inertia),
                axes: DMat3::from_cols(unit(axes.x_axis), unit(axes.y_axis), unit(axes.z_axis)),
                orientation: DQuat::from_xyzw(x, y, z, w),
            },
        }
    }
}

/// The diagonal of a matrix.
fn diag(m: DMat3) -> DVec3 {
    DVec3::new(m.x_axis.x, m.y_axis.y, m.z_axis.z)
}
