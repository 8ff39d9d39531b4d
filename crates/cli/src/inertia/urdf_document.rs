//! A URDF robot description as text with byte ranges: its links, their
//! geometries and inertials, and the splice that replaces or adds
//! `<inertial>` elements while copying every other byte unchanged.
//!
//! Parsed with roxmltree (strict XML 1.0, byte ranges of every node) rather
//! than by hand: entities, comments, CDATA and attribute quoting are its
//! problem, and the ranges let the output keep comments, order and
//! whitespace exactly.

use std::ops::Range;
use std::path::Path;

use glam::{DMat3, DQuat, DVec3};
use roxmltree::{Document, Node};

use super::urdf_wellformed::{
    LineIndex, MAX_DEPTH, declaration_problem, line_of, start_tag_end, too_deep,
};
use crate::error::CliError;

/// A pose `<origin xyz rpy>`: translation, then URDF's fixed-axis roll,
/// pitch, yaw.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Pose {
    /// Translation, m.
    pub xyz: DVec3,
    /// Roll, pitch, yaw, rad.
    pub rpy: DVec3,
}

impl Pose {
    /// The rotation parent_from_child.
    ///
    /// ```text
    /// R = Rz(yaw) Ry(pitch) Rx(roll)
    /// ```
    pub fn rotation(&self) -> DQuat {
        DQuat::from_rotation_z(self.rpy.z)
            * DQuat::from_rotation_y(self.rpy.y)
            * DQuat::from_rotation_x(self.rpy.x)
    }
}

/// The shape of one `<geometry>`.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// `<box size="x y z"/>`, centred.
    Box {
        /// Edge lengths, m.
        size: DVec3,
    },
    /// `<cylinder radius length/>` along z, centred.
    Cylinder {
        /// Radius, m.
        radius: f64,
        /// Length, m.
        length: f64,
    },
    /// `<sphere radius/>`, centred.
    Sphere {
        /// Radius, m.
        radius: f64,
    },
    /// `<capsule radius length/>` (pybullet, Drake, Gazebo): a cylinder of
    /// `length` along z capped by two hemispheres, centred.
    Capsule {
        /// Radius, m.
        radius: f64,
        /// Length of the cylindrical part, m.
        length: f64,
    },
    /// A geometry element kreisel cannot integrate (`<plane>`, pybullet's
    /// `<cdf>`, …): the link keeps its inertial, the others are filled.
    Other {
        /// The element's name.
        element: String,
    },
    /// `<mesh filename scale/>`.
    Mesh {
        /// The filename as written (`package://…`, relative, …).
        filename: String,
        /// Per-axis scale (metres per mesh unit).
        scale: DVec3,
    },
}

/// One `<collision>` or `<visual>` element.
#[derive(Debug, Clone, PartialEq)]
pub struct Geometry {
    /// Its placement in the link frame.
    pub origin: Pose,
    /// What it is.
    pub shape: Shape,
    /// 1-based line of the shape element (`<mesh>`, `<box>`, …), for messages.
    pub line: u32,
    /// The bytes of a `<mesh>`'s `filename="…"` attribute.
    pub filename_attribute: Option<Range<usize>>,
}

/// A link's `<inertial>` as written in the file.
#[derive(Debug, Clone, PartialEq)]
pub struct Inertial {
    /// The element's bytes.
    pub range: Range<usize>,
    /// The inertial frame in the link frame.
    pub origin: Pose,
    /// `<mass value>`, kg (`None` when absent).
    pub mass: Option<f64>,
    /// The tensor in the inertial frame (`None` when `<inertia>` is absent).
    pub tensor: Option<DMat3>,
}

impl Inertial {
    /// The tensor about the centre of mass in the link frame.
    ///
    /// ```text
    /// I_link = R I Rᵀ
    /// ```
    pub fn tensor_in_link(&self) -> Option<DMat3> {
        let r = DMat3::from_quat(self.origin.rotation());
        self.tensor.map(|i| r * i * r.transpose())
    }
}

/// One `<link>`.
#[derive(Debug, Clone, PartialEq)]
pub struct Link {
    /// Its name.
    pub name: String,
    /// 1-based line of the element.
    pub line: u32,
    /// Where a new `<inertial>` goes: just after the start tag.
    pub insert_at: usize,
    /// The indentation of the link's children.
    pub child_indent: String,
    /// One level of indentation.
    pub step: String,
    /// Its `<collision>` elements.
    pub collision: Vec<Geometry>,
    /// Its `<visual>` elements.
    pub visual: Vec<Geometry>,
    /// Its `<inertial>`, if any.
    pub inertial: Option<Inertial>,
}

/// A parsed robot description.
#[derive(Debug, Clone, PartialEq)]
pub struct UrdfDocument {
    /// The file's text.
    pub text: String,
    /// Every `<link>`, in file order.
    pub links: Vec<Link>,
    /// `\r\n` when the file uses it, else `\n`.
    pub newline: &'static str,
}

/// An error at a node of `path`.
fn at(path: &Path, doc: &Document, node: Node, message: String) -> CliError {
    CliError::Urdf {
        path: path.to_path_buf(),
        line: Some(doc.text_pos_at(node.range().start).row),
        message,
    }
}

/// The numbers of an attribute, which must be `n` finite ones.
fn numbers(text: &str, n: usize) -> Option<Vec<f64>> {
    let v: Vec<f64> = text
        .split_whitespace()
        .map(str::parse)
        .collect::<Result<_, _>>()
        .ok()?;
    (v.len() == n && v.iter().all(|x| x.is_finite())).then_some(v)
}

/// Reads attributes of one element, naming the element in errors.
struct Reader<'a, 'input> {
    path: &'a Path,
    doc: &'a Document<'input>,
    lines: &'a LineIndex,
    link: &'a str,
}

impl<'input> Reader<'_, 'input> {
    fn error(&self, node: Node, message: String) -> CliError {
        at(
            self.path,
            self.doc,
            node,
            format!("link '{}': {message}", self.link),
        )
    }

    /// Attribute `name` of `node` as `n` numbers; `default` when absent.
    fn vector(
        &self,
        node: Node<'_, 'input>,
        name: &str,
        n: usize,
        default: Option<Vec<f64>>,
    ) -> Result<Vec<f64>, CliError> {
        match node.attribute(name) {
            None => default.ok_or_else(|| {
                self.error(
                    node,
                    format!("<{}> has no {name} attribute", node.tag_name().name()),
                )
            }),
            Some(text) => numbers(text, n).ok_or_else(|| {
                self.error(
                    node,
                    format!(
                        "<{}> {name}=\"{text}\" is not {n} finite number(s)",
                        node.tag_name().name()
                    ),
                )
            }),
        }
    }

    fn vec3(&self, node: Node<'_, 'input>, name: &str) -> Result<DVec3, CliError> {
        let v = self.vector(node, name, 3, Some(vec![0.0; 3]))?;
        Ok(DVec3::new(v[0], v[1], v[2]))
    }

    fn scalar(&self, node: Node<'_, 'input>, name: &str) -> Result<f64, CliError> {
        Ok(self.vector(node, name, 1, None)?[0])
    }

    /// The `<origin>` child of `node` (identity when absent).
    fn origin(&self, node: Node<'_, 'input>) -> Result<Pose, CliError> {
        match child(node, "origin") {
            None => Ok(Pose::default()),
            Some(o) => Ok(Pose {
                xyz: self.vec3(o, "xyz")?,
                rpy: self.vec3(o, "rpy")?,
            }),
        }
    }

    /// A `<collision>` or `<visual>` element.
    fn geometry(&self, node: Node<'_, 'input>) -> Result<Geometry, CliError> {
        let kind = node.tag_name().name();
        let geometry = child(node, "geometry")
            .ok_or_else(|| self.error(node, format!("<{kind}> has no <geometry>")))?;
        let shape_node = geometry
            .children()
            .find(Node::is_element)
            .ok_or_else(|| self.error(geometry, "<geometry> is empty".into()))?;
        let shape = match shape_node.tag_name().name() {
            "box" => {
                let s = self.vector(shape_node, "size", 3, None)?;
                Shape::Box {
                    size: DVec3::new(s[0], s[1], s[2]),
                }
            }
            "cylinder" => Shape::Cylinder {
                radius: self.scalar(shape_node, "radius")?,
                length: self.scalar(shape_node, "length")?,
            },
            "sphere" => Shape::Sphere {
                radius: self.scalar(shape_node, "radius")?,
            },
            "mesh" => {
                let filename = shape_node.attribute("filename").ok_or_else(|| {
                    self.error(shape_node, "<mesh> has no filename attribute".into())
                })?;
                let words = shape_node
                    .attribute("scale")
                    .map(|s| s.split_whitespace().count());
                let scale = match words {
                    Some(1) => DVec3::splat(self.scalar(shape_node, "scale")?),
                    _ => {
                        let v = self.vector(shape_node, "scale", 3, Some(vec![1.0; 3]))?;
                        DVec3::new(v[0], v[1], v[2])
                    }
                };
                Shape::Mesh {
                    filename: filename.to_owned(),
                    scale,
                }
            }
            "capsule" => Shape::Capsule {
                radius: self.scalar(shape_node, "radius")?,
                length: self.scalar(shape_node, "length")?,
            },
            other => Shape::Other {
                element: other.to_owned(),
            },
        };
        Ok(Geometry {
            origin: self.origin(node)?,
            shape,
            line: self.lines.line(shape_node.range().start),
            filename_attribute: shape_node
                .attributes()
                .find(|a| a.name() == "filename" && a.namespace().is_none())
                .map(|a| a.range()),
        })
    }

    /// An `<inertial>` element.
    fn inertial(&self, node: Node<'_, 'input>) -> Result<Inertial, CliError> {
        let mass = match child(node, "mass") {
            None => None,
            Some(m) => Some(self.scalar(m, "value")?),
        };
        let tensor = match child(node, "inertia") {
            None => None,
            Some(i) => {
                let mut e = [0.0; 6];
                for (k, name) in ["ixx", "ixy", "ixz", "iyy", "iyz", "izz"]
                    .iter()
                    .enumerate()
                {
                    e[k] = self.scalar(i, name)?;
                }
                let [xx, xy, xz, yy, yz, zz] = e;
                Some(DMat3::from_cols_array(&[
                    xx, xy, xz, xy, yy, yz, xz, yz, zz,
                ]))
            }
        };
        Ok(Inertial {
            range: node.range(),
            origin: self.origin(node)?,
            mass,
            tensor,
        })
    }
}

/// The first child element of `node` named `name`.
fn child<'a, 'input>(node: Node<'a, 'input>, name: &str) -> Option<Node<'a, 'input>> {
    node.children()
        .find(|c| c.is_element() && c.tag_name().name() == name)
}

/// The whitespace before `pos` on its line (`None` when other text precedes it).
fn indent_before(text: &str, pos: usize) -> Option<&str> {
    // Only the blanks just before `pos` are looked at (never the whole line).
    let blanks = text.as_bytes()[..pos]
        .iter()
        .rev()
        .take_while(|&&b| b == b' ' || b == b'\t')
        .count();
    let start = pos - blanks;
    (start == 0 || text.as_bytes()[start - 1] == b'\n').then(|| &text[start..pos])
}

impl UrdfDocument {
    /// Parses a robot description read from `path` (named in errors).
    ///
    /// # Errors
    /// [`CliError::Urdf`] for text that is not XML (or nests elements deeper
    /// than [`MAX_DEPTH`], or declares an XML version other than 1.x), a
    /// root that is not `<robot>`, an unnamed link, two links of one name,
    /// a link with two `<inertial>` elements,
    /// and a malformed `<origin>`, `<geometry>`, `<mass>` or `<inertia>`
    /// with the line and the link (an unknown geometry element is
    /// [`Shape::Other`], the link's own problem).
    pub fn parse(path: &Path, text: String) -> Result<Self, CliError> {
        if let Some(pos) = too_deep(&text, MAX_DEPTH) {
            return Err(CliError::Urdf {
                path: path.to_path_buf(),
                line: Some(line_of(&text, pos)),
                message: format!(
                    "elements nested more than {MAX_DEPTH} deep; a URDF nests about 5 (robot, link, collision, geometry, mesh)"
                ),
            });
        }
        if let Some(message) = declaration_problem(&text) {
            return Err(CliError::Urdf {
                path: path.to_path_buf(),
                line: Some(1),
                message,
            });
        }
        let links = {
            let doc = Document::parse(&text).map_err(|e| CliError::Urdf {
                path: path.to_path_buf(),
                line: Some(e.pos().row),
                message: format!("not a valid XML file: {e}"),
            })?;
            let root = doc.root_element();
            if root.tag_name().name() != "robot" {
                return Err(at(
                    path,
                    &doc,
                    root,
                    format!(
                        "the root element is <{}>, not <robot>",
                        root.tag_name().name()
                    ),
                ));
            }
            let index = LineIndex::new(&text);
            let mut links: Vec<Link> = Vec::new();
            let mut lines = std::collections::HashMap::new();
            for node in root
                .children()
                .filter(|c| c.is_element() && c.tag_name().name() == "link")
            {
                let link = parse_link(path, &doc, &index, &text, node)?;
                if let Some(first) = lines.insert(link.name.clone(), link.line) {
                    return Err(at(
                        path,
                        &doc,
                        node,
                        format!(
                            "a second link named '{}' (the first is at line {}); link names must be unique",
                            link.name, first
                        ),
                    ));
                }
                links.push(link);
            }
            links
        };
        let newline = if text.contains("\r\n") { "\r\n" } else { "\n" };
        Ok(Self {
            text,
            links,
            newline,
        })
    }

    /// The text with the `<inertial>` of some links replaced (or added just
    /// after the link's start tag); every other byte unchanged.
    ///
    /// `elements` pairs a link index with the element's text, which starts
    /// at `<inertial>` and ends at `</inertial>` (its inner lines already
    /// indented as the link's children).
    #[cfg(test)]
    pub fn splice(&self, elements: &[(usize, String)]) -> String {
        self.splice_with(elements, Vec::new())
    }

    /// [`UrdfDocument::splice`], and the byte ranges of `more` (which
    /// overlap no `<inertial>`) replaced by their text.
    pub fn splice_with(
        &self,
        elements: &[(usize, String)],
        more: Vec<(Range<usize>, String)>,
    ) -> String {
        let mut edits: Vec<(Range<usize>, String)> = elements
            .iter()
            .map(|(k, element)| {
                let link = &self.links[*k];
                match &link.inertial {
                    Some(old) => (old.range.clone(), element.clone()),
                    None => (
                        link.insert_at..link.insert_at,
                        format!("{}{}{element}", self.newline, link.child_indent),
                    ),
                }
            })
            .chain(more)
            .collect();
        edits.sort_by_key(|(r, _)| r.start);
        let mut out = String::with_capacity(self.text.len() + 400 * edits.len());
        let mut done = 0;
        for (range, replacement) in edits {
            out.push_str(&self.text[done..range.start]);
            out.push_str(&replacement);
            done = range.end;
        }
        out.push_str(&self.text[done..]);
        out
    }
}

/// One `<link>` element.
fn parse_link(
    path: &Path,
    doc: &Document,
    lines: &LineIndex,
    text: &str,
    node: Node,
) -> Result<Link, CliError> {
    let name = node
        .attribute("name")
        .ok_or_else(|| at(path, doc, node, "a <link> has no name attribute".into()))?;
    let reader = Reader {
        path,
        doc,
        lines,
        link: name,
    };
    let mut link = Link {
        name: name.to_owned(),
        line: lines.line(node.range().start),
        insert_at: start_tag_end(text, node.range().start),
        child_indent: String::new(),
        step: String::new(),
        collision: Vec::new(),
        visual: Vec::new(),
        inertial: None,
    };
    let link_indent = indent_before(text, node.range().start).unwrap_or("");
    // The first child's indentation, or one level deeper than the link's
    // when the child shares a line with other text.
    let first_child = node.children().find(Node::is_element);
    link.child_indent = match first_child.and_then(|c| indent_before(text, c.range().start)) {
        Some(indent) => indent.to_owned(),
        None => format!("{link_indent}  "),
    };
    link.step = match link.child_indent.strip_prefix(link_indent) {
        Some(step) if !step.is_empty() => step.to_owned(),
        _ => "  ".to_owned(),
    };
    for c in node.children().filter(Node::is_element) {
        match c.tag_name().name() {
            "collision" => link.collision.push(reader.geometry(c)?),
            "visual" => link.visual.push(reader.geometry(c)?),
            "inertial" if link.inertial.is_some() => {
                return Err(reader.error(c, "a second <inertial> element".into()));
            }
            "inertial" => link.inertial = Some(reader.inertial(c)?),
            _ => {}
        }
    }
    Ok(link)
}

#[cfg(test)]
mod tests {
    use super::*;

    const ROBOT: &str = "<?xml version=\"1.0\"?>\n<!-- a > comment -->\n<robot name=\"r\">\n  <link name=\"a\" x='>'>\n    <!-- keep -->\n    <inertial>\n      <origin xyz=\"0 0 1\" rpy=\"0 0 1.5707963267948966\"/>\n      <mass value=\"2\"/>\n      <inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"2\" iyz=\"0\" izz=\"3\"/>\n    </inertial>\n    <collision><origin xyz=\"1 2 3\"/><geometry><box size=\"1 2 3\"/></geometry></collision>\n  </link>\n  <link name=\"b\">\n\t<visual>\n\t\t<geometry><mesh filename=\"package://p/m.stl\" scale=\"0.001 0.001 0.001\"/></geometry>\n\t</visual>\n  </link>\n</robot>\n";

    fn parse(text: &str) -> Result<UrdfDocument, CliError> {
        UrdfDocument::parse(Path::new("r.urdf"), text.to_owned())
    }

    #[test]
    fn links_geometry_and_inertials() {
        let doc = parse(ROBOT).unwrap();
        assert_eq!(doc.links.len(), 2);
        let a = &doc.links[0];
        assert_eq!((a.name.as_str(), a.line), ("a", 4));
        assert!(ROBOT[..a.insert_at].ends_with("<link name=\"a\" x='>'>"));
        let inertial = a.inertial.as_ref().unwrap();
        assert_eq!(inertial.mass, Some(2.0));
        // Rotated by 90 degrees about z: x and y moments swap.
        let t = inertial.tensor_in_link().unwrap();
        assert!((t.x_axis.x - 2.0).abs() < 1e-15 && (t.y_axis.y - 1.0).abs() < 1e-15);
        assert_eq!(a.collision[0].origin.xyz, DVec3::new(1.0, 2.0, 3.0));
        let b = &doc.links[1];
        // Mixed indentation: one level is two spaces.
        assert_eq!((b.child_indent.as_str(), b.step.as_str()), ("\t", "  "));
        assert_eq!(
            b.visual[0].shape,
            Shape::Mesh {
                filename: "package://p/m.stl".into(),
                scale: DVec3::splat(0.001)
            }
        );
    }

    #[test]
    fn splice_replaces_and_inserts_only_inertials() {
        let doc = parse(ROBOT).unwrap();
        let out = doc.splice(&[
            (0, "<inertial>A</inertial>".into()),
            (1, "<inertial/>".into()),
        ]);
        let expected = ROBOT
            .replace(
                &ROBOT[doc.links[0].inertial.as_ref().unwrap().range.clone()],
                "<inertial>A</inertial>",
            )
            .replace("<link name=\"b\">\n", "<link name=\"b\">\n\t<inertial/>\n");
        assert_eq!(out, expected);
        assert_eq!(doc.splice(&[]), ROBOT);
    }

    #[test]
    fn errors_name_line_and_link() {
        let odd = ROBOT.replace("<box size=\"1 2 3\"/>", "<plane normal=\"0 0 1\"/>");
        let doc = parse(&odd).expect("an unknown element is the link's problem");
        let shape = &doc.links[0].collision[0].shape;
        assert!(
            matches!(shape, Shape::Other { element } if element == "plane"),
            "{shape:?}"
        );
        let bad = ROBOT.replace("size=\"1 2 3\"", "size=\"1 2\"");
        let e = parse(&bad).unwrap_err().to_string();
        assert!(e.contains("size=\"1 2\" is not 3 finite number(s)"), "{e}");
        let e = parse("<robot><link name='a'>").unwrap_err().to_string();
        assert!(e.starts_with("r.urdf:1: not a valid XML file"), "{e}");
        let e = parse("<sdf/>").unwrap_err().to_string();
        assert_eq!(e, "r.urdf:1: the root element is <sdf>, not <robot>");
    }
}

#[cfg(test)]
#[path = "urdf_document_props.rs"]
mod props;
