//! The `<inertial>` element written into a link by `inertia --urdf`: origin
//! at the centre of mass, the mass, and the tensor about the centre of mass
//! (elements `I_xy = −Σ m x y`), in the form `--principal` / `--digits`
//! choose ([`InertialForm`]: by default `rpy="0 0 0"` and the full tensor in
//! the link axes), every number in shortest round-trip form.
//!
//! Every filled link goes through [`inertial_element`].

use glam::DMat3;
use kreisel_inertia::MassProperties;

use super::InertialForm;
use kreisel_scene::numbers::Shortest;

/// How the element is laid out in the file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Layout<'a> {
    /// Indentation of the `<inertial>` line (the link's children).
    pub indent: &'a str,
    /// One more level, for the element's own children.
    pub step: &'a str,
    /// The file's line break.
    pub newline: &'a str,
}

/// The six tensor elements `ixx ixy ixz iyy iyz izz`.
fn six(i: DMat3) -> [Shortest; 6] {
    let e = |r: usize, c: usize| Shortest(i.col(c)[r]);
    [e(0, 0), e(0, 1), e(0, 2), e(1, 1), e(1, 2), e(2, 2)]
}

/// The `<inertial>` element of `props` (link frame) in `form`, from
/// `<inertial>` to `</inertial>`; its inner lines and closing tag indented
/// per `layout`.
///
/// ```text
/// <inertial>
///   <origin xyz="cx cy cz" rpy="r p y"/>      rpy = 0 unless principal
///   <mass value="m"/>
///   <inertia ixx=".." ixy=".." ixz=".." iyy=".." iyz=".." izz=".."/>
/// </inertial>
/// ```
pub fn inertial_element(props: &MassProperties, form: InertialForm, layout: Layout) -> String {
    let Layout {
        indent,
        step,
        newline: nl,
    } = layout;
    let written = form.inertial(props.mass, props.center_of_mass, props.inertia);
    let (c, r) = (written.xyz, written.rpy);
    let [ixx, ixy, ixz, iyy, iyz, izz] = six(written.inertia);
    format!(
        "<inertial>{nl}\
         {indent}{step}<origin xyz=\"{} {} {}\" rpy=\"{} {} {}\"/>{nl}\
         {indent}{step}<mass value=\"{}\"/>{nl}\
         {indent}{step}<inertia ixx=\"{ixx}\" ixy=\"{ixy}\" ixz=\"{ixz}\" iyy=\"{iyy}\" iyz=\"{iyz}\" izz=\"{izz}\"/>{nl}\
         {indent}</inertial>",
        Shortest(c.x),
        Shortest(c.y),
        Shortest(c.z),
        Shortest(r.x),
        Shortest(r.y),
        Shortest(r.z),
        Shortest(written.mass),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn element_is_indented_and_exact() {
        // A + B > C: written unchanged (a flat body's tensor, A + B = C, would be
        // raised to stay loadable, as for a single mesh).
        let inertia = DMat3::from_cols_array(&[1.0, -0.1, 0.0, -0.1, 2.0, 0.0, 0.0, 0.0, 2.5]);
        let props = MassProperties::new(0.5, DVec3::new(0.1, -0.2, 1.0 / 3.0), inertia);
        let layout = Layout {
            indent: "    ",
            step: "  ",
            newline: "\n",
        };
        assert_eq!(
            inertial_element(&props, InertialForm::default(), layout),
            "<inertial>\n      <origin xyz=\"0.1 -0.2 0.3333333333333333\" rpy=\"0 0 0\"/>\n      \
             <mass value=\"0.5\"/>\n      <inertia ixx=\"1\" ixy=\"-0.1\" ixz=\"0\" iyy=\"2\" iyz=\"0\" izz=\"2.5\"/>\n    </inertial>"
        );
    }
}
