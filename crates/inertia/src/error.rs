//! The one error type of `kreisel-inertia`.

use std::path::PathBuf;

use glam::DVec3;

use crate::mass_properties_error::MassPropertiesError;
use crate::mesh_format::MeshFormat;

/// Everything that can go wrong when loading a mesh or computing mass properties.
///
/// Each variant carries what a person needs to fix the input: the file, the
/// index of the offending vertex or triangle, the value and the limit.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum InertiaError {
    /// A file could not be read.
    #[error("cannot read {}: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// The operating system's reason.
        source: std::io::Error,
    },
    /// The file's extension names no mesh format kreisel reads.
    #[error("{}: unknown mesh format (expected .stl, .obj, .ply, .gltf or .glb)", path.display())]
    UnknownFormat {
        /// The file.
        path: PathBuf,
    },
    /// The file is not a valid mesh of its format.
    #[error("{}: invalid {format} file: {reason}", path.display())]
    Parse {
        /// The file.
        path: PathBuf,
        /// The format it was read as.
        format: MeshFormat,
        /// What is wrong, as precisely as the parser says.
        reason: String,
    },
    /// A body read from a file fails a mesh check (the inner error says which).
    #[error("{}: body '{body}': {source}", path.display())]
    InFile {
        /// The file.
        path: PathBuf,
        /// The body's name in the file.
        body: String,
        /// What is wrong with the body's mesh.
        source: Box<InertiaError>,
    },
    /// A mesh file that parses but holds no body with triangles.
    #[error("{}: the file holds no mesh bodies", path.display())]
    NoBodies {
        /// The file.
        path: PathBuf,
    },
    /// Scaling a body's coordinates to metres made one overflow.
    #[error("{}: body '{body}': coordinates overflow when scaled by {scale}", path.display())]
    ScaleOverflow {
        /// The file.
        path: PathBuf,
        /// The body's name in the file.
        body: String,
        /// The scale factor, metres per file unit.
        scale: f64,
    },
    /// A total mass spread over the bodies' total volume gives no finite
    /// positive density (the volume is too small or too large).
    #[error(
        "{}: total volume {volume} m^3 gives no finite positive density for a total mass of {mass} kg",
        path.display()
    )]
    DerivedDensity {
        /// The file.
        path: PathBuf,
        /// The total mass asked for, kg.
        mass: f64,
        /// The total volume of the bodies, m³.
        volume: f64,
    },
    /// A mesh without vertices or triangles.
    #[error("mesh is empty ({vertices} vertices, {triangles} triangles)")]
    EmptyMesh {
        /// Number of vertices.
        vertices: usize,
        /// Number of triangles.
        triangles: usize,
    },
    /// A vertex coordinate is NaN or infinite.
    #[error("vertex {vertex} has a non-finite coordinate")]
    NonFiniteVertex {
        /// 0-based vertex index.
        vertex: usize,
    },
    /// A triangle refers to a vertex that does not exist.
    #[error(
        "triangle {triangle} refers to vertex {index}, but the mesh has {vertex_count} vertices"
    )]
    IndexOutOfRange {
        /// 0-based triangle index.
        triangle: usize,
        /// The offending vertex index.
        index: u64,
        /// Number of vertices in the mesh.
        vertex_count: usize,
    },
    /// The surface is not closed, so it encloses no volume.
    #[error(
        "mesh is open: {boundary_edges} boundary edges (edges used by only one triangle), one at ({}, {}, {}){}",
        at.x, at.y, at.z,
        match weld_gap {
            Some(g) => format!("; every boundary vertex lies within {g:.2e} of another boundary vertex (cracks rather than holes)"),
            None => "; it encloses no volume".to_owned(),
        }
    )]
    OpenMesh {
        /// Number of edges used by exactly one triangle.
        boundary_edges: usize,
        /// The midpoint of one boundary edge.
        at: DVec3,
        /// When the boundary looks like cracks: the largest distance from a
        /// boundary vertex to its nearest other boundary vertex (reported
        /// when at most 0.001 × the bounding-box diagonal), the smallest
        /// weld tolerance that could close them.
        weld_gap: Option<f64>,
    },
    /// Some edges are shared by more than two triangles whose windings do
    /// not cancel (as many must run along the edge one way as the other),
    /// so the surface bounds no well-defined volume.
    #[error(
        "mesh is not closed: {edges} edges are shared by more than two triangles whose windings do not cancel (as many must run along an edge one way as the other), one at ({}, {}, {})",
        at.x, at.y, at.z
    )]
    NonManifold {
        /// Number of such edges.
        edges: usize,
        /// The midpoint of one such edge.
        at: DVec3,
    },
    /// A connected surface cannot be oriented consistently (a Möbius strip or
    /// Klein bottle).
    #[error(
        "mesh is not orientable: a connected surface of {triangles} triangles has no consistent winding"
    )]
    NonOrientable {
        /// Number of triangles in the offending surface (as far as explored).
        triangles: usize,
    },
    /// The convex hull of the points could not be built (fewer than four
    /// points, or all of them in one plane).
    #[error("convex hull is degenerate: {reason}")]
    DegenerateHull {
        /// Why, as the hull algorithm says.
        reason: String,
    },
    /// The mesh encloses no volume (all triangles degenerate or cancelling).
    #[error("mesh encloses zero volume")]
    ZeroVolume,
    /// A physical quantity that must be positive and finite is not.
    #[error("{quantity} must be positive and finite, got {value}")]
    NonPositive {
        /// What it is (`"density"`, `"mass"`, `"thickness"`, …).
        quantity: &'static str,
        /// The value given.
        value: f64,
    },
    /// A parameter that must be a finite number (and non-negative where
    /// that matters) is not.
    #[error("{quantity} must be finite, got {value}")]
    NotFinite {
        /// What it is (`"scale factor"`, `"weld tolerance"`, …).
        quantity: &'static str,
        /// The value given.
        value: f64,
    },
    /// A mass or an inertia tensor that no physical body has (which
    /// check fails, typed).
    #[error(transparent)]
    MassProperties(#[from] MassPropertiesError),
    /// A convex hull failed its checks (closed, outward, convex, containing
    /// every point): no result rather than a wrong one.
    #[error("convex hull of {points} points failed its check: {reason}")]
    HullCheckFailed {
        /// Number of distinct input points.
        points: usize,
        /// Which check failed, and where.
        reason: String,
    },
    /// A mesh's mass properties leave the range of f64: its volume, area,
    /// mass or moments overflow (a mesh far too large in metres) or fall
    /// below the normal numbers (far too small), so no result would be
    /// right. Usually the mesh's units are wrong.
    #[error(
        "mass properties of a mesh {} m across {} f64 ({quantity} ≈ {} {unit}, {}); check the mesh's units",
        sci(*extent_log10),
        if *value_log10 > 0.0 { "overflow" } else { "underflow" },
        sci(*value_log10),
        if *value_log10 > 0.0 { "the largest f64 is 1.8e308" } else { "the smallest normal f64 is 2.2e-308" }
    )]
    MeshOutOfRange {
        /// What leaves f64 (`"volume"`, `"area"`, `"mass"`, `"inertia tensor"`).
        quantity: &'static str,
        /// Its unit (`"m^3"`, `"kg"`, …).
        unit: &'static str,
        /// `log10` of the mesh's largest extent, m.
        extent_log10: f64,
        /// `log10` of the quantity's magnitude (beyond f64, so as a logarithm).
        value_log10: f64,
    },
    /// A result overflows (or underflows to zero) in f64: the inputs are out
    /// of the representable range.
    #[error("{quantity} is not representable in f64 (got {value:e}): inputs out of range")]
    NotRepresentable {
        /// What overflowed (`"mass"`, `"inertia"`, …).
        quantity: &'static str,
        /// The value computed.
        value: f64,
    },
}

/// `10^x` written as `8e600`: three significant digits, trailing zeros dropped.
fn sci(log10: f64) -> String {
    if !log10.is_finite() {
        return if log10 > 0.0 { "inf" } else { "0" }.to_owned();
    }
    let mut e = log10.floor();
    let mut m = 10f64.powf(log10 - e);
    if format!("{m:.2}") == "10.00" {
        m = 1.0;
        e += 1.0;
    }
    let digits = format!("{m:.2}");
    let digits = digits.trim_end_matches('0').trim_end_matches('.');
    format!("{digits}e{e}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn out_of_range_names_the_quantity_extent_and_limit() {
        let e = InertiaError::MeshOutOfRange {
            quantity: "volume",
            unit: "m^3",
            extent_log10: 2f64.log10() + 200.0,
            value_log10: 8f64.log10() + 600.0,
        };
        assert_eq!(
            e.to_string(),
            "mass properties of a mesh 2e200 m across overflow f64 (volume ≈ 8e600 m^3, the largest f64 is 1.8e308); check the mesh's units"
        );
        assert_eq!(sci(-599.0 - 0.0969), "8e-600");
        assert_eq!(sci(2.9999999), "1e3");
        assert_eq!(sci(0.5), "3.16e0");
    }
}
